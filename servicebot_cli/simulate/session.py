"""One ``simulate`` invocation: a request in, the run's report out, every output written.

Click-free, so the command only builds a :class:`SimulateRequest` and bench/simulate.py can
drive and time the same function. The progress stream and the clock are injected. The run is
simulated a piece at a time and each piece goes to every output as it comes, so memory does
not grow with the simulated duration; the live window keeps a thinned track of it.
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, TextIO

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.simulate.scenario.definition import Scenario

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.simulate.bag.ros_messages import Publisher
    from servicebot_cli.simulate.expectations import Expectation
    from servicebot_cli.simulate.files.live import LiveTrack
    from servicebot_cli.simulate.model_facts import FactsAhead
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
    camera_scale: float | None = None
    camera_rate_hz: float | None = None
    camera_depth: bool | None = None


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
        allow_collisions: Run a trajectory whose points put links into each other or the
            floor (the run logs it); else such a point is refused, as ``ik`` refuses it.
        srdf: An SRDF whose ``<disable_collisions>`` pairs are never checked.
    """

    robot: RobotSource
    scenario_file: str | None = None
    overrides: Overrides = Overrides()
    seed: int = 0
    outputs: Outputs = Outputs()
    live_window: bool = False
    progress: bool | None = None
    expectations: tuple[Expectation, ...] = ()
    allow_collisions: bool = False
    srdf: str | None = None


@dataclass(frozen=True)
class SimulateReport:
    """What the command shows: the summary and the wall time of the run [s].

    ``result`` is the whole run when it was asked to be kept, else None; ``live_track`` what
    the live window plays, when it was asked for. ``unmet`` holds each expectation the
    summary does not meet, with the value it has (None when the field has none). ``notes``
    are lines for stderr: the built-in scenario's arm goal left out, collision shapes the
    simulator could not use.
    """

    summary: Summary
    wall_s: float
    result: SimResult | None = None
    unmet: tuple[tuple[Expectation, float | None], ...] = ()
    live_track: LiveTrack | None = None
    notes: tuple[str, ...] = ()

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
        ServicebotError: Bad robot or scenario, a trajectory point in collision, an
            unreadable SRDF, no display for the live window, or an output that cannot be
            written.
    """
    import numpy.random  # noqa: F401 -- the pose work's noise, in both processes: before the fork

    from servicebot_cli.description.loader import load
    from servicebot_cli.kinematics.frames import require_tree
    from servicebot_cli.simulate.model_facts import FactsAhead, description_first

    robot = load(request.robot, build_model=False)
    require_tree(robot)  # a joint loop: no model holds it, as fk and inspect say
    with FactsAhead(robot, then_import=("servicebot_cli.simulate.pose_work",)) as facts, \
            description_first(facts):
        return _run_loaded(request, robot, facts, stderr, clock)


def _run_loaded(request: SimulateRequest, robot: RobotDescription, facts: FactsAhead,
                stderr: TextIO | None, clock: Callable[[], float]) -> SimulateReport:
    """:func:`run` once the robot is read, its model's ``facts`` being worked out."""
    from servicebot_cli.kinematics.srdf import robot_disabled_pairs
    from servicebot_cli.simulate.scenario.definition import load_scenario

    disabled = robot_disabled_pairs(request.srdf, robot)
    scenario = with_overrides(load_scenario(request.scenario_file), request.overrides)
    notes: tuple[str, ...] = ()
    if request.scenario_file is None:
        scenario, notes = default_arm_for(scenario, robot)
    problem = ""
    if request.live_window:  # the window's module brings the plot's, not needed headless
        from servicebot_cli.simulate.files.live import display_problem

        problem = display_problem()
    if problem:  # checked after the input, before any work
        raise ServicebotError(f"{problem}; use --headless (with --plot FILE.png for a picture)")
    scenario_dir = Path(request.scenario_file).parent if request.scenario_file else Path.cwd()
    report = run_and_write(robot, scenario, seed=request.seed, outputs=request.outputs,
                           scenario_dir=scenario_dir, stderr=stderr, progress=request.progress,
                           clock=clock, controllers=request.overrides.controllers_file,
                           live=request.live_window, resolver=request.robot.resolver(),
                           disabled_pairs=disabled,
                           check_points=not request.allow_collisions, facts=facts)
    unmet = tuple((e, e.value(report.summary)) for e in request.expectations
                  if not e.holds(report.summary))
    return dataclasses.replace(report, unmet=unmet, notes=(*notes, *report.notes))


