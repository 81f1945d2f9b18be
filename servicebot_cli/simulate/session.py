"""One ``simulate`` invocation: a request in, the run's report out, every output written.

Click-free, so the command only builds a :class:`SimulateRequest` and bench/simulate.py can
drive and time the same function. The progress stream and the clock are injected.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.simulate.scenario.definition import Scenario

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.simulate.bag.ros_messages import Stream
    from servicebot_cli.simulate.expectations import Expectation
    from servicebot_cli.simulate.simulator import SimResult
    from servicebot_cli.simulate.summary import Summary


@dataclass(frozen=True)
class Outputs:
    """Where a run writes: a CSV directory, a bag directory, a picture; None for none."""

    out_dir: str | None = None
    bag: str | None = None
    plot: str | None = None


@dataclass(frozen=True)
class Overrides:
    """Command-line values that replace the scenario file's; None keeps the file's."""

    duration_s: float | None = None
    saturation: str | None = None
    wheel_separation_multiplier: float | None = None
    cmd_vel_timeout_s: float | None = None
    max_linear_acceleration_m_s2: float | None = None
    max_angular_acceleration_rad_s2: float | None = None
    controllers_file: str | None = None


@dataclass(frozen=True)
class SimulateRequest:
    """Everything one run needs.

    Attributes:
        robot: The robot description to simulate.
        scenario_file: A YAML or JSON scenario, or None for the built-in one.
        overrides: Values that replace the scenario's.
        seed: Seed of all sensor noise (non-negative).
        outputs: Files and directories to write.
        live_window: The run is played back in a window afterwards: a display must exist.
        progress: Draw a progress bar (None: on a terminal, outside CI).
        expectations: What the summary must meet (``simulate --expect``).
    """

    robot: RobotSource
    scenario_file: str | None = None
    overrides: Overrides = Overrides()
    seed: int = 0
    outputs: Outputs = Outputs()
    live_window: bool = False
    progress: bool | None = None
    expectations: tuple[Expectation, ...] = ()


@dataclass(frozen=True)
class SimulateReport:
    """What the command shows: the summary, the wall time of the run [s] and the run itself.

    ``unmet`` holds each expectation the summary does not meet, with the value it has (None
    when the field has none).
    """

    summary: Summary
    wall_s: float
    result: SimResult
    unmet: tuple[tuple[Expectation, float | None], ...] = ()

    @property
    def real_time_factor(self) -> float:
        """Simulated time over the wall time the run took."""
        return self.summary["duration_s"] / max(self.wall_s, 1e-9)


def run(request: SimulateRequest, *, stderr: TextIO | None = None,
             clock: Callable[[], float] = time.perf_counter) -> SimulateReport:
    """Load the robot and the scenario, run it and write every requested output.

    Args:
        request: The run.
        stderr: Where the progress bar goes (None: no bar).
        clock: Wall clock [s] for the report's ``wall_s``.

    Raises:
        ServicebotError: Bad robot or scenario, no display for the live window, or an
            output that cannot be written.
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.simulate.files.live import display_problem
    from servicebot_cli.simulate.scenario.definition import load_scenario

    robot = load(request.robot)
    scenario = with_overrides(load_scenario(request.scenario_file), request.overrides)
    problem = display_problem() if request.live_window else ""
    if problem:  # checked after the input, before any work
        raise ServicebotError(f"{problem}; use --headless (with --plot FILE.png for a picture)")
    scenario_dir = Path(request.scenario_file).parent if request.scenario_file else Path.cwd()
    report = run_and_write(robot, scenario, seed=request.seed, outputs=request.outputs,
                           scenario_dir=scenario_dir, stderr=stderr, progress=request.progress,
                           clock=clock, controllers=request.overrides.controllers_file)
    unmet = tuple((e, e.value(report.summary)) for e in request.expectations
                  if not e.holds(report.summary))
    return dataclasses.replace(report, unmet=unmet)


def with_overrides(scenario: Scenario, overrides: Overrides) -> Scenario:
    """``scenario`` with the values of ``overrides`` that are not None in place of its own."""
    changes = {f.name: getattr(overrides, f.name) for f in dataclasses.fields(overrides)
               if f.name not in ("duration_s", "controllers_file")
               and getattr(overrides, f.name) is not None}
    controller = dataclasses.replace(scenario.controller, **changes)
    duration_s = scenario.duration_s if overrides.duration_s is None else overrides.duration_s
    return dataclasses.replace(scenario, controller=controller, duration_s=duration_s,
                               controller_cli=scenario.controller_cli | frozenset(changes))


def run_and_write(robot: RobotDescription, scenario: Scenario, *, seed: int,
                  outputs: Outputs, scenario_dir: Path, stderr: TextIO | None = None,
                  progress: bool | None = None,
                  clock: Callable[[], float] = time.perf_counter,
                  controllers: str | None = None) -> SimulateReport:
    """Run ``scenario`` on a loaded robot and write ``outputs``; the wall time excludes loading.

    The controller's parameters come from the controllers file (``controllers``, else the
    one the robot names or has beside it) where the scenario does not set them.

    Raises:
        ServicebotError: Bad scenario for this robot, an unreadable controllers file, or an
            output that cannot be written.
    """
    from servicebot_cli.simulate.controllers.config import (
        find_controllers_file,
        read_controllers_file,
    )
    from servicebot_cli.simulate.controllers.resolve import resolve

    scenario = resolve(scenario, read_controllers_file(find_controllers_file(robot,
                                                                             controllers)))
    from servicebot_cli.simulate import simulator
    from servicebot_cli.simulate.bag import ros_messages
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.files.progress import Progress
    from servicebot_cli.simulate.summary import summarize
    from servicebot_cli.simulate.world.meshes import load_meshes
    from servicebot_cli.simulate.world.solids import world_solids

    start = clock()
    body = sim_robot(robot)
    meshes = load_meshes(scenario, scenario_dir)
    writers = _writers(outputs)
    bar = Progress(simulator.scan_count(body, scenario) + len(writers), stderr,
                   enabled=progress) if stderr is not None else None
    try:
        result = simulator.run(body, scenario, seed=seed, solids=world_solids(scenario.world),
                               meshes=meshes, progress=bar.advance if bar else None)
        streams = ros_messages.streams(result)
        summary = summarize(result, streams)
        for stage, write in writers:
            if bar:
                bar.stage(stage)
            write(result, streams, summary)
            if bar:
                bar.advance()
    finally:  # an error line, or Ctrl-C's, starts on a clean line
        if bar:
            bar.close()
    return SimulateReport(summary, clock() - start, result)


Writer = Callable[["SimResult", "Sequence[Stream]", "Summary"], None]
"""Writes one output from the run, its message streams and its summary."""


def _writers(outputs: Outputs) -> list[tuple[str, Writer]]:
    """The writers ``outputs`` asks for, in order, each with its progress-bar label."""
    from servicebot_cli.simulate.bag.rosbag import write_bag
    from servicebot_cli.simulate.files.csv_out import write_directory
    from servicebot_cli.simulate.files.plot import write_plot

    writers: list[tuple[str, Writer]] = []
    if (bag := outputs.bag) is not None:
        writers.append(("writing bag", lambda result, streams, summary: write_bag(bag, streams)))
    if (out_dir := outputs.out_dir) is not None:
        writers.append(("writing CSV", lambda result, streams, summary:
                        write_directory(out_dir, result, summary)))
    if (plot := outputs.plot) is not None:
        writers.append(("plotting", lambda result, streams, summary: write_plot(plot, result)))
    return writers
