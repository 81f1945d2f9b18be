"""What a worker process does for one run: exactly what ``servicebot simulate`` does.

The task carries the robot's source, the scenario with the sweep's values in place, the seed
and the outputs to keep; the worker loads the robot once per process (``load`` memoises it)
and calls :func:`~servicebot_cli.simulate.session.run_and_write`, the function behind
``simulate``, so a run's files are byte for byte those of ``simulate`` alone.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING

from servicebot_cli.common.signals import ENDING_SIGNALS, EndedBySignal
from servicebot_cli.simulate.session import Outputs

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.simulate.scenario.definition import Scenario
    from servicebot_cli.simulate.summary import Summary


@dataclass(frozen=True)
class Task:
    """One run, as sent to a worker.

    Attributes:
        robot: The robot description to load.
        scenario: The scenario with the run's values in place.
        seed: The noise seed.
        scenario_dir: Where the scenario's relative paths (meshes) start.
        outputs: Per-run outputs to keep (absolute paths), or none.
        disabled_pairs: Link pairs left out of the self-contact log (``--srdf``).
    """

    robot: RobotSource
    scenario: Scenario
    seed: int
    scenario_dir: str
    outputs: Outputs = Outputs()
    disabled_pairs: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class Outcome:
    """A finished run: its summary and its wall time in the worker [s] (loading excluded)."""

    summary: Summary
    wall_s: float


def simulate_task(task: Task) -> Outcome:
    """Run ``task`` and write its kept outputs.

    Raises:
        ServicebotError: An output cannot be written, or the scenario does not fit the robot.
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.simulate.session import run_and_write

    for directory in (task.outputs.out_dir, task.outputs.bag, task.outputs.plot):
        if directory is not None:
            Path(directory).parent.mkdir(parents=True, exist_ok=True)
    report = run_and_write(load(task.robot), task.scenario, seed=task.seed,
                           outputs=task.outputs, scenario_dir=Path(task.scenario_dir),
                           disabled_pairs=task.disabled_pairs)
    return Outcome(report.summary, report.wall_s)


HELD_SIGNALS = (signal.SIGINT, *ENDING_SIGNALS)


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """Hold back Ctrl-C and the ending signals while workers start (main thread, POSIX).

    A signal inside ``ProcessPoolExecutor.submit`` could leave the pool half started, and a
    worker that gets Ctrl-C before :func:`prepare_worker` dies with a traceback. Held back
    here, workers start with these signals blocked and unblock them once their handlers are
    set; the sweep gets any signal that came meanwhile when the block ends.
    """
    if threading.current_thread() is not threading.main_thread() \
            or not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, HELD_SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def prepare_worker(environment: Mapping[str, str]) -> None:
    """Set up a local worker process before its first run: environment and signals.

    ``environment`` goes into this process's own environment (BLAS thread counts: numpy,
    loaded by the first run, reads them). A terminal's Ctrl-C reaches every process of its
    group; workers ignore it and the sweep lets the runs under way finish. SIGTERM and
    SIGHUP unwind a worker as they unwind ``simulate`` (so its atomic writers clean up).
    Signals held back by :func:`signals_held` are let through once these are set.
    """
    os.environ.update(environment)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for signum in ENDING_SIGNALS:
        signal.signal(signum, _raise)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, HELD_SIGNALS)


def _raise(signum: int, frame: FrameType | None) -> None:
    raise EndedBySignal(signum)
