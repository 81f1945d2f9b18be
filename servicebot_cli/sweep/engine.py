"""Where runs execute: local worker processes or a Dask cluster, behind one Executor.

Both are :class:`concurrent.futures.Executor`: a :class:`~concurrent.futures.ProcessPoolExecutor`
here, ``distributed.Client.get_executor()`` on a cluster. :func:`execute` submits every task
and hands each outcome over as it finishes, in whatever order they finish.
"""

from __future__ import annotations

import contextlib
import importlib
import os
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor, as_completed, wait
from typing import Any

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.sweep.worker import Outcome, Task, prepare_worker, simulate_task

CLUSTER_EXTRA = "pip install 'servicebot[cluster]' (dask and distributed)"


class SchedulerError(ServicebotError):
    """The Dask scheduler cannot be reached, or Dask is not installed."""


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system knows it)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS, Windows
        return os.cpu_count() or 1


@contextlib.contextmanager
def local_executor(jobs: int) -> Iterator[Executor]:
    """``jobs`` worker processes; on the way out, runs not started are cancelled."""
    pool = ProcessPoolExecutor(max_workers=jobs, initializer=prepare_worker)
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
    try:
        client = distributed.Client(address, timeout=timeout_s)
    except (OSError, TimeoutError, ValueError) as exc:
        raise SchedulerError(f"no Dask scheduler answers at {address} ({exc}); start one "
                             "with 'dask scheduler' or check the address") from None
    try:
        executor: Executor = client.get_executor(pure=False)
        yield executor
    finally:
        client.close()


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
    """
    futures: dict[Future[Outcome], int] = {
        executor.submit(simulate_task, task): index for index, task in enumerate(tasks)}
    handed: set[Future[Outcome]] = set()
    try:
        for future in as_completed(futures):
            handed.add(future)
            finished(futures[future], future.result())
    except BaseException:
        for future in futures:
            future.cancel()
        under_way = [f for f in futures if f not in handed and not f.cancelled()]
        for future in wait(under_way).done:
            if not future.cancelled() and future.exception() is None:
                finished(futures[future], future.result())
        raise