def default_arm_for(scenario: Scenario,
                    robot: RobotDescription) -> tuple[Scenario, tuple[str, ...]]:
    """The built-in scenario without its arm goal when ``robot`` lacks the bundled arm's joints.

    The built-in scenario moves the bundled robot's arm; another robot is driven by the same
    ``cmd_vel`` with its joints held, and a note says so (a scenario file of its own can move
    them). Returns the scenario and the notes for stderr.
    """
    movable = {j.name for j in robot.movable_joints}
    missing = [n for n in scenario.arm.joint_names if n not in movable]
    if not missing:
        return _without_followers(scenario, robot, movable)
    from servicebot_cli.simulate.scenario.definition import ArmTrajectory

    name = robot.name or "this robot"
    note = (f"note: the built-in scenario moves the bundled robot's arm; {name} has no joint "
            f"'{missing[0]}', so its joints hold still (to move them, write a scenario from "
            "'servicebot simulate --print-scenario' and give it with -s)")
    return dataclasses.replace(scenario, arm=ArmTrajectory()), (note,)


def _without_followers(scenario: Scenario, robot: RobotDescription,
                       movable: set[str]) -> tuple[Scenario, tuple[str, ...]]:
    """The built-in scenario's arm goal without the joints ``robot`` makes mimic another.

    They follow their leader (a scenario file that commands one is refused); a note says so.
    """
    trajectory = scenario.arm
    followers = {j.name: j.mimic.joint for j in robot.joints
                 if j.mimic is not None and j.mimic.joint in movable}
    dropped = [n for n in trajectory.joint_names if n in followers]
    if not dropped:
        return scenario, ()
    from servicebot_cli.simulate.scenario.definition import TrajectoryPoint

    notes = tuple(f"note: the built-in scenario moves '{n}'; {robot.name or 'this robot'} makes "
                  f"it mimic '{followers[n]}', so it follows that joint instead" for n in dropped)
    kept = [i for i, n in enumerate(trajectory.joint_names) if n not in followers]
    if not kept:  # the built-in goal commands followers only: nothing left to move
        from servicebot_cli.simulate.scenario.definition import ArmTrajectory

        return dataclasses.replace(scenario, arm=ArmTrajectory()), notes
    points = tuple(TrajectoryPoint(p.time_from_start_s, tuple(p.positions[i] for i in kept))
                   for p in trajectory.points)
    arm = dataclasses.replace(trajectory, joint_names=tuple(trajectory.joint_names[i]
                                                            for i in kept), points=points)
    return dataclasses.replace(scenario, arm=arm), notes


def with_overrides(scenario: Scenario, overrides: Overrides) -> Scenario:
    """``scenario`` with the values of ``overrides`` that are not None in place of its own.

    Any camera value turns the camera's images on.
    """
    changes = {f.name: getattr(overrides, f.name) for f in dataclasses.fields(overrides)
               if f.name not in ("duration_s", "controllers_file")
               and not f.name.startswith("camera_") and getattr(overrides, f.name) is not None}
    controller = dataclasses.replace(scenario.controller, **changes)
    duration_s = scenario.duration_s if overrides.duration_s is None else overrides.duration_s
    camera = {name: value for name, value in (("scale", overrides.camera_scale),
                                              ("rate_hz", overrides.camera_rate_hz),
                                              ("depth", overrides.camera_depth))
              if value is not None}
    images = scenario.camera
    if camera:
        images = dataclasses.replace(images, enabled=True, from_cli=images.from_cli
                                     | frozenset(camera), **camera)  # type: ignore[arg-type]
    return dataclasses.replace(scenario, controller=controller, duration_s=duration_s,
                               controller_cli=scenario.controller_cli | frozenset(changes),
                               camera=images)


