"""The simulator's worker process: the same results as in-process, and nothing left behind.

The unit tests drive :class:`~servicebot_cli.common.forked.Worker` directly; the others run
the real ``servicebot simulate``: on one core against two (the same bytes), and with its
worker killed or the run ended by a signal (no output, and no process, left behind).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from servicebot_cli.common import forked as worker_module
from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.common.forked import PIPE_BYTES, Worker, WorkerEnded, second_core
from tests.processes import children, reaped

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="the worker is forked")


class _Counter:
    """A function with state carried from job to job, as the scan noise is."""

    def __init__(self) -> None:
        self.calls = 0

    def __call__(self, job: int) -> tuple[int, int, int]:
        self.calls += 1
        if job < 0:
            raise ValueError(f"job {job} refused")
        if job == 99:
            time.sleep(60)
        return os.getpid(), self.calls, job * 2


def test_a_forked_worker_gives_each_result_in_order_from_its_own_process():
    counter = _Counter()
    worker: Worker[int, tuple[int, int, int]] = Worker(counter, forked=True)
    pid = worker.pid
    assert pid is not None and pid != os.getpid()
    for job in (1, 2, 3):
        worker.submit(job)
    worker.no_more_jobs()
    assert [worker.result() for _ in range(3)] == [(pid, 1, 2), (pid, 2, 4), (pid, 3, 6)]
    assert counter.calls == 0  # the state lives in the worker
    worker.close(finished=True)
    assert reaped(pid)


@pytest.mark.parametrize("forked", [True, False])
def test_dropped_results_are_skipped_and_the_others_come_in_order(forked):
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=forked)
    worker.submit(1)
    worker.submit(2)
    worker.drop_result()
    worker.submit(3)
    worker.submit(4)
    worker.drop_result()
    worker.submit(5)
    worker.no_more_jobs()
    # the dropped jobs are done all the same: the calls count them
    assert [worker.result()[1:] for _ in range(3)] == [(1, 2), (3, 6), (5, 10)]
    worker.close(finished=True)


@pytest.mark.parametrize("forked", [True, False])
def test_a_dropped_jobs_error_is_raised_when_a_later_result_is_asked_for(forked):
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=forked)
    worker.submit(-1)
    worker.drop_result()
    worker.submit(2)
    worker.no_more_jobs()
    with pytest.raises(ValueError, match="job -1 refused"):
        worker.result()
    worker.close()


def _refuse_rebuilding() -> None:
    raise ValueError("cannot be rebuilt here")


class _Unbuildable:
    """A job that pickles, and raises when it is unpickled."""

    def __reduce__(self) -> tuple[object, tuple[()]]:
        return _refuse_rebuilding, ()


def test_a_job_the_worker_cannot_read_is_its_error_not_a_killed_worker():
    worker: Worker[object, tuple[int, int, int]] = Worker(_Counter(), forked=True)
    pid = worker.pid
    worker.submit(_Unbuildable())
    worker.submit(2)
    with pytest.raises(RuntimeError, match="could not read its job: ValueError: cannot be rebuilt"):
        worker.result()
    worker.close()
    assert pid is not None and reaped(pid)


def test_an_in_process_worker_does_each_job_when_its_result_is_taken():
    counter = _Counter()
    worker: Worker[int, tuple[int, int, int]] = Worker(counter, forked=False)
    assert worker.pid is None
    worker.submit(1)
    worker.submit(2)
    assert counter.calls == 0
    assert worker.result() == (os.getpid(), 1, 2)
    assert worker.result() == (os.getpid(), 2, 4)
    worker.close(finished=True)


class _Prepared:
    """A function whose ``prepare`` leaves a mark the jobs read (then fails, if told to)."""

    def __init__(self, fail: bool = False) -> None:
        self.fail, self.mark = fail, None

    def prepare(self) -> None:
        self.mark = os.getpid()
        if self.fail:
            raise OSError("no cache to warm")

    def __call__(self, job: int) -> tuple[int, int | None, int]:
        return os.getpid(), self.mark, job + 1


def test_a_forked_worker_prepares_in_its_own_process_before_the_first_job():
    function = _Prepared()
    work = Worker(function, forked=True, prepare=function.prepare)
    work.submit(1)
    pid, mark, value = work.result()
    work.close(finished=True)
    assert (pid, mark, value) == (pid, pid, 2) and pid != os.getpid()
    assert function.mark is None  # the parent's copy is untouched


def test_a_prepare_that_fails_leaves_the_jobs_to_run():
    function = _Prepared(fail=True)
    work = Worker(function, forked=True, prepare=function.prepare)
    work.submit(1)
    pid, mark, value = work.result()
    assert (mark, value) == (pid, 2)  # it was called, and its error did not stop the job
    work.close(finished=True)


def test_an_error_in_the_worker_is_raised_in_the_parent_and_the_worker_reaped():
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=True)
    pid = worker.pid
    assert pid is not None
    worker.submit(1)
    worker.submit(-1)
    assert worker.result()[2] == 2
    with pytest.raises(ValueError, match="job -1 refused") as caught:
        worker.result()
    worker.close()
    assert reaped(pid)
    # where it was raised in the worker, for --debug (the parent's traceback ends at result)
    [note] = caught.value.__notes__
    assert note.startswith("raised in the forked process:\nTraceback")
    assert "in __call__" in note and note.endswith("ValueError: job -1 refused")


def test_a_worker_closed_before_its_results_is_killed_and_reaped_at_once():
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=True)
    pid = worker.pid
    assert pid is not None
    worker.submit(99)  # a minute's work
    began = time.monotonic()
    worker.close()
    assert time.monotonic() - began < 5
    assert reaped(pid)
    worker.close()  # twice is harmless


def test_a_worker_killed_from_outside_is_reported():
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=True)
    pid = worker.pid
    assert pid is not None
    worker.submit(99)
    os.kill(pid, signal.SIGKILL)
    with pytest.raises(WorkerEnded, match="ended before its results came"):
        worker.result()
    worker.close()
    assert reaped(pid)


def _states(pid: int) -> set[str]:
    """The state letters of the process's threads in /proc ("Z": ended; none: gone)."""
    found = set()
    try:
        tasks = list(Path(f"/proc/{pid}/task").iterdir())
    except OSError:
        return found
    for task in tasks:
        try:
            found.add((task / "stat").read_text().rsplit(")", 1)[1].split()[0])
        except OSError:
            continue
    return found


