"""One ``simulate`` invocation, from parsed options to files.

The command's work, kept out of Click so bench/simulate.py can drive and time it.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TextIO

from servicebot_cli.simulate.scenario.definition import Scenario


@dataclass(frozen=True)
class Outputs:
    """Where a run writes: a CSV directory, a bag directory, a PNG; None for none."""

    out_dir: str | None = None
    bag: str | None = None
    plot: str | None = None


@dataclass(frozen=True)
class Report:
    """What the command prints: the summary and the wall time the run took [s]."""

    summary: dict[str, Any]
    wall_s: float
    result: Any


def with_overrides(scenario: Scenario, duration_s: float | None = None,
                   **controller: Any) -> Scenario:
    """``scenario`` with command-line values in place of the file's (None: keep the file's)."""
    changes = {k: v for k, v in controller.items() if v is not None}
    ctrl = dataclasses.replace(scenario.controller, **changes)
    return dataclasses.replace(scenario, controller=ctrl,
                               duration_s=duration_s if duration_s else scenario.duration_s)


def simulate_and_write(robot: Any, scenario: Scenario, *, seed: int, outputs: Outputs,
                       scenario_dir: Path, stderr: TextIO | None = None,
                       progress: bool | None = None) -> Report:
    """Run the scenario and write every requested output.

    Raises:
        ServicebotError: Bad scenario for this robot, or an output that cannot be written.
    """
    from servicebot_cli.simulate import simulator
    from servicebot_cli.simulate.bag import ros_messages
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.files.progress import Progress
    from servicebot_cli.simulate.summary import summarize
    from servicebot_cli.simulate.world.meshes import load_meshes
    from servicebot_cli.simulate.world.solids import world_solids

    start = time.perf_counter()
    body = sim_robot(robot)
    meshes = load_meshes(scenario, scenario_dir)
    bar = Progress(simulator.scan_count(body, scenario) + 3, stderr, enabled=progress) \
        if stderr is not None else None
    result = simulator.run(body, scenario, seed=seed, solids=world_solids(scenario.world),
                           meshes=meshes, progress=bar.advance if bar else None)
    streams = ros_messages.streams(result)
    summary = summarize(result, streams)
    for stage, write in _writers(outputs, result, streams, summary):
        if bar:
            bar.stage(stage)
        write()
        if bar:
            bar.advance()
    if bar:
        bar.close()
    return Report(summary, time.perf_counter() - start, result)


def _writers(outputs: Outputs, result: Any, streams: Any, summary: Any) -> list[tuple[str, Any]]:
    from servicebot_cli.simulate.bag.rosbag import write_bag
    from servicebot_cli.simulate.files.csv_out import write_directory
    from servicebot_cli.simulate.files.plot import write_plot

    writers = []
    if outputs.bag:
        writers.append(("writing bag", lambda: write_bag(outputs.bag, streams)))  # type: ignore[arg-type]
    if outputs.out_dir:
        writers.append(("writing CSV", lambda: write_directory(outputs.out_dir, result, summary)))  # type: ignore[arg-type]
    if outputs.plot:
        writers.append(("plotting", lambda: write_plot(outputs.plot, result)))  # type: ignore[arg-type]
    return writers
