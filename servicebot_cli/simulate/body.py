"""The robot as the simulator needs it, read from the URDF through the shared model.

Wheels, radius and track come from :func:`drive_geometry`; sensor specs from the Gazebo
``<sensor>`` blocks; where each sensor sits on the base from Pinocchio's frame placements in
one configuration of the whole robot (planar base); the robot's shape from the collision
shapes of every link. Nothing is a constant of the bundled robot.
"""

from __future__ import annotations

import contextlib
import functools
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Generic, TypeVar

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.model_plugins import model_imu
from servicebot_cli.description.ray_output import LASER_SCAN
from servicebot_cli.description.sensors import (
    CAMERA_TYPES,
    LIDAR_TYPES,
    CameraSpec,
    ImuSpec,
    LidarSpec,
    camera_spec,
    imu_spec,
    lidar_spec,
)
from servicebot_cli.kinematics.drive_geometry import DriveGeometry, drive_geometry
from servicebot_cli.kinematics.mesh_wheels import file_points
from servicebot_cli.kinematics.mimics import Mimics
from servicebot_cli.kinematics.running_gear import chassis_joints
from servicebot_cli.kinematics.steering import refuse_steered_wheels
from servicebot_cli.kinematics.transforms import pose_matrix
from servicebot_cli.simulate.model_facts import FactsAhead, description_first
from servicebot_cli.simulate.sensors.lidar import cast_problem
from servicebot_cli.simulate.shape import RobotShape, robot_shape

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.extensions import Sensor
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
SpecT = TypeVar("SpecT", LidarSpec, ImuSpec, CameraSpec)
Placement = Callable[[str], FloatArray]
"""A link's name to ``transform_link_to_base`` (4, 4) with the base at the origin."""


@dataclass(frozen=True)
class Mounted(Generic[SpecT]):
    """A sensor and where it sits: ``transform_sensor_to_base`` (4, 4), its link, its name.

    The name is the URDF's ``<sensor name>`` (empty for a model plugin's IMU).
    """

    spec: SpecT
    transform_sensor_to_base: FloatArray
    link: str = ""
    name: str = ""


@dataclass(frozen=True, eq=False)
class SimRobot:
    """Everything the simulator reads from the robot description.

    Attributes:
        robot: The shared description.
        geometry: Wheels, radius, track, velocity limits.
        joint_space: Movable joints of the planar-base model (one Pinocchio configuration).
        arm_joints: Movable joints that are neither drive wheels nor running gear (casters,
            suspensions, wheel drops: ``inspect``'s chassis), URDF order.
        base_height_m: Height of the root link's origin above the floor (wheels touching it).
        shape: Every link's collision parts, posed by the arm joints.
        ray_sensors: Every published ray sensor (LIDARs, sonars, cliff and IR range
            sensors), the one with the most rays first (the LIDAR), then in URDF order.
        imu, camera: Mounted sensors, None where the URDF has none.
        sensor_notes: A stderr note for each published sensor left out, and why: a ray
            sensor it cannot cast, a camera it cannot image, a second IMU or camera, a
            sensor on a link the robot lacks.
        camera_left_out: Why the published camera is not simulated (camera images asked
            for say so); None where it is, or there is none.
        disabled_pairs: Link pairs the self-contact check leaves out (an SRDF's
            ``<disable_collisions>``, as ``ik --srdf``).
        resolver: Finds the ``package://`` collision meshes (the shape's and the self-contact
            check's); None: the environment's and the file's workspace.
    """

    robot: RobotDescription
    geometry: DriveGeometry
    joint_space: JointSpace
    arm_joints: tuple[str, ...]
    base_height_m: float
    shape: RobotShape
    ray_sensors: tuple[Mounted[LidarSpec], ...]
    imu: Mounted[ImuSpec] | None
    camera: Mounted[CameraSpec] | None
    sensor_notes: tuple[str, ...] = ()
    camera_left_out: str | None = None
    disabled_pairs: tuple[tuple[str, str], ...] = ()
    resolver: PackageResolver | None = None

    @property
    def root_link(self) -> str:
        """The base frame's name."""
        return self.robot.root_link or "base_link"

    @functools.cached_property
    def arm_mimics(self) -> Mimics:
        """The arm's ``<mimic>`` joints, as columns of :attr:`arm_joints`."""
        return Mimics.among(self.robot.joints, self.arm_joints)

    @functools.cached_property
    def joint_mimics(self) -> Mimics:
        """Every ``<mimic>`` joint, as columns of the joint space's names (wheels' too)."""
        return Mimics.among(self.robot.joints, self.joint_space.names)