def run_and_write(robot: RobotDescription, scenario: Scenario, *, seed: int,
                  outputs: Outputs, scenario_dir: Path, stderr: TextIO | None = None,
                  progress: bool | None = None,
                  clock: Callable[[], float] = time.perf_counter,
                  controllers: str | None = None, piece_s: float | None = None,
                  keep_run: bool = False, live: bool = False,
                  resolver: PackageResolver | None = None,
                  disabled_pairs: tuple[tuple[str, str], ...] = (),
                  check_points: bool = False,
                  facts: FactsAhead | None = None) -> SimulateReport:
    """Run ``scenario`` on a loaded robot and write ``outputs``; the wall time excludes loading.

    Loading, not timed, is reading the robot, the scenario, the controllers and the modules
    the run uses, and building the robot's model when ``facts`` brings it (``load`` builds
    it before any other command's work); the wall time is the rest, to the last output.

    The controller's parameters come from the controllers file (``controllers``, else the
    one the robot names or has beside it) where the scenario does not set them. The run is
    simulated ``piece_s`` simulated seconds at a time (None: the simulator's default), or in
    one piece kept in the report with ``keep_run``; the outputs are the same bytes either way.
    ``live`` gathers the live window's track as the run goes. ``resolver`` finds the robot's
    collision meshes; ``disabled_pairs`` are never checked for self contact; with
    ``check_points`` a trajectory point in collision is refused before the run. ``facts``
    brings the robot's model facts when they are being worked out already.

    Raises:
        ServicebotError: Bad scenario for this robot, an unreadable controllers file, a
            trajectory point in collision (``check_points``), or an output that cannot be
            written.
    """
    from servicebot_cli.simulate.controllers.joint_state_topics import joint_state_topics
    from servicebot_cli.simulate.controllers.plugin_drive import controllers_for
    from servicebot_cli.simulate.controllers.resolve import resolve

    controllers_file = controllers_for(robot, controllers)
    joint_states = joint_state_topics(robot, controllers_file)
    scenario = joint_states.timed(resolve(scenario, controllers_file))
    from servicebot_cli.simulate import simulator
    from servicebot_cli.simulate.bag.ray_messages import unpublished_note
    from servicebot_cli.simulate.bag.ros_messages import odom_frames, odom_topic, publishers
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.controllers.diff_drive import tick_count
    from servicebot_cli.simulate.files.progress import Progress
    from servicebot_cli.simulate.plugin_topics import unpublished
    from servicebot_cli.simulate.world.meshes import load_meshes
    from servicebot_cli.simulate.world.solids import world_solids

    _load_modules(outputs, camera_images=scenario.camera.enabled)
    if facts is not None:  # the model, built meanwhile, is the robot's loading: not timed
        facts.result()
    start = clock()
    body = sim_robot(robot, resolver=resolver, disabled_pairs=disabled_pairs, facts=facts)
    if check_points:
        from servicebot_cli.simulate.scenario.world_check import check_arm_points

        check_arm_points(body, scenario)
    meshes = load_meshes(scenario, scenario_dir)
    piece_s = math.inf if keep_run else simulator.PIECE_S if piece_s is None else piece_s
    with contextlib.ExitStack() as stack:  # outputs go in place when it closes, unless on error
        bar = Progress(tick_count(scenario.controller, scenario.duration_s), stderr,
                       enabled=progress) if stderr is not None else None
        if bar:  # an error line, or Ctrl-C's, starts on a clean line
            stack.callback(bar.close)
        pieces = simulator.pieces(body, scenario, seed=seed, solids=world_solids(scenario.world),
                                  meshes=meshes, piece_s=piece_s, facts=facts)
        stack.enter_context(contextlib.closing(pieces))  # its worker stopped whatever happens
        topic = odom_topic(controllers_file)
        tf_topic = controllers_file.tf_topic or "/tf"
        odometry_on = [*filter(None, (topic,)), *((tf_topic,) if controllers_file.odom_tf else ())]
        sources = publishers(body, scenario.camera, topic, controllers_file.odom_tf,
                             odom_frames(controllers_file, body), joint_states.topics,
                             controllers_file.wheel_tf_joints, tf_topic)
        left_out = unpublished(robot, {source.topic for source in sources})
        summary, last, writers = _write_pieces(
            joint_states.narrowed(pieces), outputs, sources, stack,
            bar.advance if bar else None, live, odometry_on)
    track = None
    if live:
        from servicebot_cli.simulate.files.live import LiveWriter

        track = next(w.track for w in writers if isinstance(w, LiveWriter))
    notes = (*controllers_file.notes, *joint_states.notes,
             *(f"note: the simulator's collision shape of link {skipped}"
               for skipped in body.shape.skipped),
             *filter(None, (unpublished_note(mounted.spec) for mounted in body.ray_sensors)),
             *body.sensor_notes, *left_out)
    return SimulateReport(summary, clock() - start, last if keep_run else None,
                          live_track=track, notes=notes)


