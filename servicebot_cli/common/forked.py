"""One function applied to jobs in order, in a forked process when a second core is free.

A caller hands work that depends on nothing it does meanwhile to a :class:`Worker` and goes
on: ``simulate`` the pose work of each piece (:mod:`~servicebot_cli.simulate.pose_work`),
``check`` the Pinocchio model of a one-file run (:mod:`~servicebot_cli.check.model_ahead`).
The forked process inherits everything the function closes over (a robot, a world, a noise
generator) and only the jobs and the results cross the pipes, in order, so the results are
the bits the function gives in-process: the state it carries from job to job (a noise
generator) lives in the one process that calls it.

Without :func:`os.fork` or with one core to run on (:func:`os.sched_getaffinity`), the jobs
are done in-process when their results are asked for. The process ignores SIGINT and takes
SIGTERM, SIGHUP and SIGQUIT at their default (Ctrl-C reaches the whole process group: the
parent ends the run and stops the worker); it never returns into the caller's code. Closing
the worker after the last result lets it end; closing it on an error or a signal kills it.
Either way it is reaped before :meth:`Worker.close` returns.
"""

from __future__ import annotations

import os
import pickle
import signal
import sys
import threading
from collections.abc import Callable
from queue import SimpleQueue
from typing import IO, Any, Generic, TypeVar

from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.common.signals import ENDING_SIGNALS, SignalsHeld

J = TypeVar("J")
R = TypeVar("R")
_END = None  # the job queue's end, after the parent closed the jobs' pipe


class WorkerEnded(ServicebotError):
    """The worker process ended before it gave a result (killed from outside)."""

    exit_code = ExitCode.FAILED


def second_core() -> bool:
    """A process can be forked and given a core of its own (this process may use two).

    Not in a worker of a :mod:`multiprocessing` pool (``sweep``'s runs): its siblings
    share the cores already; nor while other Python threads run (a fork copies their locks).
    """
    if not hasattr(os, "fork") or threading.active_count() > 1:
        return False  # another thread could hold a lock the forked process would wait on
    pools = sys.modules.get("multiprocessing")  # imported in every such worker
    if pools is not None and pools.parent_process() is not None:
        return False
    affinity = getattr(os, "sched_getaffinity", None)
    cores = len(affinity(0)) if affinity is not None else os.cpu_count() or 1
    return cores >= 2


