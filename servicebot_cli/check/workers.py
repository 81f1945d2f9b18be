"""``check urdf --jobs N``: files checked by worker processes, reports in the files' order.

The files are cut into contiguous runs (neighbours in a directory share meshes, and each
worker reads a mesh once, through its own :class:`~servicebot_cli.check.meshes.MeshCache`),
several per worker so that a slow file does not leave the others idle. Workers ignore
SIGINT: the parent alone answers Ctrl-C, and stops them. Nothing is written by a worker; the
reports come back to the parent, which renders them as a serial run does.
"""

from __future__ import annotations

import gc
import itertools
import os
import signal
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.findings import Issue
from servicebot_cli.check.meshes import MeshCache
from servicebot_cli.check.runner import FileReport, check_source, place_issues
from servicebot_cli.check.settings import Settings
from servicebot_cli.common.errors import DescriptionError, ExitCode, ServicebotError
from servicebot_cli.common.signals import ENDING_SIGNALS
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.description.packages import PackageResolver

_RUNS_PER_WORKER = 4
_LONGEST_RUN = 8  # files: long runs leave a worker idle at the end
_WHOLE_DIRECTORY = 16  # files of one directory kept in one run, sharing its meshes
_M_TRIM_THRESHOLD, _M_TOP_PAD = -1, -2  # glibc's mallopt parameters (malloc.h)


