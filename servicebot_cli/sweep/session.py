"""One ``sweep`` invocation: a request in, every run done (or found done), a typed report out.

Click-free, so the command only builds a :class:`SweepRequest` and bench/sweep.py can drive
and time the same function. Everything the sweep file asks for is checked before the first
run: the file's fields, the scenario with every combination of values, the expectations.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.simulate.expectations import Expectation
    from servicebot_cli.sweep.definition import SweepDefinition
    from servicebot_cli.sweep.plan import Run
    from servicebot_cli.sweep.store import Record


@dataclass(frozen=True)
class SweepRequest:
    """Everything a sweep needs.

    Attributes:
        sweep_file: The sweep file (YAML or JSON).
        robot: The robot description every run simulates.
        jobs: Local worker processes (ignored with ``scheduler``).
        scheduler: A Dask scheduler's address, or None for local processes.
        out_dir: Where tables, records and kept outputs go; None: nowhere (no resuming).
        keep: Per-run outputs to keep: any of ``csv``, ``bag``, ``plot``.
        plot: A picture of every metric against every swept value, or None.
        progress: Draw a progress bar (None: on a terminal, outside CI).
        allow_collisions: Run arm points that put links into each other or the floor, as
            ``simulate --allow-collisions`` does; else such a scenario is refused up front.
        srdf: An SRDF whose ``<disable_collisions>`` pairs are never checked.
    """

    sweep_file: str
    robot: RobotSource
    jobs: int = 1
    scheduler: str | None = None
    out_dir: str | None = None
    keep: tuple[str, ...] = ()
    plot: str | None = None
    progress: bool | None = None
    allow_collisions: bool = False
    srdf: str | None = None


@dataclass(frozen=True)
class RunResult:
    """A finished run: the run, its stored record, its metrics and the expectations it failed."""

    run: Run
    record: Record
    metrics: dict[str, float]
    failed: tuple[str, ...]
    resumed: bool


@dataclass(frozen=True)
class SweepReport:
    """What the command shows and writes.

    Attributes:
        sweep: The sweep file as named.
        robot: The robot's name.
        scenario: The scenario's name.
        planned: How many runs the sweep has.
        shape: Grid points, draws and seeds (their product is ``planned``).
        expectations: The ``expect`` lines, as written.
        results: The finished runs, in the sweep's order.
        workers: Where runs ran: ``2 local workers`` or the scheduler's address.
        wall_s: Wall time of the runs done now [s] (checks and loading excluded).
        files: Files written into the output directory.
        notes: What the sweep changed of the built-in scenario for this robot.
    """

    sweep: str
    robot: str
    scenario: str
    planned: int
    shape: tuple[int, int, int]
    expectations: tuple[str, ...]
    results: tuple[RunResult, ...]
    workers: str
    wall_s: float
    files: tuple[Path, ...] = field(default=())
    notes: tuple[str, ...] = ()

    @property
    def resumed(self) -> int:
        """Runs found finished in the output directory, not run again."""
        return sum(r.resumed for r in self.results)

    @property
    def failed(self) -> tuple[RunResult, ...]:
        """The runs that failed an expectation."""
        return tuple(r for r in self.results if r.failed)


def run(request: SweepRequest, *, stderr: TextIO | None = None,
        clock: Callable[[], float] = time.perf_counter) -> SweepReport:
    """Check the sweep, run what is not done yet, write the tables; return the report.

    An interruption (Ctrl-C, SIGTERM) keeps the runs finished so far: their records, and
    the tables of what finished, are written before it goes on.

    Raises:
        ServicebotError: A bad sweep file, scenario value, expectation, robot or output;
            a run that failed; no Dask scheduler.
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.sweep import store
    from servicebot_cli.sweep.definition import load_sweep
    from servicebot_cli.sweep.plan import plan

    definition = load_sweep(request.sweep_file)
    base = load_scenario(definition.scenario_file)
    checks = _expectations(definition)
    robot = load(request.robot)
    runs = plan(definition, base, robot.xml_text)
    notes: tuple[str, ...] = ()
    if definition.scenario_file is None:  # the built-in scenario, as simulate fits it
        runs, notes = _fitted(runs, robot)
    from servicebot_cli.kinematics.srdf import robot_disabled_pairs

    disabled = robot_disabled_pairs(request.srdf, robot)
    _check_against_robot(definition, runs, robot, disabled,
                         check_points=not request.allow_collisions)
    out_dir = Path(request.out_dir) if request.out_dir else None
    if out_dir is not None:
        _make_dir(out_dir)
    results: dict[int, RunResult] = {}
    for r in runs:
        record = store.load_record(out_dir, r.key, request.keep) if out_dir else None
        if record is not None:
            results[r.index] = _result(r, record, checks, resumed=True)
    todo = [r for r in runs if r.index not in results]

    def report(wall_s: float, files: Sequence[Path] = ()) -> SweepReport:
        return SweepReport(request.sweep_file, robot.name, base.name, len(runs),
                           _shape(definition), tuple(c.text for c in checks),
                           tuple(results[i] for i in sorted(results)),
                           _workers(request), wall_s, tuple(files), notes)

    files: tuple[Path, ...] = ()
    start = clock()
    try:
        _run_all(request, definition, todo, checks, results, out_dir, stderr, disabled)
    finally:  # Ctrl-C, SIGTERM or a failed run: the tables of what finished
        if out_dir is not None and results:
            files = _write(report(clock() - start), out_dir, stderr)
    finished = report(clock() - start, files)
    if request.plot is not None:
        from servicebot_cli.sweep.plot import write_plot

        write_plot(finished, request.plot)
    return finished


