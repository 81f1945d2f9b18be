"""Where runs execute: local worker processes or a Dask cluster, behind one Executor.

Both are :class:`concurrent.futures.Executor`: a :class:`~concurrent.futures.ProcessPoolExecutor`
here, ``distributed.Client.get_executor()`` on a cluster. :func:`execute` submits every task
and hands each outcome over as it finishes, in whatever order they finish.

Local workers are started fresh (``spawn``), not forked: numpy is not loaded in them yet, so
the BLAS thread counts set in each worker's own environment take effect there, and the
caller's environment is left as it was.
"""

from __future__ import annotations

import contextlib
import importlib
import multiprocessing
import os
import socket
from collections.abc import Callable, Iterator, Mapping, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor, as_completed, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any

from servicebot_cli.common.blas_threads import one_thread_each
from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.sweep.worker import (
    Outcome,
    Task,
    prepare_worker,
    signals_held,
    simulate_task,
)

CLUSTER_EXTRA = "pip install 'servicebot[cluster]' (dask and distributed)"


class SchedulerError(ServicebotError):
    """The Dask scheduler cannot be reached, or Dask is not installed."""


class WorkerLost(ServicebotError):
    """A local worker process died: killed, out of memory, a crash, or an unguarded script."""

    exit_code = ExitCode.INTERNAL


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system knows it)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS, Windows
        return os.cpu_count() or 1


def worker_environment(environ: Mapping[str, str]) -> dict[str, str]:
    """What a local worker adds to its environment: one BLAS thread, unless the user chose.

    One run per core: BLAS threads in each worker would compete with the other workers for
    the cores. A count set in ``environ`` is the user's and is left alone.
    """
    return one_thread_each(environ)


@contextlib.contextmanager
def local_executor(jobs: int) -> Iterator[Executor]:
    """``jobs`` fresh worker processes; on the way out, runs not started are cancelled."""
    pool = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn"),
                               initializer=prepare_worker,
                               initargs=(worker_environment(os.environ),))
    try:
        yield pool
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


@contextlib.contextmanager
def dask_executor(address: str, timeout_s: float = 10.0) -> Iterator[Executor]:
    """The workers of the Dask scheduler at ``address`` (``tcp://HOST:8786``).

    Raises:
        SchedulerError: Dask is missing or the scheduler does not answer in ``timeout_s``.
    """
    try:  # typed as Any: distributed ships no type information, and is optional
        distributed: Any = importlib.import_module("distributed")
    except ImportError:
        raise SchedulerError(f"--scheduler needs Dask: {CLUSTER_EXTRA}") from None
    refused = _refused(address, timeout_s)
    try:
        if refused is not None:
            raise refused
        client = distributed.Client(address, timeout=timeout_s)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:  # TypeError: TLS unset
        raise SchedulerError(f"no Dask scheduler answers at {address} ({exc}); start one "
                             "with 'dask scheduler' or check the address") from None
    try:
        executor: Executor = client.get_executor(pure=False)
        yield executor
    finally:
        client.close()


def _refused(address: str, timeout_s: float) -> OSError | None:
    """Why a ``tcp://HOST:PORT`` cannot be connected to, or None (also for other schemes).

    Dask's client retries a refused connection until its timeout; a plain connection
    attempt says at once that nothing listens there.
    """
    scheme, _, rest = address.rpartition("://")
    host, _, port = rest.rpartition(":")
    if scheme not in ("", "tcp") or not port.isdigit():
        return None
    try:
        socket.create_connection((host.strip("[]") or "localhost", int(port)),
                                 timeout=timeout_s).close()
    except OSError as exc:
        return exc
    return None


def executor_for(jobs: int, scheduler: str | None) -> contextlib.AbstractContextManager[Executor]:
    """The Dask cluster at ``scheduler``, or ``jobs`` local processes."""
    return dask_executor(scheduler) if scheduler else local_executor(jobs)


def execute(executor: Executor, tasks: Sequence[Task],
            finished: Callable[[int, Outcome], None]) -> None:
    """Run every task; call ``finished(index, outcome)`` for each as it finishes.

    On an error or an interruption (Ctrl-C, SIGTERM) the tasks not started are cancelled,
    those under way are waited for and handed over, then the exception goes on.

    Raises:
        ServicebotError: A run failed; the others were stopped.
        WorkerLost: A local worker process died.
    """
    futures: dict[Future[Outcome], int] = {}
    handed: set[Future[Outcome]] = set()
    try:
        with signals_held():  # workers start here
            for index, task in enumerate(tasks):
                futures[executor.submit(simulate_task, task)] = index
        for future in as_completed(futures):
            handed.add(future)
            finished(futures[future], _result(future))
    except BaseException:
        for future in futures:
            future.cancel()
        under_way = [f for f in futures if f not in handed and not f.cancelled()]
        for future in wait(under_way).done:
            if not future.cancelled() and future.exception() is None:
                finished(futures[future], future.result())
        raise


def _result(future: Future[Outcome]) -> Outcome:
    try:
        return future.result()
    except BrokenProcessPool:
        raise WorkerLost("a worker process ended abruptly (killed, out of memory, or a "
                         "crash); the runs finished so far are kept, a re-run with the same "
                         "--out goes on from there. A script that starts a sweep needs "
                         "`if __name__ == '__main__':` (workers are fresh processes)") from None
