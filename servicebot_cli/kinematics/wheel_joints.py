"""One joint as a drive wheel: whether it is one, its radius, side and direction, or why not.

A wheel is a continuous joint (or a revolute one with endless limits) whose child link
carries a cylinder turning about the joint's axis, or a sphere, with that axis horizontal and
across the robot (the root link's y). Wheels on +y are left, on -y right. A sphere on the
centre line is a ball caster. For :mod:`~servicebot_cli.kinematics.drive_geometry`. Pure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.description.elements import Joint, Link, Shape
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

PARALLEL = 0.99
"""``|cos|`` of the angle between axes that counts as parallel (about 8 degrees)."""
BALL_CASTER = "on the centre line: a ball caster, not a drive wheel"
"""Why a sphere on the centre line is not a drive wheel (:func:`as_wheel`)."""
_ENDLESS_RAD = 1e3  # revolute limits beyond this each way bound no wheel


@dataclass(frozen=True)
class Wheel:
    """One drive wheel.

    Attributes:
        joint: The wheel's joint.
        side: ``left`` or ``right``.
        radius_m: Cylinder radius [m].
        position_m: Wheel centre in the root link frame at the zero configuration [m].
        axis_sign: +1 when a positive joint velocity rolls the robot forward, else -1.
        velocity_limit_rad_s: The joint's ``<limit velocity>`` [rad/s]; inf if absent.
    """

    joint: str
    side: str
    radius_m: float
    position_m: tuple[float, float, float]
    axis_sign: int
    velocity_limit_rad_s: float


def turns_freely(joint: Joint) -> bool:
    """A continuous joint, or a revolute one whose limits bound nothing a wheel does.

    Exporters write an endless wheel as revolute with limits of 1e16 rad (neobotix's
    MP-400); more than :data:`_ENDLESS_RAD` each way is endless.
    """
    if joint.type == "continuous":
        return True
    limits = joint.limits
    return joint.type == "revolute" and limits is not None and limits.lower is not None \
        and limits.upper is not None and limits.lower <= -_ENDLESS_RAD \
        and limits.upper >= _ENDLESS_RAD


NO_ROUND_SHAPE = "but no <cylinder> or <sphere> on its link to take a radius from"
"""Why a joint that turns freely is no wheel, when its link gives no round shape."""


def as_wheel(robot: RobotDescription, joint: Joint,
              world: dict[str, np.ndarray]) -> Wheel | str | None:
    """The wheel ``joint`` drives; why it is not one (a joint that turns freely); or None.

    Its radius is that of a cylinder about the joint axis, else of a sphere (a ball turns
    about any axis: neobotix's wheels collide as spheres).
    """
    link = robot.find_link(joint.child)  # a child that is no link: SB103 says so
    if not turns_freely(joint) or link is None or joint.child not in world \
            or joint.parent not in world:
        return None
    axis = unit_axis(joint)
    round_shape = _round_shape(link, axis)
    if round_shape is None or not round_shape.geometry.radius:
        return NO_ROUND_SHAPE
    if axis is None:
        return "about a zero axis"
    if round_shape.geometry.kind == "cylinder" \
            and abs(float(axis @ _cylinder_axis(round_shape))) < PARALLEL:
        return f"about an axis that is not the axis of the cylinder on '{link.name}'"
    transform = world[joint.child]
    axis_in_root = transform[:3, :3] @ axis
    if abs(axis_in_root[1]) < PARALLEL:
        shown = " ".join(f"{v:.3g}" for v in np.round(axis_in_root, 3) + 0.0)
        return (f"about ({shown}) in {robot.root_link}, not across the robot (its y, with x "
                "forward as REP 103 has it)")
    # the wheel's centre is its cylinder's (or sphere's), which may sit along the axle from
    # the joint (limo's wheels are 0.0225 m outward of their joints: a track 0.045 m wider)
    position = (transform @ pose_matrix(round_shape.origin))[:3, 3]
    if round_shape.geometry.kind == "sphere" and abs(position[1]) <= round_shape.geometry.radius:
        return BALL_CASTER
    return wheel_at(joint, position, float(round_shape.geometry.radius), axis_in_root)


def _round_shape(link: Link, axis: np.ndarray | None) -> Shape | None:
    """The shape a wheel rolls on: its largest cylinder about ``axis``, else a sphere.

    Collisions before visuals, as Gazebo rolls on those. Of several cylinders about the axis
    the largest touches the ground: Leo's wheels list a hub (r 0.057 m) before the tyre
    (r 0.0625 m), and the radius was the hub's. Without one about the axis, the first
    cylinder (whose axis the caller then says is not the joint's).
    """
    for shapes in (link.collisions, link.visuals):
        cylinders = [s for s in shapes if s.geometry.kind == "cylinder"]
        about = [s for s in cylinders if axis is not None and s.geometry.radius is not None
                 and math.isfinite(s.geometry.radius)
                 and abs(float(axis @ _cylinder_axis(s))) >= PARALLEL]
        if about:
            return max(about, key=lambda s: abs(s.geometry.radius or 0.0))
    shapes = (*link.collisions, *link.visuals)
    return next((s for s in shapes if s.geometry.kind == "cylinder"), None) \
        or next((s for s in shapes if s.geometry.kind == "sphere"), None)


def unit_axis(joint: Joint) -> np.ndarray | None:
    """``joint``'s axis of unit length in its own frame; None when it is zero or no number."""
    axis = np.array(joint.axis, dtype=float)
    if not np.all(np.isfinite(axis)) or np.linalg.norm(axis) == 0:
        return None
    unit: np.ndarray = axis / np.linalg.norm(axis)
    return unit


def wheel_at(joint: Joint, position: np.ndarray, radius_m: float,
             axis_in_root: np.ndarray) -> Wheel:
    """The wheel of ``joint`` centred at ``position``, turning about ``axis_in_root``.

    Its side is the sign of its y; its speed limit the joint's ``<limit velocity>``.
    """
    limit = joint.limits.velocity if joint.limits and joint.limits.velocity else math.inf
    return Wheel(
        joint=joint.name,
        side="left" if position[1] > 0 else "right",
        radius_m=radius_m,
        position_m=(float(position[0]), float(position[1]), float(position[2])),
        axis_sign=1 if axis_in_root[1] > 0 else -1,
        velocity_limit_rad_s=float(limit),
    )


def rolls_on_cylinder(robot: RobotDescription, joint: Joint) -> bool:
    """Whether the wheel of ``joint`` takes its radius from a cylinder (else a sphere)."""
    link = robot.find_link(joint.child)
    if link is None:
        return False
    return any(s.geometry.kind == "cylinder" for s in (*link.collisions, *link.visuals))


def _cylinder_axis(shape: Shape) -> np.ndarray:
    """The cylinder's own z axis, expressed in its link frame."""
    return pose_matrix(shape.origin)[:3, 2]
