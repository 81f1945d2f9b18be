"""The differential-drive geometry a URDF implies: which joints are wheels, radius, track.

A wheel is a continuous joint (or a revolute one with endless limits) whose child link
carries a cylinder turning about the joint's axis, or a sphere, with that axis horizontal and
across the robot (the root link's y). Wheels on +y are
left, on -y right. Nothing here is a constant: change the URDF and the numbers follow.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.elements import Joint, Shape
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_ONE_AXIS = ("revolute", "continuous", "prismatic")
_PARALLEL = 0.99  # |cos| of the angle between axes that counts as parallel (about 8 degrees)
_ENDLESS_RAD = 1e3  # revolute limits beyond this each way bound no wheel
_BALL_CASTER = "on the centre line: a ball caster, not a drive wheel"


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


@dataclass(frozen=True)
class DriveGeometry:
    """The wheels of a differential-drive base and the numbers diff_drive_controller needs.

    Attributes:
        wheels: Every wheel, URDF order.
        wheel_radius_m: Mean wheel radius [m].
        track_m: Distance between the mean left and mean right wheel centres
            (diff_drive_controller's ``wheel_separation``) [m].
        max_wheel_speed_rad_s: The smallest wheel velocity limit [rad/s].
    """

    wheels: tuple[Wheel, ...]
    wheel_radius_m: float
    track_m: float
    max_wheel_speed_rad_s: float

    @property
    def left(self) -> tuple[str, ...]:
        """Left wheel joint names."""
        return tuple(w.joint for w in self.wheels if w.side == "left")

    @property
    def right(self) -> tuple[str, ...]:
        """Right wheel joint names."""
        return tuple(w.joint for w in self.wheels if w.side == "right")

    @property
    def max_linear_m_s(self) -> float:
        """Top straight-line speed the wheel limits allow [m/s]."""
        return self.max_wheel_speed_rad_s * self.wheel_radius_m

    @property
    def max_angular_rad_s(self) -> float:
        """Top turn-in-place rate the wheel limits allow [rad/s]."""
        return 2.0 * self.max_linear_m_s / self.track_m


def drive_geometry(robot: RobotDescription) -> DriveGeometry:
    """Find the drive wheels of ``robot``.

    Raises:
        DescriptionError: Fewer than one wheel on either side, naming what was found.
    """
    world = _link_transforms(robot)
    wheels: list[Wheel] = []
    left_out: dict[str, list[str]] = {}
    swivel_of = _swivels_above(robot, world)
    for joint in robot.joints:
        swivel = swivel_of.get(joint.name)
        wheel = (_as_wheel(robot, joint, world) if swivel is None
                 else f"on a caster: '{swivel}' swivels it about the vertical")
        if isinstance(wheel, Wheel):
            wheels.append(wheel)
        elif wheel is not None:
            left_out.setdefault(wheel, []).append(joint.name)
    sides = {side: [w for w in wheels if w.side == side] for side in ("left", "right")}
    if not sides["left"] or not sides["right"]:
        found = ", ".join(f"{w.joint} ({w.side})" for w in wheels) or "none"
        raise DescriptionError(
            f"{robot.display}: not a differential drive: needs wheel joints that turn freely "
            "(continuous, or revolute with endless limits) on both sides, with a cylinder "
            f"about the joint axis or a sphere (found: {found}); "
            + _why_not_wheels(robot, left_out)
        )
    left_y = np.mean([w.position_m[1] for w in sides["left"]])
    right_y = np.mean([w.position_m[1] for w in sides["right"]])
    return DriveGeometry(
        wheels=tuple(wheels),
        wheel_radius_m=float(np.mean([w.radius_m for w in wheels])),
        track_m=float(left_y - right_y),
        max_wheel_speed_rad_s=min(w.velocity_limit_rad_s for w in wheels),
    )


def chassis_joints(robot: RobotDescription, wheels: Sequence[str] = ()) -> tuple[str, ...]:
    """The movable joints of the running gear other than the drive ``wheels``, URDF order.

    Passive casters (:func:`_swivels_above`; a ball on the centre line), and the one-axis
    joints above a drive wheel or a caster that carry wheels of one side only: a suspension
    (Leo Rover's rockers) or a steering joint. A joint that carries both sides' wheels (a
    virtual planar base above the whole robot) is not running gear, nor is anything above
    it. None of them is an arm.
    """
    world = _link_transforms(robot)
    below = _swivels_above(robot, world)
    gear = set(below.values()) | set(below) | {
        joint.name for joint in robot.joints
        if _as_wheel(robot, joint, world) == _BALL_CASTER}
    by_child = {joint.child: joint for joint in robot.joints}
    by_name = {joint.name: joint for joint in robot.joints}
    children: dict[str, list[Joint]] = {}
    for each in robot.joints:
        if each.parent is not None:
            children.setdefault(each.parent, []).append(each)
    side = _wheel_sides(by_name, wheels, world)
    for name in (*wheels, *gear):
        joint = by_name.get(name)
        above = by_child.get(joint.parent) if joint is not None else None
        while above is not None and above.name not in gear:
            if len({side[w] for w in _wheels_below(above, side, children)}) > 1:
                break  # it carries both sides: the base itself moves
            if above.type in _ONE_AXIS:
                gear.add(above.name)
            above = by_child.get(above.parent)
    return tuple(j.name for j in robot.joints if j.name in gear and j.name not in wheels)


def _wheel_sides(by_name: dict[str, Joint], wheels: Sequence[str],
                 world: dict[str, np.ndarray]) -> dict[str, str]:
    """Each drive wheel's side (its joint's child on +y of the root: left)."""
    sides = {}
    for name in wheels:
        child = by_name[name].child if name in by_name else None
        if child is not None and child in world:
            sides[name] = "left" if world[child][1, 3] > 0 else "right"
    return sides


def _wheels_below(joint: Joint, side: dict[str, str],
                  children: dict[str, list[Joint]]) -> list[str]:
    """The drive wheels of ``side`` in the subtree ``joint`` carries (itself included).

    ``children``: each link's child joints.
    """
    found: list[str] = []
    stack, seen = [joint], set()
    while stack:
        current = stack.pop()
        if current.name in seen:
            continue
        seen.add(current.name)
        if current.name in side:
            found.append(current.name)
        stack += children.get(current.child or "", [])
    return found


def _swivels_above(robot: RobotDescription, world: dict[str, np.ndarray]) -> dict[str, str]:
    """Passive casters: each caster wheel joint, and the swivel it turns on.

    A swivel turns freely about the vertical (the root link's z), on a link fixed to the
    root link; its child link is the parent of the caster wheel's joint, which turns freely
    and carries a round shape (MiR's ``fl_caster_rotation_joint`` over
    ``fl_caster_wheel_joint``). An arm's waist carries no wheel; a virtual yaw joint above
    the whole base stands on a moving link.
    """
    by_child = {joint.child: joint for joint in robot.joints}
    on_root = _fixed_to_root(robot)
    found: dict[str, str] = {}
    for joint in robot.joints:
        swivel = by_child.get(joint.parent) if joint.parent is not None else None
        if joint.child is None or not turns_freely(joint) or swivel is None \
                or not turns_freely(swivel) or swivel.parent not in on_root \
                or not _vertical(swivel, world):
            continue
        link = robot.link(joint.child)
        if any(s.geometry.kind in ("cylinder", "sphere")
               for s in (*link.collisions, *link.visuals)):
            found[joint.name] = swivel.name
    return found


def _fixed_to_root(robot: RobotDescription) -> set[str]:
    """The root link and the links fixed to it."""
    fixed: dict[str, list[str]] = {}
    for joint in robot.joints:
        if joint.type == "fixed" and joint.parent is not None and joint.child is not None:
            fixed.setdefault(joint.parent, []).append(joint.child)
    found, stack = set(), [robot.root_link] if robot.root_link else []
    while stack:
        link = stack.pop()
        if link not in found:
            found.add(link)
            stack += fixed.get(link, [])
    return found


def _vertical(joint: Joint, world: dict[str, np.ndarray]) -> bool:
    """Whether ``joint`` turns about the root link's z at the zero configuration."""
    axis = np.array(joint.axis, dtype=float)
    norm = float(np.linalg.norm(axis))
    if joint.child not in world or not math.isfinite(norm) or norm == 0:
        return False
    return abs(float((world[joint.child][:3, :3] @ (axis / norm))[2])) >= _PARALLEL


def _why_not_wheels(robot: RobotDescription, left_out: dict[str, list[str]]) -> str:
    """Why the continuous joints are not wheels, joints grouped by reason (three at most)."""
    if not left_out:
        return "it has no continuous joint" if not any(
            turns_freely(j) for j in robot.joints) else "no other continuous joint is one"
    reasons = [f"{', '.join(joints)} {'turns' if len(joints) == 1 else 'turn'} {reason}"
               for reason, joints in left_out.items()]
    return "; ".join(reasons[:3]) + ("; ..." if len(reasons) > 3 else "")


def _link_transforms(robot: RobotDescription) -> dict[str, np.ndarray]:
    """Pose of every reachable link in the root frame at the zero configuration."""
    return link_transforms(robot)


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


def _as_wheel(robot: RobotDescription, joint: Joint,
              world: dict[str, np.ndarray]) -> Wheel | str | None:
    """The wheel ``joint`` drives; why it is not one (a joint that turns freely); or None.

    Its radius is that of a cylinder about the joint axis, else of a sphere (a ball turns
    about any axis: neobotix's wheels collide as spheres).
    """
    if not turns_freely(joint) or joint.child not in world or joint.parent not in world:
        return None
    link = robot.link(joint.child)
    shapes = (*link.collisions, *link.visuals)
    round_shape = next((s for s in shapes if s.geometry.kind == "cylinder"), None) \
        or next((s for s in shapes if s.geometry.kind == "sphere"), None)
    if round_shape is None or not round_shape.geometry.radius:
        return (f"but link '{link.name}' has no <cylinder> or <sphere> collision or visual to "
                "take its radius from")
    axis = np.array(joint.axis, dtype=float)
    if not np.all(np.isfinite(axis)) or np.linalg.norm(axis) == 0:
        return "about a zero axis"
    axis /= np.linalg.norm(axis)
    if round_shape.geometry.kind == "cylinder" \
            and abs(float(axis @ _cylinder_axis(round_shape))) < _PARALLEL:
        return f"about an axis that is not the axis of the cylinder on '{link.name}'"
    transform = world[joint.child]
    axis_in_root = transform[:3, :3] @ axis
    if abs(axis_in_root[1]) < _PARALLEL:
        shown = " ".join(f"{v:.3g}" for v in np.round(axis_in_root, 3) + 0.0)
        return (f"about ({shown}) in {robot.root_link}, not across the robot (its y, with x "
                "forward as REP 103 has it)")
    position = transform[:3, 3]
    if round_shape.geometry.kind == "sphere" and abs(position[1]) <= round_shape.geometry.radius:
        return _BALL_CASTER
    limit = joint.limits.velocity if joint.limits and joint.limits.velocity else math.inf
    return Wheel(
        joint=joint.name,
        side="left" if position[1] > 0 else "right",
        radius_m=float(round_shape.geometry.radius),
        position_m=(float(position[0]), float(position[1]), float(position[2])),
        axis_sign=1 if axis_in_root[1] > 0 else -1,
        velocity_limit_rad_s=float(limit),
    )


def _cylinder_axis(shape: Shape) -> np.ndarray:
    """The cylinder's own z axis, expressed in its link frame."""
    return pose_matrix(shape.origin)[:3, 2]