def sim_robot(robot: RobotDescription, *, resolver: PackageResolver | None = None,
              disabled_pairs: Sequence[tuple[str, str]] = (),
              facts: FactsAhead | None = None) -> SimRobot:
    """Read what the simulator needs from ``robot``.

    ``resolver`` finds ``package://`` collision meshes (default: the environment's and the
    file's workspace); ``disabled_pairs`` are left out of the self-contact check; ``facts``
    brings the model's facts when they are being worked out already (else they are now).

    Raises:
        DescriptionError: Pinocchio cannot build the description, not a differential drive
            (steered wheels too), or no collision shape on the base.
    """
    with FactsAhead(robot) if facts is None else contextlib.nullcontext(facts) as ahead:
        with description_first(ahead):
            geometry = drive_geometry(robot, file_points(resolver, robot.path.parent))
            refuse_steered_wheels(robot)
        gear = {w.joint for w in geometry.wheels}
        gear.update(chassis_joints(robot, [w.joint for w in geometry.wheels]))
        space = ahead.result().joint_space
        arm_joints = tuple(n for n in space.names if n not in gear)
        with description_first(ahead):
            shape = _shape(robot, arm_joints, resolver)
        placements = ahead.result().placements
    height = float(np.mean([w.radius_m - w.position_m[2] for w in geometry.wheels]))

    def placement(link: str) -> FloatArray:
        return placements[link]

    rays, ray_notes = _castable_rays(robot)
    camera, left_out = _imaged_camera(robot, placement)
    return SimRobot(
        robot=robot, geometry=geometry, joint_space=space,
        arm_joints=arm_joints,
        base_height_m=height,
        shape=shape,
        ray_sensors=tuple(_placed(robot, sensor, spec, placement) for sensor, spec in rays),
        imu=_mount(robot, ("imu",), _published_imu, placement) or _model_imu(robot, placement),
        camera=camera,
        sensor_notes=(*_unplaced(robot), *ray_notes,
                      *((f"note: {left_out}; its topics are left out",) if left_out else ()),
                      *_beyond_the_first(robot)),
        camera_left_out=left_out,
        disabled_pairs=tuple(disabled_pairs),
        resolver=resolver,
    )


def _mount(robot: RobotDescription, types: tuple[str, ...],
           read: Callable[[Sensor], SpecT | None], placement: Placement) -> Mounted[SpecT] | None:
    """The first published sensor of ``types``, None without one.

    ``read`` gives a sensor's spec, None when nothing publishes it on ROS.
    """
    found = next(_published(robot, types, read), None)
    return _placed(robot, *found, placement) if found else None


def _imaged_camera(robot: RobotDescription, placement: Placement
                   ) -> tuple[Mounted[CameraSpec] | None, str | None]:
    """The first published camera, or why its image cannot be made.

    Such a camera is left out, as a ray sensor the simulator cannot cast is.
    """
    mounted = _mount(robot, CAMERA_TYPES, _published_camera, placement)
    if mounted is None:
        return None, None
    from servicebot_cli.simulate.sensors.camera_info import intrinsics

    try:
        intrinsics(mounted.spec)
    except DescriptionError as exc:
        return None, (f"camera '{mounted.name}' on {mounted.link} of {robot.display} is not "
                      f"simulated: {exc}")
    return mounted, None


def _castable_rays(robot: RobotDescription
                   ) -> tuple[list[tuple[Sensor, LidarSpec]], tuple[str, ...]]:
    """The published ray sensors the simulator casts, and a note for each it leaves out.

    The one with the most rays comes first, then the others in URDF order: a Create 3 base
    (TurtleBot 4) declares one-ray cliff and IR sensors before its LIDAR, which keeps the
    noise stream and the ``scan.csv`` it always had. Left out: rays it cannot cast, or a
    topic another of them publishes in another message type (one topic holds one type in a
    bag).
    """
    cast: list[tuple[Sensor, LidarSpec]] = []
    notes: list[str] = []
    for sensor, spec in _published(robot, LIDAR_TYPES, _published_lidar):
        problem = cast_problem(spec)
        if problem is None:
            cast.append((sensor, spec))
        else:
            notes.append(_left_out(sensor, spec, problem))
    cast.sort(key=lambda f: -(f[1].samples or 0))  # stable: URDF order among equals
    types: dict[str | None, tuple[str, str]] = {}
    kept = []
    for sensor, spec in cast:
        message = spec.output.message if spec.output else LASER_SCAN
        first = types.setdefault(spec.topic, (message, sensor.name or ""))
        if first[0] == message:
            kept.append((sensor, spec))
            continue
        notes.append(_left_out(sensor, spec, (
            f"ray sensor '{first[1]}' publishes {first[0].replace('/msg/', '/')} on that "
            f"topic, and this one {message.replace('/msg/', '/')}; give one of them its own "
            "topic")))
    return kept, tuple(notes)


def _beyond_the_first(robot: RobotDescription) -> Iterator[str]:
    """A stderr note for each published IMU or camera after the first, which alone is run."""
    published = {"IMU": [s for s, _ in _published(robot, ("imu",), _published_imu)],
                 "camera": [s for s, _ in _published(robot, CAMERA_TYPES, _published_camera)]}
    for kind, sensors in published.items():
        for sensor in sensors[1:]:
            yield (f"note: {kind} '{sensor.name}' is not simulated: simulate runs one "
                   f"{kind}, the first ('{sensors[0].name}')")


