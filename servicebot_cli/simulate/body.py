"""The robot as the simulator needs it, read from the URDF through the shared model.

Wheels, radius and track come from :func:`drive_geometry`; sensor specs from the Gazebo
``<sensor>`` blocks; where each sensor sits on the base from Pinocchio's frame placements in
one configuration of the whole robot (planar base); the footprint from the collision shapes
of everything that moves with the base. Nothing is a constant of the bundled robot.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Generic, TypeVar

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.joint_space import JointSpace
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
from servicebot_cli.kinematics.transforms import pose_matrix
from servicebot_cli.simulate.world.solids import Footprint

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.elements import Geometry, Joint
    from servicebot_cli.description.extensions import Sensor
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
SpecT = TypeVar("SpecT", LidarSpec, ImuSpec, CameraSpec)
Placement = Callable[[str], FloatArray]
"""A link's name to ``transform_link_to_base`` (4, 4) with the base at the origin."""


@dataclass(frozen=True)
class Mounted(Generic[SpecT]):
    """A sensor and where it sits: ``transform_sensor_to_base`` (4, 4) at floor height 0."""

    spec: SpecT
    transform_sensor_to_base: FloatArray


@dataclass(frozen=True, eq=False)
class SimRobot:
    """Everything the simulator reads from the robot description.

    Attributes:
        robot: The shared description.
        geometry: Wheels, radius, track, velocity limits.
        joint_space: Movable joints of the planar-base model (one Pinocchio configuration).
        arm_joints: Movable joints that are not wheels, URDF order.
        base_height_m: Height of the root link's origin above the floor (wheels touching it).
        footprint: Outline of everything that moves with the base.
        lidar, imu, camera: Mounted sensors, None where the URDF has none.
    """

    robot: RobotDescription
    geometry: DriveGeometry
    joint_space: JointSpace
    arm_joints: tuple[str, ...]
    base_height_m: float
    footprint: Footprint
    lidar: Mounted[LidarSpec] | None
    imu: Mounted[ImuSpec] | None
    camera: Mounted[CameraSpec] | None

    @property
    def root_link(self) -> str:
        """The base frame's name."""
        return self.robot.root_link or "base_link"

    @property
    def model(self) -> pin.Model:
        """The planar-base Pinocchio model."""
        return self.robot.model_with_base("planar")


def sim_robot(robot: RobotDescription) -> SimRobot:
    """Read what the simulator needs from ``robot``.

    Raises:
        DescriptionError: Not a differential drive, or no collision shape on the base.
    """
    import pinocchio as pin

    geometry = drive_geometry(robot)
    model = robot.model_with_base("planar")
    space = JointSpace.of(model, robot.movable_joints)
    data = model.createData()
    pin.framesForwardKinematics(model, data, space.neutral())
    wheels = {w.joint for w in geometry.wheels}
    height = float(np.mean([w.radius_m - w.position_m[2] for w in geometry.wheels]))

    def placement(link: str) -> FloatArray:
        # Pinocchio's data.oMf[i] is transform_frame_to_world; the base sits at the origin.
        return np.array(data.oMf[model.getFrameId(link, pin.BODY)].homogeneous)

    return SimRobot(
        robot=robot, geometry=geometry, joint_space=space,
        arm_joints=tuple(n for n in space.names if n not in wheels),
        base_height_m=height,
        footprint=_footprint(robot, placement, wheels, height),
        lidar=_mount(robot, LIDAR_TYPES, lidar_spec, placement),
        imu=_mount(robot, ("imu",), imu_spec, placement),
        camera=_mount(robot, CAMERA_TYPES, camera_spec, placement),
    )


def _mount(robot: RobotDescription, types: tuple[str, ...], read: Callable[[Sensor], SpecT],
           placement: Placement) -> Mounted[SpecT] | None:
    sensor = next((s for s in robot.sensors if s.type in types and s.reference), None)
    if sensor is None or sensor.reference is None:
        return None
    robot.require_frame(sensor.reference)
    transform = placement(sensor.reference) @ pose_matrix(sensor.pose)
    return Mounted(read(sensor), transform)


def _moves_with_base(robot: RobotDescription, wheels: set[str]) -> list[str]:
    """Links joined to the root by fixed joints or wheel joints only."""
    root = robot.root_link
    if root is None:
        return []
    links, changed = {root}, True
    while changed:
        changed = False
        for joint in robot.joints:
            rigid = joint.type == "fixed" or joint.name in wheels
            if rigid and joint.parent in links and joint.child not in links:
                links.add(joint.child or "")
                changed = True
    return [link.name for link in robot.links if link.name in links]


def _footprint(robot: RobotDescription, placement: Placement, wheels: set[str],
               height_m: float) -> Footprint:
    corners = []
    for name in _moves_with_base(robot, wheels):
        for shape in robot.link(name).collisions:
            box = _half_extents(shape.geometry)
            if box is None:
                continue
            transform = placement(name) @ pose_matrix(shape.origin)
            signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
            corners.append((signs * box) @ transform[:3, :3].T + transform[:3, 3])
    if not corners:
        raise DescriptionError(
            f"{robot.display}: the base has no box, cylinder or sphere collision shape, so "
            "the simulator cannot tell where it would touch obstacles; add <collision> to "
            f"{robot.root_link}"
        )
    points = np.vstack(corners)
    low, high = points.min(axis=0), points.max(axis=0)
    return Footprint(float(low[0]), float(high[0]), float(low[1]), float(high[1]),
                     float(high[2] + height_m))


def _half_extents(geometry: Geometry) -> FloatArray | None:
    kind = geometry.kind
    if kind == "box" and geometry.size:
        return np.array(geometry.size) / 2
    if kind == "cylinder" and geometry.radius and geometry.length:
        r = geometry.radius
        return np.array([r, r, geometry.length / 2])
    if kind == "sphere" and geometry.radius:
        return np.full(3, geometry.radius)
    return None


def movable_joints(robot: RobotDescription, names: tuple[str, ...]) -> list[Joint]:
    """The URDF joints called ``names``, in that order."""
    return [robot.joint(n) for n in names]