def _ended(pid: int, within_s: float = 20.0) -> bool:
    """Every thread of the process has ended.

    Its leader ends first; the last thread to end, tearing down a large address space,
    still holds the process's files (the pipes) for a while.
    """
    deadline = time.monotonic() + within_s
    while _states(pid) - {"Z"}:
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)
    return True


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
def test_a_job_submitted_after_the_worker_stopped_at_an_error_raises_that_error():
    """Not "killed from outside": the error the worker sent before it ended."""
    worker: Worker[int, tuple[int, int, int]] = Worker(_Counter(), forked=True)
    pid = worker.pid
    assert pid is not None
    worker.submit(-1)
    assert _ended(pid)  # it stopped at the error: the next job meets a broken pipe
    with pytest.raises(ValueError, match="job -1 refused"):
        worker.submit(2)
    worker.close()
    assert reaped(pid)


class _Unrebuildable(ServicebotError):
    """An error whose pickled form cannot be rebuilt (its constructor takes two arguments)."""

    exit_code = ExitCode.FAILED

    def __init__(self, what: str, where: str) -> None:
        super().__init__(f"{what} at {where}")


def _refuse(job: int) -> int:
    raise _Unrebuildable("a mesh cannot be read", f"job {job}")


def test_an_error_that_cannot_be_rebuilt_keeps_its_message_and_exit_code():
    worker: Worker[int, int] = Worker(_refuse, forked=True)
    worker.submit(3)
    with pytest.raises(ServicebotError, match="a mesh cannot be read at job 3") as caught:
        worker.result()
    assert caught.value.exit_code == ExitCode.FAILED
    assert "in _refuse" in caught.value.__notes__[0]  # rebuilt, with where it was raised
    worker.close()


_ORPHAN = """
import os, pickle, sys
from servicebot_cli.common.forked import Worker
worker = Worker(abs, forked=True)
print(worker.pid, flush=True)
worker._jobs.write(pickle.dumps(list(range(100000)))[:1000])  # a job cut short
worker._jobs.flush()
os._exit(0)  # the parent dies without closing anything
"""


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
def test_a_worker_whose_parent_died_in_the_middle_of_a_job_ends():
    done = subprocess.run([sys.executable, "-c", _ORPHAN], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert _ended(int(done.stdout)), "the orphaned worker still runs"
    assert "Traceback" not in done.stderr


def _big(job: int) -> bytes:
    return bytes(2 << 20)  # more than a pipe holds: the writer waits for the parent


def test_closing_a_worker_whose_writer_waits_on_a_full_pipe_prints_nothing(capfd):
    for _ in range(10):
        worker: Worker[int, bytes] = Worker(_big, forked=True)
        for job in range(3):
            worker.submit(job)
        time.sleep(0.1)  # the first result fills the pipe
        worker.close()
    assert capfd.readouterr().err == ""


def _handlers(job: int) -> list[object]:
    return [signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP,
                                          signal.SIGQUIT)]


def test_the_worker_ignores_ctrl_c_and_ends_at_once_on_the_ending_signals():
    worker: Worker[int, list[object]] = Worker(_handlers, forked=True)
    worker.submit(0)
    assert worker.result() == [signal.SIG_IGN, signal.SIG_DFL, signal.SIG_DFL, signal.SIG_DFL]
    worker.close()


def test_one_core_or_no_fork_means_in_process(monkeypatch):
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0}, raising=False)
    assert not second_core()
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1}, raising=False)
    assert second_core()
    monkeypatch.delattr(os, "fork")
    assert not worker_module.second_core()


def _second_core_in_a_pool_worker() -> bool:
    return second_core()


def test_a_worker_of_a_process_pool_does_its_jobs_in_process():
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        assert pool.submit(_second_core_in_a_pool_worker).result() is False