def _load_modules(outputs: Outputs, *, camera_images: bool) -> None:
    """Import the modules the run will use: the summary's, the writers', the camera's.

    The writers are those ``outputs`` asks for; the camera's compiled renderer (numba, about
    0.3 s) comes with ``camera_images``. Importing is loading, which the run's wall time
    leaves out as it leaves out the robot's.
    """
    import importlib

    names = ["servicebot_cli.simulate.summary"]
    if outputs.bag is not None:
        names += ["servicebot_cli.simulate.bag.rosbag", "zstandard"]
    if outputs.out_dir is not None:
        names.append("servicebot_cli.simulate.files.csv_out")
    for name in names:
        importlib.import_module(name)
    if camera_images:
        from servicebot_cli.simulate.sensors.camera_image import load_renderer

        load_renderer()


def _write_pieces(pieces: Iterator[SimResult], outputs: Outputs, sources: list[Publisher],
                  stack: contextlib.ExitStack, advance: Callable[[int], None] | None,
                  live: bool = False, odometry_on: Sequence[str] = ()
                  ) -> tuple[Summary, SimResult, list[Writer]]:
    """Give each piece to the summary and to every writer (``live``: the live window's too).

    ``odometry_on``: where the base's controller publishes odometry (a topic, /tf).

    Returns the summary, the last piece and the writers.

    The writers begin with the first piece, which comes once the scenario is checked.
    """
    from servicebot_cli.simulate.summary import Summarizer

    summarizer = Summarizer(sources, odometry_on)
    writers: list[Writer] | None = None
    for piece in pieces:
        if writers is None:
            writers = _writers(outputs, piece, sources, stack, live)
        summarizer.add(piece)
        for writer in writers:
            writer.add(piece)
        if advance:
            advance(piece.plan.ticks)
    summary = summarizer.summary()
    for writer in writers or []:
        writer.finish(summary)
    return summary, piece, writers or []


class Writer(Protocol):
    """An output written as the run's pieces come."""

    def add(self, piece: SimResult) -> None:
        """Write what comes from the next piece of the run."""

    def finish(self, summary: Summary) -> None:
        """Write what needs the whole run (its files go in place when the stack closes)."""


def _writers(outputs: Outputs, first: SimResult, sources: list[Publisher],
             stack: contextlib.ExitStack, live: bool = False) -> list[Writer]:
    """The writers ``outputs`` asks for, begun on ``stack``, for a run starting with ``first``.

    With ``live``, the live window's track is gathered too.
    """
    writers: list[Writer] = []
    if live:
        from servicebot_cli.simulate.files.live import LiveWriter

        writers.append(LiveWriter(first))
    if outputs.bag is not None:
        from servicebot_cli.simulate.bag.rosbag import BagWriter

        writers.append(BagWriter(outputs.bag, sources, stack))
    if outputs.out_dir is not None:
        from servicebot_cli.simulate.files.csv_out import CsvWriter

        writers.append(CsvWriter(outputs.out_dir, stack))
    if outputs.plot is not None:
        from servicebot_cli.simulate.files.plot import PlotWriter

        writers.append(PlotWriter(outputs.plot, first))
    return writers
