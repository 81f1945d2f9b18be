"""What a simulation run does: duration, start pose, commands, arm motion, world.

A scenario is a YAML or JSON file; every field is documented in README.md (section
``simulate``) and checked here, and a bad field is reported with its file, line and name.
Without a file, the built-in ``default_scenario.yaml`` beside this module is used.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from pathlib import Path as FsPath
from typing import TYPE_CHECKING

from servicebot_cli.common.inputs import read_input_text
from servicebot_cli.simulate.scenario.camera import CameraImages, read_camera
from servicebot_cli.simulate.scenario.colour import Color, read_color
from servicebot_cli.simulate.scenario.located import Located, Path, ScenarioError, parse
from servicebot_cli.simulate.scenario.schema import Reader

if TYPE_CHECKING:
    from servicebot_cli.simulate.controllers.classic_drive import ClassicDrive

DEFAULT_SCENARIO = FsPath(__file__).with_name("default_scenario.yaml")
SATURATIONS = ("keep-curvature", "per-wheel")
MAX_SCENARIO_BYTES = 10_000_000
MAX_DURATION_S = 24 * 3600.0


@dataclass(frozen=True)
class Pose2D:
    """A pose on the floor: position [m] and heading [rad] in the world frame."""

    x_m: float = 0.0
    y_m: float = 0.0
    yaw_rad: float = 0.0


@dataclass(frozen=True)
class Controller:
    """diff_drive_controller parameters (its names, with units); infinite: no limit.

    ``min_*`` limits are negative (a minimum acceleration of -0.05 brakes at 0.05 m/s^2);
    the covariance diagonals go into every Odometry message. ``wheel_separation_m`` and
    ``wheel_radius_m`` are the controller's (None: the URDF's); it turns commands into wheel
    speeds and wheel turns into odometry with them, while the robot moves as its URDF wheels
    carry it.
    """

    update_rate_hz: float = 100.0
    publish_rate_hz: float = 50.0
    cmd_vel_timeout_s: float = 0.5
    wheel_separation_m: float | None = None
    wheel_radius_m: float | None = None
    wheel_separation_multiplier: float = 1.0
    left_wheel_radius_multiplier: float = 1.0
    right_wheel_radius_multiplier: float = 1.0
    saturation: str = "keep-curvature"
    max_linear_velocity_m_s: float = math.inf
    min_linear_velocity_m_s: float = -math.inf
    max_linear_acceleration_m_s2: float = math.inf
    min_linear_acceleration_m_s2: float = -math.inf
    max_linear_jerk_m_s3: float = math.inf
    min_linear_jerk_m_s3: float = -math.inf
    max_angular_velocity_rad_s: float = math.inf
    min_angular_velocity_rad_s: float = -math.inf
    max_angular_acceleration_rad_s2: float = math.inf
    min_angular_acceleration_rad_s2: float = -math.inf
    max_angular_jerk_rad_s3: float = math.inf
    min_angular_jerk_rad_s3: float = -math.inf
    pose_covariance_diagonal: tuple[float, ...] = (0.0,) * 6
    twist_covariance_diagonal: tuple[float, ...] = (0.0,) * 6


@dataclass(frozen=True)
class Slip:
    """How the floor departs from ideal rolling (ground truth only; odometry does not know).

    Attributes:
        track_factor: Effective track / geometric track; above 1 for skid-steer turning.
        longitudinal: Fraction of wheel surface speed lost to slip, in [0, 1).
    """

    track_factor: float = 1.0
    longitudinal: float = 0.0


@dataclass(frozen=True)
class CmdVel:
    """A ``cmd_vel`` Twist published continuously from ``start_s`` for ``duration_s``."""

    start_s: float
    duration_s: float
    linear_m_s: float
    angular_rad_s: float

    @property
    def end_s(self) -> float:
        """When the last message of this segment is sent [s]."""
        return self.start_s + self.duration_s


@dataclass(frozen=True)
class TrajectoryPoint:
    """A ``trajectory_msgs/JointTrajectoryPoint``: positions [rad] reached at a time [s]."""

    time_from_start_s: float
    positions: tuple[float, ...]


@dataclass(frozen=True)
class ArmTrajectory:
    """A ``joint_trajectory`` goal sent at ``start_s``."""

    joint_names: tuple[str, ...] = ()
    points: tuple[TrajectoryPoint, ...] = ()
    start_s: float = 0.0


@dataclass(frozen=True)
class Wall:
    """A wall from ``from_m`` to ``to_m`` on the floor."""

    from_m: tuple[float, float]
    to_m: tuple[float, float]
    thickness_m: float
    height_m: float
    color: Color | None = None


@dataclass(frozen=True)
class Box:
    """A box standing on the floor (or at ``center_m[2]``), turned by ``yaw_rad``."""

    center_m: tuple[float, float, float]
    size_m: tuple[float, float, float]
    yaw_rad: float
    color: Color | None = None


@dataclass(frozen=True)
class Cylinder:
    """A vertical cylinder standing on the floor."""

    center_m: tuple[float, float]
    radius_m: float
    height_m: float
    color: Color | None = None


@dataclass(frozen=True)
class MeshObstacle:
    """A mesh file (STL, OBJ, PLY, ...) placed in the world."""

    file: str
    xyz_m: tuple[float, float, float]
    rpy_rad: tuple[float, float, float]
    scale: float
    color: Color | None = None


@dataclass(frozen=True)
class World:
    """Obstacles; the floor is the plane z = 0 (``floor_color``: None, the camera's checker)."""

    walls: tuple[Wall, ...] = ()
    boxes: tuple[Box, ...] = ()
    cylinders: tuple[Cylinder, ...] = ()
    meshes: tuple[MeshObstacle, ...] = ()
    floor_color: Color | None = None


@dataclass(frozen=True)
class Rates:
    """Publishing rates of streams the URDF's sensors do not set [Hz]."""

    joint_states_hz: float = 50.0


@dataclass(frozen=True)
class Scenario:
    """A whole run. ``source`` remembers where each field was written, for later errors."""

    duration_s: float
    initial_pose: Pose2D = Pose2D()
    controller: Controller = Controller()
    slip: Slip = Slip()
    cmd_vel: tuple[CmdVel, ...] = ()
    arm: ArmTrajectory = ArmTrajectory()
    world: World = World()
    rates: Rates = Rates()
    camera: CameraImages = CameraImages()
    name: str = "scenario"
    source: Located | None = field(default=None, repr=False, compare=False)
    controller_given: frozenset[str] = frozenset()
    """The controller fields the scenario file sets (they override the controllers file)."""
    controller_cli: frozenset[str] = frozenset()
    """The controller fields the command line sets (they override the scenario)."""
    controller_from: tuple[tuple[str, str], ...] = ()
    """Each controller field and where its value came from, once resolved."""
    speed_limiter: str = "diff_drive_controller"
    """Whose speed limiter the base runs (``gz-math`` under gz-sim's DiffDrive), once resolved."""
    classic_drive: ClassicDrive | None = None
    """Gazebo Classic's diff-drive plugin, when it drives the base, once resolved."""


def load_scenario(path: str | FsPath | None) -> Scenario:
    """Read and check a scenario file (``.json`` is JSON, anything else YAML).

    Raises:
        ScenarioError: Unreadable, not well-formed, or a bad field (with file and line).
    """
    file = DEFAULT_SCENARIO if path is None else FsPath(path)
    display = "default scenario" if path is None else str(path)
    text = read_input_text(str(file), kind="a YAML or JSON scenario, or none for the built-in "
                           "one", error=ScenarioError, max_bytes=MAX_SCENARIO_BYTES)
    located = parse(text, display, json_syntax=file.suffix.lower() == ".json")
    if located.value in (None, {}):
        raise ScenarioError(f"{display}: holds no scenario (it is empty, or only comments); "
                            "start from 'servicebot simulate --print-scenario'")
    return read_scenario(located, name="default" if path is None else file.stem)


_TOP = ("duration_s", "initial_pose", "controller", "slip", "cmd_vel", "arm", "world", "rates",
        "camera")


def read_scenario(located: Located, name: str = "scenario", *,
                  cut_short: bool = False) -> Scenario:
    """The scenario in a parsed document.

    Args:
        located: The document.
        name: The scenario's name in messages and the summary.
        cut_short: ``duration_s`` was set from outside (a sweep, as ``--duration-s``) to
            stop the run early: commands after it are expected, not a mistake.

    Raises:
        ScenarioError: The first bad field, with its line.
    """
    r = Reader(located)
    r.mapping((), _TOP, required=("duration_s",))
    duration = r.number(("duration_s",), positive=True, maximum=MAX_DURATION_S)
    world = _world(r, ("world",))
    scenario = Scenario(
        duration_s=duration,
        initial_pose=_pose(r, ("initial_pose",)),
        controller=_controller(r, ("controller",)),
        controller_given=_keys(r, ("controller",)),
        slip=_slip(r, ("slip",)),
        cmd_vel=_cmd_vel(r, ("cmd_vel",)),
        arm=_arm(r, ("arm",)),
        world=world,
        rates=_rates(r, ("rates",)),
        camera=dataclasses.replace(read_camera(r, ("camera",)), floor_color=world.floor_color,
                                   mesh_colors=tuple(m.color for m in world.meshes)),
        name=name,
        source=located,
    )
    _refuse_what_cannot_be_meant(r, scenario, cut_short=cut_short)
    return scenario


def _refuse_what_cannot_be_meant(r: Reader, scenario: Scenario, *, cut_short: bool) -> None:
    """Refuse commands that would never be sent and rates the control loop cannot keep.

    A command that starts at or after ``duration_s`` is never sent (a typo in one of the two
    numbers, most likely); a stream published faster than the control ticks would repeat
    the same state.
    """
    end = math.inf if cut_short else scenario.duration_s
    for i, segment in enumerate(scenario.cmd_vel):
        if segment.start_s >= end:
            raise r.error(("cmd_vel", i, "start_s"), f"starts at {segment.start_s:g} s, when "
                          f"the run has ended (duration_s: {end:g}); it would never be sent")
    arm = scenario.arm
    if arm.points and arm.start_s >= end:
        raise r.error(("arm", "start_s"), f"the goal is sent at {arm.start_s:g} s, when the "
                      f"run has ended (duration_s: {end:g})")
    for i, point in enumerate(arm.points):
        if arm.start_s + point.time_from_start_s > end:
            raise r.error(("arm", "points", i, "time_from_start_s"),
                          f"reached at {arm.start_s + point.time_from_start_s:g} s, after the "
                          f"run ends (duration_s: {end:g})")
    control_hz = scenario.controller.update_rate_hz
    rates = (((("controller", "publish_rate_hz"), scenario.controller.publish_rate_hz)),
             (("rates", "joint_states_hz"), scenario.rates.joint_states_hz))
    for path, rate_hz in rates:
        if rate_hz > control_hz + 1e-9 and r.has(path):
            raise r.error(path, f"{rate_hz:g} Hz is above the control rate "
                          f"(controller.update_rate_hz: {control_hz:g} Hz); a stream cannot "
                          "be published faster than the simulation steps")


def _pose(r: Reader, path: Path) -> Pose2D:
    if not r.has(path):
        return Pose2D()
    r.mapping(path, ("x_m", "y_m", "yaw_rad"))
    return Pose2D(r.number((*path, "x_m"), 0.0), r.number((*path, "y_m"), 0.0),
                  r.number((*path, "yaw_rad"), 0.0))


def _controller(r: Reader, path: Path) -> Controller:
    if not r.has(path):
        return Controller()
    names = [f for f in Controller.__dataclass_fields__]
    r.mapping(path, names)
    d = Controller()
    values: dict[str, object] = {}
    for name in names:
        where = (*path, name)
        if not r.has(where):
            continue
        if name == "saturation":
            values[name] = r.string(where, d.saturation, SATURATIONS)
        elif name.endswith("_diagonal"):
            values[name] = tuple(r.number((*where, i), minimum=0.0)
                                 for i in range(len(r.vector(where, 6))))
        elif name.startswith("min_"):
            values[name] = r.number(where, maximum=0.0)
        elif name.endswith("_rate_hz"):
            values[name] = r.number(where, positive=True, maximum=10_000.0)
        else:
            values[name] = r.number(where, positive=True)
    return dataclasses.replace(d, **values)  # type: ignore[arg-type]  # checked per field


def _keys(r: Reader, path: Path) -> frozenset[str]:
    """The keys of the mapping at ``path`` (none when absent)."""
    value = r.get(path) if r.has(path) else None
    return frozenset(value) if isinstance(value, dict) else frozenset()


def _slip(r: Reader, path: Path) -> Slip:
    if not r.has(path):
        return Slip()
    r.mapping(path, ("track_factor", "longitudinal"))
    return Slip(r.number((*path, "track_factor"), 1.0, positive=True),
                r.number((*path, "longitudinal"), 0.0, minimum=0.0, maximum=0.99))


def _cmd_vel(r: Reader, path: Path) -> tuple[CmdVel, ...]:
    segments: list[CmdVel] = []

    def read(p: Path) -> CmdVel:
        r.mapping(p, ("start_s", "duration_s", "linear_m_s", "angular_rad_s"),
                  required=("duration_s",))
        previous_end = segments[-1].end_s if segments else 0.0
        start = r.number((*p, "start_s"), previous_end, minimum=0.0)
        if start < previous_end - 1e-9:
            raise r.error((*p, "start_s"), f"{start:g} s is before the previous segment ends "
                          f"({previous_end:g} s); segments must not overlap")
        segment = CmdVel(start, r.number((*p, "duration_s"), positive=True),
                         r.number((*p, "linear_m_s"), 0.0), r.number((*p, "angular_rad_s"), 0.0))
        segments.append(segment)
        return segment

    return r.items(path, read)


def _arm(r: Reader, path: Path) -> ArmTrajectory:
    if not r.has(path):
        return ArmTrajectory()
    r.mapping(path, ("joint_names", "points", "start_s"), required=("joint_names", "points"))
    names = r.items((*path, "joint_names"), lambda p: r.string(p))
    if len(set(names)) != len(names):
        raise r.error((*path, "joint_names"), "a joint is named twice")
    times: list[float] = []

    def point(p: Path) -> TrajectoryPoint:
        r.mapping(p, ("time_from_start_s", "positions"), required=("time_from_start_s",
                                                                   "positions"))
        t = r.number((*p, "time_from_start_s"), minimum=0.0)
        if times and t <= times[-1]:
            raise r.error((*p, "time_from_start_s"), f"{t:g} s is not after the previous "
                          f"point's {times[-1]:g} s; points must be in time order")
        times.append(t)
        return TrajectoryPoint(t, r.vector((*p, "positions"), len(names)))

    return ArmTrajectory(names, r.items((*path, "points"), point),
                         r.number((*path, "start_s"), 0.0, minimum=0.0))


def _world(r: Reader, path: Path) -> World:
    if not r.has(path):
        return World()
    r.mapping(path, ("walls", "boxes", "cylinders", "meshes", "floor"))

    def wall(p: Path) -> Wall:
        r.mapping(p, ("from_m", "to_m", "thickness_m", "height_m", "color"),
                  required=("from_m", "to_m"))
        start, end = r.pair((*p, "from_m")), r.pair((*p, "to_m"))
        if start == end:
            raise r.error((*p, "to_m"), "a wall needs two different ends")
        return Wall(start, end, r.number((*p, "thickness_m"), 0.1, positive=True),
                    r.number((*p, "height_m"), 1.0, positive=True), read_color(r, (*p, "color")))

    def box(p: Path) -> Box:
        r.mapping(p, ("center_m", "size_m", "yaw_rad", "color"), required=("center_m", "size_m"))
        size = r.triple((*p, "size_m"))
        if min(size) <= 0:
            raise r.error((*p, "size_m"), "sizes must be positive")
        centre = r.vector((*p, "center_m"), (2, 3))
        z = centre[2] if len(centre) == 3 else size[2] / 2.0
        return Box((centre[0], centre[1], z), size, r.number((*p, "yaw_rad"), 0.0),
                   read_color(r, (*p, "color")))

    def cylinder(p: Path) -> Cylinder:
        r.mapping(p, ("center_m", "radius_m", "height_m", "color"),
                  required=("center_m", "radius_m"))
        return Cylinder(r.pair((*p, "center_m")), r.number((*p, "radius_m"), positive=True),
                        r.number((*p, "height_m"), 1.0, positive=True),
                        read_color(r, (*p, "color")))

    def mesh(p: Path) -> MeshObstacle:
        r.mapping(p, ("file", "xyz_m", "rpy_rad", "scale", "color"), required=("file",))
        return MeshObstacle(r.string((*p, "file")), r.triple((*p, "xyz_m"), (0, 0, 0)),
                            r.triple((*p, "rpy_rad"), (0, 0, 0)),
                            r.number((*p, "scale"), 1.0, positive=True),
                            read_color(r, (*p, "color")))

    floor = (*path, "floor")
    if r.has(floor):
        r.mapping(floor, ("color",))
    return World(r.items((*path, "walls"), wall), r.items((*path, "boxes"), box),
                 r.items((*path, "cylinders"), cylinder), r.items((*path, "meshes"), mesh),
                 read_color(r, (*floor, "color")) if r.has(floor) else None)


def _rates(r: Reader, path: Path) -> Rates:
    if not r.has(path):
        return Rates()
    r.mapping(path, ("joint_states_hz",))
    return Rates(r.number((*path, "joint_states_hz"), 50.0, positive=True, maximum=10_000.0))