# The real command.

_TWO_CORES = pytest.mark.skipif(
    not hasattr(os, "sched_getaffinity") or len(os.sched_getaffinity(0)) < 2,
    reason="needs two cores to run a worker")


def _simulate(cwd: Path, *args: str, one_core: bool = False,
              **popen: object) -> subprocess.Popen[bytes]:
    first = min(os.sched_getaffinity(0)) if one_core else None
    return subprocess.Popen(  # type: ignore[call-overload]
        [sys.executable, "-m", "servicebot_cli", "simulate", "--headless", *args], cwd=cwd,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, env={**os.environ, "CI": ""},
        preexec_fn=(lambda: os.sched_setaffinity(0, {first})) if one_core else None,
        start_new_session=True, **popen)


def _files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


def _wait_for_worker(process: subprocess.Popen[bytes], cwd: Path) -> int:
    """The run's worker: its child once the outputs are begun in ``cwd`` (the process that
    builds the model ahead is gone by then)."""
    deadline = time.monotonic() + 120
    while not (any(cwd.iterdir()) and (found := children(process.pid))):
        assert process.poll() is None, "the run ended before its worker was seen"
        assert time.monotonic() < deadline, "no worker process came"
        time.sleep(0.002)
    [child] = found
    return child


def _nothing_left(session: int, child: int) -> bool:
    with pytest.raises(ProcessLookupError):
        os.killpg(session, 0)  # no process of the run's session is left
    return not Path(f"/proc/{child}").exists()


@_TWO_CORES
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
def test_on_one_core_the_run_writes_the_same_bytes_as_with_its_worker(tmp_path):
    runs = {}
    for name, one_core in (("one", True), ("two", False)):
        (tmp_path / name).mkdir()
        process = _simulate(tmp_path / name, "--duration-s", "70", "--bag", "B", "--out", "O",
                            one_core=one_core)
        stdout, stderr = process.communicate(timeout=300)
        assert process.returncode == 0, stderr.decode()
        runs[name] = (stdout, _files(tmp_path / name))
    assert runs["one"] == runs["two"]
    assert "scan.csv" in {Path(name).name for name in runs["one"][1]}


@_TWO_CORES
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
def test_a_run_whose_worker_is_killed_fails_and_leaves_nothing(tmp_path):
    process = _simulate(tmp_path, "--duration-s", "3600", "--bag", "B", "--out", "O")
    child = _wait_for_worker(process, tmp_path)
    os.kill(child, signal.SIGKILL)
    _, stderr = process.communicate(timeout=120)
    assert process.returncode == 1, stderr.decode()
    assert "worker process" in stderr.decode() and "ended before" in stderr.decode()
    assert list(tmp_path.iterdir()) == []  # no bag, no CSV directory, no temporary
    assert _nothing_left(process.pid, child)


@_TWO_CORES
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
@pytest.mark.parametrize(("signum", "code", "group"), [(signal.SIGTERM, 143, False),
                                                       (signal.SIGINT, 130, True),
                                                       (signal.SIGHUP, 129, True)])
def test_a_run_ended_by_a_signal_stops_its_worker(tmp_path, signum, code, group):
    """To the run alone (a CI job cancelled) or to its whole group (Ctrl-C, a closed terminal)."""
    process = _simulate(tmp_path, "--duration-s", "3600", "--bag", "B")
    child = _wait_for_worker(process, tmp_path)
    if group:
        os.killpg(process.pid, signum)
    else:
        process.send_signal(signum)
    _, stderr = process.communicate(timeout=120)
    assert process.returncode == code, stderr.decode()
    assert list(tmp_path.iterdir()) == []
    assert _nothing_left(process.pid, child)


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc")
def test_a_run_of_several_pieces_with_a_second_core_forks_its_worker_and_reaps_it(monkeypatch):
    """The pieces' generator forks one worker, which is gone once the generator is closed."""
    from servicebot_cli.simulate import simulator
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.simulate.world.solids import world_solids
    from tests.simulate.helpers import body

    monkeypatch.setattr(simulator, "second_core", lambda: True)
    scenario = load_scenario(None)
    pieces = simulator.pieces(body(), scenario, seed=0, solids=world_solids(scenario.world))
    before = set(children(os.getpid()))
    next(pieces)
    [worker] = set(children(os.getpid())) - before
    pieces.close()
    assert reaped(worker)


@pytest.mark.skipif(not hasattr(__import__("fcntl"), "F_GETPIPE_SZ"), reason="Linux pipes only")
def test_its_pipes_hold_a_whole_piece_so_submitting_never_waits_on_its_reader():
    import fcntl

    limit = int(Path("/proc/sys/fs/pipe-max-size").read_text())
    worker = Worker(lambda job: job, forked=True)
    try:
        assert worker._jobs is not None and worker._results is not None
        for pipe in (worker._jobs, worker._results):
            size = fcntl.fcntl(pipe.fileno(), fcntl.F_GETPIPE_SZ)
            assert size == min(PIPE_BYTES, limit) and size > 219_000  # a default piece's job
        worker.submit(7)
        assert worker.result() == 7
    finally:
        worker.close()