def available_cores() -> int:
    """Cores this process may run on (its CPU affinity), at least 1."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


@dataclass(frozen=True)
class Refused:
    """A file the loader refused outright (missing, a directory, unreadable).

    Attributes:
        display: The file as the user named it.
        message: The loader's message.
        named: The user named it (an error of the run), else it was found in a directory.
    """

    display: str
    message: str
    named: bool


Outcome = FileReport | Refused


class _Worker:
    """What a worker process keeps between its runs of files: settings and the mesh cache."""

    env: CheckEnv
    settings: Settings


def _start(settings: Settings, packages: tuple[tuple[str, str], ...],
           mesh_cache: Path | None) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for ending in ENDING_SIGNALS:  # not the parent's handlers: it stops them with SIGTERM
        signal.signal(ending, signal.SIG_DFL)
    _keep_freed_memory()
    collect_garbage_rarely()
    _Worker.settings = settings
    _Worker.env = env_for(packages, settings, mesh_cache)


def _keep_freed_memory() -> None:
    """Have glibc keep the memory a worker frees, for the next mesh, until the worker ends.

    A worker reads hundreds of megabytes of meshes one file at a time. By default glibc hands
    freed memory back to the system and asks for it again at the next file: every page then
    costs a fault and is zeroed again (a third of the workers' system time on the corpus of
    ``bench/check.py``). Elsewhere than glibc, nothing changes.
    """
    try:
        import ctypes

        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):  # pragma: no cover - not glibc
        return
    mallopt(_M_TRIM_THRESHOLD, 1 << 30)  # give back only beyond 1 GB free at the top
    mallopt(_M_TOP_PAD, 1 << 28)  # and grow the heap 256 MB at a time


def collect_garbage_rarely() -> None:
    """Have the cycle collector look at fewer objects, less often, for a run of many files.

    Checking a file makes tens of thousands of short-lived objects (elements, findings),
    freed by reference counting; the collector's default (every 700 allocations, through
    every object the imports made) spent 6 to 8 % of a run's CPU finding no cycle. The
    objects alive now (modules, the catalogue) are frozen out of its sight.
    """
    gc.freeze()
    gc.set_threshold(50_000, 20, 20)


def env_for(packages: tuple[tuple[str, str], ...], settings: Settings,
            mesh_cache: Path | None = None) -> CheckEnv:
    """The shared part of a run: package search and mesh cache (kept in ``mesh_cache``)."""
    resolver = PackageResolver.from_environment({k: Path(v) for k, v in packages})
    store = None
    if mesh_cache is not None:
        from servicebot_cli.check.mesh_store import MeshStore  # hashlib, json: only then

        store = MeshStore(mesh_cache)
    return CheckEnv(resolver=resolver, meshes=MeshCache(store),
                    inertia_factor=settings.inertia_factor)


def check_one(source: RobotSource, named: bool, settings: Settings, env: CheckEnv) -> Outcome:
    """The report of one file, or why the loader refused it."""
    try:
        return check_source(source, settings, env, named)
    except DescriptionError as exc:
        return Refused(source.display, str(exc), named)


def _check_run(run: Sequence[tuple[RobotSource, bool]]) -> list[Outcome]:
    return [check_one(source, named, _Worker.settings, _Worker.env) for source, named in run]


def runs(sources: Sequence[tuple[RobotSource, bool]],
         jobs: int) -> Iterator[Sequence[tuple[RobotSource, bool]]]:
    """Contiguous runs of a few files (four per worker, at most eight), for ``jobs`` workers.

    A directory of a few files is kept whole, so a run may hold up to sixteen.

    Files of one directory share meshes (a robot's variants): split over two workers, each
    would read them. A directory of more than :data:`_WHOLE_DIRECTORY` files is cut.
    """
    size = min(_LONGEST_RUN, max(1, -(-len(sources) // (jobs * _RUNS_PER_WORKER))))
    run: list[tuple[RobotSource, bool]] = []
    for _, group in itertools.groupby(sources, key=lambda item: item[0].path.parent):
        files = list(group)
        if len(files) > _WHOLE_DIRECTORY:
            for start in range(0, len(files), size):
                run += files[start:start + size]
                if len(run) >= size:
                    yield run
                    run = []
            continue
        if run and len(run) + len(files) > size:
            yield run
            run = []
        run += files
        if len(run) >= size:
            yield run
            run = []
    if run:
        yield run


class WorkerDied(ServicebotError):
    """A worker process died (a native library crashed on a file); exit code 3."""

    exit_code = ExitCode.INTERNAL


def check_in_workers(sources: Sequence[tuple[RobotSource, bool]], settings: Settings,
                     packages: tuple[tuple[str, str], ...], jobs: int,
                     mesh_cache: Path | None = None) -> Iterator[Outcome]:
    """Each source's outcome, in order, checked by ``jobs`` worker processes.

    Raises:
        WorkerDied: A worker was killed by a signal (a crash in a native library): the
            files of the run it had are named.
    """
    import multiprocessing  # not for a single file
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    pool = ProcessPoolExecutor(jobs, mp_context=context, initializer=_start,
                               initargs=(settings, packages, mesh_cache))
    work = list(runs(sources, jobs))
    try:
        futures = [pool.submit(_check_run, run) for run in work]
        for run, future in zip(work, futures, strict=True):
            try:
                outcomes = future.result()
            except BrokenProcessPool:
                names = ", ".join(source.display for source, _ in run)
                raise WorkerDied(f"a worker process died while checking {names}: a native "
                                 "library crashed on one of them; check them one at a time "
                                 "with --jobs 1 to see which") from None
            yield from outcomes
    finally:  # at once on an error, a signal or a refused file; else they are done
        for process in list(getattr(pool, "_processes", {}).values()):
            if process.is_alive():
                process.terminate()
        pool.shutdown(wait=True, cancel_futures=True)


def report_of(outcome: Outcome, settings: Settings) -> FileReport:
    """The report of ``outcome``: a refused file found in a directory is SB001.

    Raises:
        DescriptionError: A file the user named was refused (the run's error, exit 2).
    """
    if isinstance(outcome, FileReport):
        return outcome
    if outcome.named:
        raise DescriptionError(outcome.message)
    issue = Issue("SB001", outcome.message.split(": ", 1)[-1], where=(outcome.display, 0, 0))
    return FileReport(outcome.display, tuple(place_issues(None, [issue], settings)))
