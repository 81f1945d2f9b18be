"""From a body twist to wheel joint velocities that respect the robot's limits.

The twist goes through the robot's kinematics (radius and track from the URDF), is scaled
down as a whole when a wheel would exceed its velocity limit (so the path's curvature is
kept), and the wheels then approach it no faster than the acceleration limit allows, both
sides together (so the curvature is kept while ramping too).
"""

from __future__ import annotations

import math

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.kinematics.diff_drive import rate_limit, saturate_keep_curvature, wheel_speeds


class WheelShaper:
    """Twist in, limited wheel joint velocities out; remembers the last output.

    Args:
        motors: The robot's wheels and their limits.
        max_accel_rad_s2: Largest change of a wheel's speed per second [rad/s^2].
    """

    def __init__(self, motors: MotorMap, max_accel_rad_s2: float) -> None:
        self.motors = motors
        self.max_accel_rad_s2 = max_accel_rad_s2
        self.left_rad_s = 0.0
        self.right_rad_s = 0.0
        self.scaled = False

    def unlimited(self, linear_m_s: float, angular_rad_s: float) -> tuple[float, float]:
        """Left and right speeds [rad/s] the kinematics ask for.

        A twist that is not a number (NaN) is a stop. A finite twist so large that the speeds
        overflow asks for infinite speeds (:meth:`target` still scales it down correctly).
        """
        if math.isnan(linear_m_s) or math.isnan(angular_rad_s):
            return 0.0, 0.0
        return wheel_speeds(linear_m_s, angular_rad_s, wheel_radius_m=self.motors.wheel_radius_m,
                            track_m=self.motors.track_m)

    def target(self, linear_m_s: float, angular_rad_s: float) -> tuple[float, float]:
        """Left and right speeds [rad/s] within the wheel limit, curvature kept.

        The twist is first divided by its largest component when its speeds would overflow:
        the same path, at a speed a float holds, scaled down to the limit from there.
        """
        left, right = self.unlimited(linear_m_s, angular_rad_s)
        if not (math.isfinite(left) and math.isfinite(right)):
            size = max(abs(linear_m_s), abs(angular_rad_s))
            if not math.isfinite(size):
                return 0.0, 0.0  # an infinite twist has no direction to keep
            left, right = self.unlimited(linear_m_s / size, angular_rad_s / size)
        return saturate_keep_curvature(left, right, self.motors.max_wheel_rad_s)

    def step(self, linear_m_s: float, angular_rad_s: float, dt_s: float) -> tuple[float, ...]:
        """Wheel joint velocities [rad/s] for the next command, ``dt_s`` after the last one."""
        left, right = self.target(linear_m_s, angular_rad_s)
        self.scaled = (left, right) != self.unlimited(linear_m_s, angular_rad_s)
        d_left, d_right = left - self.left_rad_s, right - self.right_rad_s
        peak = max(abs(d_left), abs(d_right))
        if peak > 0.0:  # share the acceleration so both sides arrive together
            dt = max(0.0, dt_s)
            self.left_rad_s = rate_limit(self.left_rad_s, left,
                                         self.max_accel_rad_s2 * abs(d_left) / peak, dt)
            self.right_rad_s = rate_limit(self.right_rad_s, right,
                                          self.max_accel_rad_s2 * abs(d_right) / peak, dt)
        return self.motors.clamp_wheels(self.motors.side_speeds(self.left_rad_s, self.right_rad_s))

    def reset(self) -> None:
        """The wheels are stopped: ramp from zero again."""
        self.left_rad_s = self.right_rad_s = 0.0