class Worker(Generic[J, R]):
    """``function`` applied to each submitted job, the results taken in the order submitted.

    Args:
        function: Called once per job, in order. In a forked process, what it keeps between
            calls stays there: the caller's copy must not be used while the worker lives.
        forked: Do the jobs in a forked process (else in-process, when taken).
        name: What the process is, for the error when it ends early ("the NAME process").
        prepare: Work the first job would do that needs no job (imports, caches), done by a
            forked process as soon as it starts, while it waits for that job. Its errors
            are left for the job to meet.
    """

    def __init__(self, function: Callable[[J], R], *, forked: bool,
                 name: str = "worker", prepare: Callable[[], object] | None = None) -> None:
        self._function, self.name, self._prepare = function, name, prepare
        self._waiting: list[J] = []  # in-process: the jobs whose results are not taken
        self._submitted = self._taken = 0  # jobs handed over, results read
        self._unwanted: set[int] = set()  # the jobs (by number) whose results are dropped
        self.pid: int | None = None
        self._jobs: IO[bytes] | None = None
        self._results: IO[bytes] | None = None
        if forked:
            self._fork()

    def _fork(self) -> None:
        jobs_read, jobs_write = os.pipe()
        results_read, results_write = os.pipe()
        for fd in (jobs_write, results_write):
            _widen(fd)
        held = SignalsHeld()  # no signal between the fork and the parent knowing the pid
        try:
            try:
                pid = os.fork()
            except BaseException:
                for fd in (jobs_read, jobs_write, results_read, results_write):
                    os.close(fd)
                raise
            if pid == 0:  # the worker: it never returns from here
                code = 1
                try:
                    os.close(jobs_write)
                    os.close(results_read)
                    _serve(self._function, jobs_read, results_write, self._prepare)
                    code = 0
                finally:
                    os._exit(code)
            self.pid = pid
            os.close(jobs_read)
            os.close(results_write)
            self._jobs = os.fdopen(jobs_write, "wb")
            self._results = os.fdopen(results_read, "rb")
        finally:
            try:
                held.release()  # raises a signal that came meanwhile
            except BaseException:
                self.close()
                raise

    def submit(self, job: J) -> None:
        """Hand over the next job; its result comes after those submitted before it.

        Raises:
            WorkerEnded: The worker process has ended.
        """
        if self._jobs is None:
            self._submitted += 1
            self._waiting.append(job)
            return
        self.submit_pickled(pickle.dumps(job, protocol=pickle.HIGHEST_PROTOCOL))

    def submit_pickled(self, data: bytes) -> None:
        """:meth:`submit` a job already pickled (to a forked worker only).

        Raises:
            WorkerEnded: The worker process has ended.
        """
        assert self._jobs is not None, "only a forked worker's jobs are sent pickled"
        self._submitted += 1
        try:
            self._jobs.write(data)
            self._jobs.flush()
        except BrokenPipeError:  # it stopped: at an error of a job (which it sent), or killed
            raise self._error_sent() from None

    def no_more_jobs(self) -> None:
        """Every job is submitted: a forked worker ends once it has done them."""
        if self._jobs is not None:
            self._jobs.close()
            self._jobs = None

    def result(self) -> R:
        """The result of the oldest job whose result is not taken yet (waits for it).

        Raises:
            WorkerEnded: The worker process ended without it.
            Exception: What the function raised for the job.
        """
        while self._taken in self._unwanted:
            self._unwanted.discard(self._taken)
            self._next()
        return self._next()

    def drop_result(self) -> None:
        """Leave out the result of the job submitted last.

        It is read and dropped when a later one is asked for; its error is raised then.
        """
        self._unwanted.add(self._submitted - 1)

    def _next(self) -> R:
        self._taken += 1
        if self._results is None:
            return self._function(self._waiting.pop(0))
        try:
            done, value = pickle.load(self._results)
        except (EOFError, pickle.UnpicklingError):  # none, or cut short by its end
            raise self._ended() from None
        if not done:
            raise value
        return value  # type: ignore[no-any-return]

    def _error_sent(self) -> Exception:
        """The error of a job the worker sent before it ended, else :class:`WorkerEnded`."""
        if self._results is not None:
            try:
                while True:
                    done, value = pickle.load(self._results)
                    if not done:
                        return value  # type: ignore[no-any-return]
            except Exception:  # noqa: BLE001 -- the end of what it sent, whatever the form
                pass
        return self._ended()

    def _ended(self) -> WorkerEnded:
        return WorkerEnded(f"the {self.name} process {self.pid} ended before its results came "
                           "(killed from outside?)")

    def close(self, *, finished: bool = False) -> None:
        """Stop the worker process and reap it; ``finished``: every result was taken.

        A finished worker ends by itself once its jobs' pipe is closed; any other is killed.
        """
        pid, self.pid = self.pid, None
        held = SignalsHeld()  # the worker is reaped whatever signal comes meanwhile
        try:
            if pid is not None and not finished:  # before its pipes close under it
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            for stream in (self._jobs, self._results):
                if stream is not None:
                    try:
                        stream.close()
                    except OSError:  # a broken pipe, with unflushed bytes
                        pass
            self._jobs = self._results = None
            if pid is not None:
                try:
                    os.waitpid(pid, 0)
                except ChildProcessError:  # SIGCHLD ignored: the system reaped it
                    pass
        finally:
            held.release()


PIPE_BYTES = 1 << 20
"""A pipe's buffer when Linux allows it (64 KiB by default): a job or a result of a few hundred
KiB then goes in at once, instead of the writer waiting on the other process's reading thread,
which waits for that process's main thread to let go of the GIL."""


def _widen(fd: int) -> None:
    """Give the pipe ``fd`` a :data:`PIPE_BYTES` buffer, or the most the system allows."""
    import fcntl

    setting = getattr(fcntl, "F_SETPIPE_SZ", None)
    if setting is None:  # pragma: no cover - not on Linux
        return
    try:
        fcntl.fcntl(fd, setting, PIPE_BYTES)
    except OSError:  # above /proc/sys/fs/pipe-max-size for an unprivileged process
        return