def _left_out(sensor: Sensor, spec: LidarSpec, why: str) -> str:
    """The stderr note for ray sensor ``sensor`` left out of the run, and ``why``."""
    return f"note: /{(spec.topic or '').lstrip('/')} (ray sensor '{sensor.name}') is not " \
        f"simulated: {why}"


def _published(robot: RobotDescription, types: tuple[str, ...],
               read: Callable[[Sensor], SpecT | None]) -> Iterator[tuple[Sensor, SpecT]]:
    """Each sensor of ``types`` on a link of the robot that ``read`` says publishes, and its spec.

    One on a link the robot lacks is no sensor Gazebo makes (see :func:`_unplaced`).
    """
    links = {link.name for link in robot.links}
    return ((s, spec) for s in robot.sensors if s.type in types and s.reference in links
            for spec in [read(s)] if spec is not None)


def _unplaced(robot: RobotDescription) -> tuple[str, ...]:
    """A stderr note for each sensor whose ``<gazebo reference>`` names no link or joint.

    A force-torque sensor sits on a joint; the simulator makes none of those either, and
    says nothing of them.

    sdformat applies a ``<gazebo reference>`` block to the link it names and drops the rest,
    so Gazebo makes no such sensor: interbotix's locobot puts its Create 3 cliff sensors
    under ``cliff_side_left`` where the link is ``locobot/cliff_side_left``.
    """
    parts = robot.part_names
    return tuple(f"note: sensor '{s.name}' is not simulated: its <gazebo reference="
                 f"\"{s.reference}\"> names no link or joint, so Gazebo drops it"
                 if s.reference else
                 f"note: sensor '{s.name}' is not simulated: its <gazebo> block names no link, "
                 "and Gazebo makes no sensor of the model's"
                 for s in robot.sensors if not s.reference or s.reference not in parts)


def _placed(robot: RobotDescription, sensor: Sensor, spec: SpecT,
            placement: Placement) -> Mounted[SpecT]:
    """``sensor`` at its pose on its link.

    Raises:
        DescriptionError: Its link is not in the robot.
    """
    assert sensor.reference is not None  # _published keeps sensors on a link only
    robot.require_frame(sensor.reference)
    return Mounted(spec, placement(sensor.reference) @ pose_matrix(sensor.pose), sensor.reference,
                   sensor.name or "")


def _published_lidar(sensor: Sensor) -> LidarSpec | None:
    """A ray sensor's spec if it publishes (a Gazebo ROS plugin or gz-sim's ``<topic>``).

    Gazebo Classic publishes a ray sensor on ROS only through a ROS plugin (gazebo_ros_pkgs'
    ``gazebo_ros_ray_sensor``); a kobuki's cliff sensor, with none, publishes nothing.
    """
    spec = lidar_spec(sensor)
    return spec if spec.topic is not None else None


def _published_camera(sensor: Sensor) -> CameraSpec | None:
    """A camera's spec if it publishes: a ``gazebo_ros_camera`` plugin or gz-sim's ``<topic>``."""
    spec = camera_spec(sensor)
    return spec if spec.image_topic is not None or spec.info_topic is not None else None


def _published_imu(sensor: Sensor) -> ImuSpec | None:
    """An IMU sensor's spec if it publishes: its own ROS plugin or gz-sim's ``<topic>``.

    Gazebo Classic publishes nothing on ROS for an IMU sensor without a plugin.
    """
    spec = imu_spec(sensor)
    return spec if spec.topic is not None else None


def _model_imu(robot: RobotDescription, placement: Placement) -> Mounted[ImuSpec] | None:
    """The first ROS 1 ``gazebo_ros_imu`` model plugin's IMU, at its ``<bodyName>`` link.

    The plugin measures its link itself (TurtleBot3's ``imu_link``), sensor or not; a link
    that is not in the model stops it (nothing is published).
    """
    links = {link.name for link in robot.links}
    found = next((found for plugin in robot.model_plugins for found in [model_imu(plugin)]
                  if found and found[0] in links), None)
    if found is None:
        return None
    link, spec = found
    return Mounted(spec, placement(link), link)


def _shape(robot: RobotDescription, arm_joints: tuple[str, ...],
           resolver: PackageResolver | None) -> RobotShape:
    reader = None
    if resolver is not None:
        from servicebot_cli.simulate.world.meshes import link_mesh_reader

        reader = link_mesh_reader(resolver, robot.path.parent)
    shape = robot_shape(robot, arm_joints, reader)
    if not shape.fixed().any():
        skipped = next((s for s in shape.skipped if s.startswith(f"{shape.root}:")), None)
        raise DescriptionError(
            f"{robot.display}: the base has no collision shape the simulator can use"
            + (f" ({skipped})" if skipped else "")
            + ", so it cannot tell where it would touch obstacles; add a <collision> box, "
            f"cylinder, sphere or readable mesh to {robot.root_link}"
        )
    return shape


def movable_joints(robot: RobotDescription, names: tuple[str, ...]) -> list[Joint]:
    """The URDF joints called ``names``, in that order."""
    return [robot.joint(n) for n in names]
