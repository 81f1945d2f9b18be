"""The differential-drive geometry a URDF implies: which joints are wheels, radius, track.

A wheel is a continuous joint (or a revolute one with endless limits) whose child link
carries a cylinder turning about the joint's axis, or a sphere, with that axis horizontal and
across the robot (the root link's y). Wheels on +y are
left, on -y right. Nothing here is a constant: change the URDF and the numbers follow.
One joint is judged in :mod:`~servicebot_cli.kinematics.wheel_joints`; wheels on passive
casters are left out (:mod:`~servicebot_cli.kinematics.running_gear`). Where the links give
no such wheels, a Gazebo diff-drive plugin's wheel joints and diameter stand in
(:mod:`~servicebot_cli.kinematics.plugin_wheels`), each wheel where its round mesh is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.listing import some_of
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.mesh_wheels import MeshPoints, file_points
from servicebot_cli.kinematics.running_gear import swivels_above
from servicebot_cli.kinematics.wheel_joints import (
    NO_ROUND_SHAPE,
    Wheel,
    as_wheel,
    rolls_on_cylinder,
    turns_freely,
)

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


_MOST_JOINTS_NAMED = 6  # of one reason, in the note of what is no differential drive
SMALLEST_RADIUS_M = 1e-4
"""A wheel of a tenth of a millimetre: a typo, or no number [m]."""
LARGEST_RADIUS_M = 3.0
"""The largest wheel size taken (a drive plugin's numbers too) [m]: a mining truck's tyre is
2 m; a wheel mesh in millimetres or centimetres (70 mm read as 70 m, 7 cm as 7 m) is beyond."""


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
    def side_radii_m(self) -> tuple[float, float]:
        """The mean radius of the left wheels and of the right ones [m]: what rolls each side."""
        left, right = ([w.radius_m for w in self.wheels if w.side == side]
                       for side in ("left", "right"))
        if not left or not right:
            return self.wheel_radius_m, self.wheel_radius_m
        return float(np.mean(left)), float(np.mean(right))

    @property
    def max_linear_m_s(self) -> float:
        """Top straight-line speed the wheel limits allow [m/s]."""
        return self.max_wheel_speed_rad_s * self.wheel_radius_m

    @property
    def max_angular_rad_s(self) -> float:
        """Top turn-in-place rate the wheel limits allow [rad/s]."""
        return 2.0 * self.max_linear_m_s / self.track_m


def drive_geometry(robot: RobotDescription, meshes: MeshPoints | None = None) -> DriveGeometry:
    """Find the drive wheels of ``robot``.

    ``meshes`` reads the vertices of wheels drawn as meshes (default: from their files, found
    from the robot's file and the environment's packages).

    Raises:
        DescriptionError: Fewer than one wheel on either side, naming what was found.
    """
    world = link_transforms(robot)
    wheels: list[Wheel] = []
    left_out: dict[str, list[str]] = {}
    swivel_of = swivels_above(robot, world)
    for joint in robot.joints:
        swivel = swivel_of.get(joint.name)
        wheel = (as_wheel(robot, joint, world) if swivel is None
                 else f"on a caster: '{swivel}' swivels it about the vertical")
        if isinstance(wheel, Wheel):
            wheels.append(wheel)
        elif wheel is not None:
            left_out.setdefault(wheel, []).append(joint.name)
    wheels = _without_ball_casters(robot, wheels, left_out)
    sides = {side: [w for w in wheels if w.side == side] for side in ("left", "right")}
    if not sides["left"] or not sides["right"]:  # mesh wheels a diff-drive plugin names?
        from servicebot_cli.kinematics.plugin_wheels import plugin_wheels

        if meshes is None:
            meshes = file_points(None, robot.path.parent)
        wheels = plugin_wheels(robot, world, meshes) or wheels
        sides = {side: [w for w in wheels if w.side == side] for side in ("left", "right")}
    if not sides["left"] or not sides["right"]:
        found = ", ".join(f"{w.joint} ({w.side})" for w in wheels) or "none"
        raise DescriptionError(
            f"{robot.display}: not a differential drive: needs wheel joints that turn freely "
            "(continuous, or revolute with endless limits) on both sides, with a cylinder "
            "about the joint axis or a sphere, or a round mesh where a diff-drive plugin or "
            f"<ros2_control> velocity command names the joint (found: {found}); "
            + _why_not_wheels(robot, left_out)
        )
    for wheel in wheels:
        if math.isnan(wheel.radius_m):  # radius="50mm": no number (SB013)
            raise DescriptionError(
                f"{robot.display}: wheel joint '{wheel.joint}' rolls on a radius that is no "
                "number as written ('nan', or a unit after it: '50mm'); write its cylinder's "
                "radius in metres, a plain number (run 'servicebot check "
                f"{robot.display}' for the line)")
        if not (math.isfinite(wheel.radius_m) and SMALLEST_RADIUS_M <= wheel.radius_m
                <= LARGEST_RADIUS_M):
            raise DescriptionError(
                f"{robot.display}: wheel joint '{wheel.joint}' rolls on a radius of "
                f"{wheel.radius_m:g} m, which no wheel has (from {SMALLEST_RADIUS_M:g} to "
                f"{LARGEST_RADIUS_M:g} m); draw it at its real size in metres: a cylinder's or "
                "sphere's radius, or a mesh with the scale that makes its units metres "
                "(scale=\"0.001 0.001 0.001\" for millimetres, \"0.01 0.01 0.01\" for "
                "centimetres)")
    left_y = np.mean([w.position_m[1] for w in sides["left"]])
    right_y = np.mean([w.position_m[1] for w in sides["right"]])
    return DriveGeometry(
        wheels=tuple(wheels),
        wheel_radius_m=float(np.mean([w.radius_m for w in wheels])),
        track_m=float(left_y - right_y),
        max_wheel_speed_rad_s=min(w.velocity_limit_rad_s for w in wheels),
    )


def _without_ball_casters(robot: RobotDescription, wheels: list[Wheel],
                          left_out: dict[str, list[str]]) -> list[Wheel]:
    """``wheels`` without the balls beside cylinder wheels: passive ball casters.

    A ball on a continuous joint turns about any axis; beside drive wheels that are
    cylinders on both sides, it carries the robot and drives nothing (a base with four
    corner casters had their radii and positions averaged into the drive's). Where every
    wheel is a ball (neobotix's collide as spheres), the balls are the wheels.
    """
    cylinders = [w for w in wheels if rolls_on_cylinder(robot, robot.joint(w.joint))]
    if {w.side for w in cylinders} != {"left", "right"}:
        return wheels
    for wheel in wheels:
        if wheel not in cylinders:
            left_out.setdefault("as a ball beside cylinder wheels: a passive caster",
                                []).append(wheel.joint)
    return cylinders


def _why_not_wheels(robot: RobotDescription, left_out: dict[str, list[str]]) -> str:
    """Why the continuous joints are not wheels, joints grouped by reason (three at most).

    Joints that mimic another come last: a finger that follows its neighbour is less likely
    the wheel the reader looks for (Pepper's three mimic fingers hid its wheels behind '...').
    Joints whose links lack a round shape are named with their links.
    """
    if not left_out:
        return "it has no continuous joint" if not any(
            turns_freely(j) for j in robot.joints) else "no other continuous joint is one"
    mimics = {j.name for j in robot.joints if j.mimic is not None}
    reasons = []
    for reason, joints in sorted(left_out.items(),
                                 key=lambda item: all(j in mimics for j in item[1])):
        joints = sorted(joints, key=lambda joint: joint in mimics)
        one = len(joints) == 1
        if reason == NO_ROUND_SHAPE:
            named = [f"{joint} (link '{robot.joint(joint).child}')" for joint in joints]
            reasons.append(f"{some_of(named, _MOST_JOINTS_NAMED)} {'turns' if one else 'turn'}"
                           f" but {'its link has' if one else 'their links have'} no <cylinder>"
                           " or <sphere> collision or visual to take a radius from")
        else:
            reasons.append(f"{some_of(joints, _MOST_JOINTS_NAMED)} "
                           f"{'turns' if one else 'turn'} {reason}")
    return "; ".join(reasons[:3]) + ("; ..." if len(reasons) > 3 else "")

