"""Wheel odometry as diff_drive_controller computes it: dead reckoning from the encoders.

Each control tick the controller reads how far the left and right wheels turned, turns that
into a body twist with its own ``wheel_separation * multiplier`` and wheel radius, and
integrates the arc exactly. The floor's slip is unknown to it, so with slip configured (or a
multiplier that does not match the floor) the odometry drifts from the ground truth.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics import diff_drive
from servicebot_cli.simulate.world import motion

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Odometry:
    """Odometry messages: pose in the ``odom`` frame (starts at zero) and body twist."""

    times_s: FloatArray
    x_m: FloatArray
    y_m: FloatArray
    yaw_rad: FloatArray
    linear_m_s: FloatArray
    angular_rad_s: FloatArray


def dead_reckoning(left_rad_s: FloatArray, right_rad_s: FloatArray, dt_s: float, *,
                   wheel_radius_m: float, track_m: float) -> motion.Path2D:
    """The odometry path at every tick boundary, from the wheel speeds each tick."""
    # body_twist is plain arithmetic, so it takes whole arrays of wheel speeds.
    linear, angular = diff_drive.body_twist(left_rad_s, right_rad_s,  # type: ignore[arg-type]  # typed for floats
                                            wheel_radius_m=wheel_radius_m, track_m=track_m)
    return motion.integrate((0.0, 0.0, 0.0), np.asarray(linear), np.asarray(angular), dt_s)


def published(path: motion.Path2D, times_s: FloatArray) -> Odometry:
    """What the controller publishes at ``times_s``: the latest update's estimate."""
    n = len(path.linear_m_s)
    k = np.clip(np.floor(times_s / path.dt_s + 1e-9).astype(np.int64), 0, n)
    twist = np.clip(k - 1, 0, n - 1)
    return Odometry(times_s, path.x_m[k], path.y_m[k], path.yaw_rad[k],
                    path.linear_m_s[twist], path.angular_rad_s[twist])