def _fitted(runs: list[Run], robot: RobotDescription) -> tuple[list[Run], tuple[str, ...]]:
    """The runs of the built-in scenario with its arm goal fitted to ``robot``, and the notes.

    As ``simulate`` runs it (:func:`~servicebot_cli.simulate.session.default_arm_for`): a
    robot without the bundled arm's joints holds its own still; a joint it makes mimic
    another follows its leader.
    """
    from servicebot_cli.simulate.session import default_arm_for

    fitted, notes = [], {}
    for r in runs:
        scenario, said = default_arm_for(r.scenario, robot)
        fitted.append(dataclasses.replace(r, scenario=scenario))
        notes.update(dict.fromkeys(said))
    return fitted, tuple(notes)


def _run_all(request: SweepRequest, definition: SweepDefinition, todo: list[Run],
             checks: Sequence[Expectation], results: dict[int, RunResult],
             out_dir: Path | None, stderr: TextIO | None,
             disabled: tuple[tuple[str, str], ...] = ()) -> None:
    """Run ``todo`` on the workers, storing each result as it comes.

    ``disabled`` pairs are left out of each run's self-contact log.
    """
    from servicebot_cli.simulate.session import Outputs
    from servicebot_cli.sweep import store
    from servicebot_cli.sweep.engine import execute, executor_for
    from servicebot_cli.sweep.plan import scenario_dir
    from servicebot_cli.sweep.progress import SweepProgress
    from servicebot_cli.sweep.worker import Outcome, Task

    if not todo:
        return
    directory = str(scenario_dir(definition).resolve())
    tasks = [Task(request.robot, r.scenario, r.seed, directory,
                  store.kept_outputs(out_dir, r.key, request.keep) if out_dir else Outputs(),
                  disabled) for r in todo]
    total = len(todo) + len(results)
    bar = SweepProgress(total, stderr, done=len(results), enabled=request.progress) \
        if stderr is not None else None

    def finished(index: int, outcome: Outcome) -> None:
        r = todo[index]
        record = store.save_record(out_dir, r, outcome.summary, outcome.wall_s) if out_dir \
            else store.Record(r.key, r.seed, dict(r.values), outcome.summary, outcome.wall_s)
        results[r.index] = _result(r, record, checks, resumed=False)
        if bar:
            bar.advance()

    try:
        with executor_for(request.jobs, request.scheduler) as executor:
            execute(executor, tasks, finished)
    finally:
        if bar:
            bar.close()


def _expectations(definition: SweepDefinition) -> list[Expectation]:
    from servicebot_cli.simulate.expectations import ExpectationError, parse_expectation

    checks = []
    for item in definition.expectations:
        try:
            checks.append(parse_expectation(item.text))
        except ExpectationError as exc:
            raise definition.error(item.where, str(exc)) from None
    return checks


def _check_against_robot(definition: SweepDefinition, runs: Sequence[Run],
                         robot: RobotDescription, disabled: tuple[tuple[str, str], ...] = (),
                         *, check_points: bool = True) -> None:
    """Check each distinct scenario against the robot, as ``simulate`` checks one.

    Arm joints and limits, the start pose, and (``check_points``) arm points in collision.
    """
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.scenario.world_check import check_arm_points, check_scenario
    from servicebot_cli.simulate.world.meshes import load_meshes
    from servicebot_cli.simulate.world.solids import world_solids
    from servicebot_cli.sweep.plan import distinct_scenarios, scenario_dir

    directory = scenario_dir(definition)
    body = sim_robot(robot, disabled_pairs=disabled)
    for r in distinct_scenarios(runs):
        s = r.scenario
        check_scenario(body, s, world_solids(s.world), load_meshes(s, directory))
        if check_points:
            check_arm_points(body, s)


def _result(r: Run, record: Record, checks: Sequence[Expectation], *,
            resumed: bool) -> RunResult:
    from servicebot_cli.sweep.metrics import flat_metrics

    failed = tuple(c.text for c in checks if not c.holds(record.summary))
    return RunResult(r, record, flat_metrics(record.summary), failed, resumed)


def _make_dir(out_dir: Path) -> None:
    from servicebot_cli.common.files import OutputError

    try:
        out_dir.mkdir(exist_ok=True)
    except OSError as exc:
        raise OutputError(f"{out_dir}: cannot create the directory: "
                          f"{exc.strerror or exc}") from None


def _write(report: SweepReport, out_dir: Path, stderr: TextIO | None) -> tuple[Path, ...]:
    from servicebot_cli.sweep.tables import write_tables

    written = write_tables(report, out_dir)
    for note in written.notes if stderr is not None else ():
        print(note, file=stderr)
    return written.files


def _shape(definition: SweepDefinition) -> tuple[int, int, int]:
    points = 1
    for axis in definition.grid:
        points *= len(axis.values)
    return points, max(definition.sample_n, 1), len(definition.seeds)


def _workers(request: SweepRequest) -> str:
    if request.scheduler:
        return f"Dask at {request.scheduler}"
    return f"{request.jobs} local worker{'s' if request.jobs != 1 else ''}"
