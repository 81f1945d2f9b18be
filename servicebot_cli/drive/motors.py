"""The motors a controller drives, in wire order, with the limits the URDF gives them.

Every number comes from the robot description: wheel joints, sides, radius and track from
:func:`~servicebot_cli.kinematics.drive_geometry.drive_geometry`, wheel velocity limits
from each wheel's ``<limit velocity>``, arm ranges and speeds from ``robot.joint_space``.
Nothing that leaves :meth:`MotorMap.clamp_wheels` or :meth:`MotorMap.clamp_arm` is beyond
a limit, whatever went in (NaN and infinities included).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError, JointNotFound, OutOfLimits

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.drive_geometry import DriveGeometry


@dataclass(frozen=True)
class MotorMap:
    """Wheel and arm motors of one robot.

    Attributes:
        robot: The robot's name, for messages.
        wheel_joints: Wheel joint names, URDF order (the order on the wire).
        wheel_sides: ``left`` or ``right`` per wheel.
        wheel_axis_signs: +1 when a positive joint velocity rolls the robot forward.
        wheel_max_rad_s: Velocity limit per wheel [rad/s].
        geometry: The drive geometry the URDF implies (radius, track, top speeds).
        arm_joints: Arm joint names, URDF order.
        arm_lower: Lower position limit per arm joint [rad].
        arm_upper: Upper position limit per arm joint [rad].
        arm_max_rad_s: Velocity limit per arm joint [rad/s]; inf where the URDF has none.
    """

    robot: str
    wheel_joints: tuple[str, ...]
    wheel_sides: tuple[str, ...]
    wheel_axis_signs: tuple[int, ...]
    wheel_max_rad_s: tuple[float, ...]
    geometry: DriveGeometry
    arm_joints: tuple[str, ...]
    arm_lower: tuple[float, ...]
    arm_upper: tuple[float, ...]
    arm_max_rad_s: tuple[float, ...]

    @property
    def max_wheel_rad_s(self) -> float:
        """The smallest wheel velocity limit [rad/s]: what a side may turn at."""
        return min(self.wheel_max_rad_s)

    @property
    def wheel_radius_m(self) -> float:
        """Wheel radius [m]."""
        return self.geometry.wheel_radius_m

    @property
    def track_m(self) -> float:
        """Left-to-right wheel distance [m]."""
        return self.geometry.track_m

    def capped(self, max_wheel_rad_s: float | None) -> MotorMap:
        """These motors with every wheel limited to ``max_wheel_rad_s`` too (``--max-speed``).

        Raises:
            OutOfLimits: A cap above the URDF's limit (it would not cap anything).
        """
        if max_wheel_rad_s is None:
            return self
        if max_wheel_rad_s > self.max_wheel_rad_s:
            raise OutOfLimits(
                f"{max_wheel_rad_s:g} rad/s is above {self.robot}'s wheel limit of "
                f"{self.max_wheel_rad_s:g} rad/s in the URDF; give a smaller cap, or none")
        return replace(
            self, wheel_max_rad_s=tuple(min(v, max_wheel_rad_s) for v in self.wheel_max_rad_s),
            geometry=replace(self.geometry, max_wheel_speed_rad_s=min(
                self.geometry.max_wheel_speed_rad_s, max_wheel_rad_s)))

    def clamp_wheels(self, speeds_rad_s: Sequence[float]) -> tuple[float, ...]:
        """Each wheel speed inside its limit; NaN becomes 0 (stop)."""
        return tuple(
            0.0 if math.isnan(v) else max(-limit, min(limit, v))
            for v, limit in zip(speeds_rad_s, self.wheel_max_rad_s, strict=True)
        )

    def clamp_arm(self, targets_rad: Sequence[float]) -> tuple[float, ...]:
        """Each arm target inside its range; NaN becomes the value nearest 0 in range."""
        return tuple(
            max(lo, min(hi, 0.0 if math.isnan(v) else v))
            for v, lo, hi in zip(targets_rad, self.arm_lower, self.arm_upper, strict=True)
        )

    def side_speeds(self, left_rad_s: float, right_rad_s: float) -> tuple[float, ...]:
        """Joint velocities of every wheel for forward-positive side speeds [rad/s]."""
        return tuple(
            sign * (left_rad_s if side == "left" else right_rad_s)
            for side, sign in zip(self.wheel_sides, self.wheel_axis_signs, strict=True)
        )

    def arm_targets(self, assignments: Mapping[str, float],
                    base: Sequence[float]) -> tuple[float, ...]:
        """``base`` with the named arm joints set; every value checked against its range.

        Raises:
            JointNotFound: A name that is not an arm joint, with the closest ones.
            OutOfLimits: A value outside its joint's range.
        """
        targets = list(base)
        for name, value in assignments.items():
            if name not in self.arm_joints:
                raise JointNotFound.for_name(name, self.arm_joints, robot=f"{self.robot}'s arm")
            i = self.arm_joints.index(name)
            lo, hi = self.arm_lower[i], self.arm_upper[i]
            if not lo <= value <= hi:
                raise OutOfLimits(
                    f"joint '{name}' = {value:g} rad is outside its limits [{lo:g}, {hi:g}] rad "
                    "in the URDF; give a value inside them"
                )
            targets[i] = value
        return tuple(targets)


def motor_map(robot: RobotDescription, resolver: PackageResolver | None = None) -> MotorMap:
    """The wheel and arm motors of ``robot`` with their URDF limits.

    ``resolver`` finds wheel meshes (``--package``), where the wheels are drawn as meshes.

    Raises:
        DescriptionError: Not a differential drive (steered wheels too), or a wheel without a
            velocity limit.
    """
    from servicebot_cli.kinematics.drive_geometry import drive_geometry
    from servicebot_cli.kinematics.mesh_wheels import file_points
    from servicebot_cli.kinematics.steering import refuse_steered_wheels

    geometry = drive_geometry(robot, file_points(resolver, robot.path.parent))
    refuse_steered_wheels(robot)
    wheels = geometry.wheels
    unlimited = [w.joint for w in wheels if not math.isfinite(w.velocity_limit_rad_s)]
    if unlimited:
        raise DescriptionError(
            f"{robot.display}: wheel joint '{unlimited[0]}' has no <limit velocity>; drive "
            "never sends a speed without a limit, so add one to the URDF"
        )
    space = robot.joint_space
    wheel_names = {w.joint for w in wheels}
    arm = [i for i, (name, kind) in enumerate(zip(space.names, space.types, strict=True))
           if name not in wheel_names and kind in ("revolute", "prismatic")]
    return MotorMap(
        robot=robot.name,
        wheel_joints=tuple(w.joint for w in wheels),
        wheel_sides=tuple(w.side for w in wheels),
        wheel_axis_signs=tuple(w.axis_sign for w in wheels),
        wheel_max_rad_s=tuple(w.velocity_limit_rad_s for w in wheels),
        geometry=geometry,
        arm_joints=tuple(space.names[i] for i in arm),
        arm_lower=tuple(float(space.lower[i]) for i in arm),
        arm_upper=tuple(float(space.upper[i]) for i in arm),
        arm_max_rad_s=tuple(_finite_or_inf(float(space.velocity[i])) for i in arm),
    )


def _finite_or_inf(value: float) -> float:
    return value if math.isfinite(value) else math.inf