def _serve(function: Callable[[Any], Any], jobs_fd: int, results_fd: int,
           prepare: Callable[[], object] | None = None) -> None:
    """The worker process: each job read, the function's result (or error) written back.

    ``prepare`` is done first, while the first job is on its way. A thread reads the jobs
    and another writes the results, so that neither pipe waits on the other process while
    this one works: the parent never waits to hand over a job, and the next job is begun
    while the parent has not taken the last result yet.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for ending in ENDING_SIGNALS:  # not the parent's handlers: it stops the worker
        signal.signal(ending, signal.SIG_DFL)
    jobs: SimpleQueue[Any] = SimpleQueue()
    results: SimpleQueue[bytes | None] = SimpleQueue()
    threading.Thread(target=_read_jobs, args=(jobs_fd, jobs), daemon=True).start()
    writer = threading.Thread(target=_write_results, args=(results_fd, results), daemon=True)
    writer.start()
    try:
        prepare_quietly(prepare)
        while (job := jobs.get()) is not _END:
            try:
                if isinstance(job[0], _Unreadable):
                    raise job[0].error
                answer: tuple[bool, Any] = (True, function(job[0]))
            except Exception as exc:  # the parent raises it, with where it was raised here
                exc.add_note(_where_raised())
                answer = (False, exc)
            try:
                data = pickle.dumps(answer, protocol=pickle.HIGHEST_PROTOCOL)
                if not answer[0]:
                    pickle.loads(data)  # an error must come back whole in the parent
            except Exception as exc:  # noqa: BLE001 -- one that cannot: its message and code
                data = pickle.dumps((False, _portable(answer[1], exc)))
            results.put(data)
            if not answer[0]:
                break
    finally:
        results.put(None)
        writer.join()


def prepare_quietly(prepare: Callable[[], object] | None) -> None:
    """Do a worker's ``prepare``, if it has one; its error is left for the first job to meet.

    That job does the same work, and its error comes back as the job's result.
    """
    if prepare is None:
        return
    try:
        prepare()
    except Exception:  # noqa: BLE001,S110 -- the job meets it again, and says so
        pass


def _where_raised() -> str:
    """The traceback of the error being handled, as a note ``--debug`` shows in the parent.

    The parent's own traceback ends where it raises the error it was sent.
    """
    import traceback  # only on an error

    return "raised in the forked process:\n" + traceback.format_exc().rstrip()


def _portable(error: Exception, why: Exception) -> Exception:
    """``error`` as one that pickles both ways: a user's error keeps its message and code."""
    portable: Exception = RuntimeError(f"{error!r} ({why})")
    if isinstance(error, ServicebotError):
        user = ServicebotError(str(error))
        user.exit_code = error.exit_code
        portable = user
    for note in getattr(error, "__notes__", ()):
        portable.add_note(note)
    return portable


class _Unreadable:
    """A job this process cannot rebuild (a class it cannot import): its error is the result."""

    def __init__(self, error: Exception) -> None:
        self.error = RuntimeError(f"the forked process could not read its job: "
                                  f"{type(error).__name__}: {error}")


def _read_jobs(jobs_fd: int, jobs: SimpleQueue[Any]) -> None:
    """Queue each job, then the end: at the pipe's end, or after a job that cannot be read.

    A job cut short (the parent died) or rebuilt with an error ends the jobs with that error
    as the next result, which a parent still there raises.
    """
    try:
        with os.fdopen(jobs_fd, "rb") as stream:
            while True:
                try:
                    job = pickle.load(stream)
                except EOFError:  # the parent closed the pipe: no more jobs
                    break
                except Exception as exc:  # noqa: BLE001 -- whatever rebuilding it raised
                    jobs.put((_Unreadable(exc),))
                    break
                jobs.put((job,))
    finally:
        jobs.put(_END)


def _write_results(results_fd: int, results: SimpleQueue[bytes | None]) -> None:
    """Write each result; the parent gone (a broken pipe), drop the rest quietly."""
    try:
        with os.fdopen(results_fd, "wb", buffering=0) as stream:
            while (data := results.get()) is not None:
                stream.write(data)
    except OSError:
        pass
