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


class Odometer:
    """The controller's dead reckoning, a stretch of ticks at a time, from the wheel speeds."""

    def __init__(self, dt_s: float, *, wheel_radius_m: float, track_m: float) -> None:
        self.dt_s, self.wheel_radius_m, self.track_m = dt_s, wheel_radius_m, track_m
        self.integrator = motion.Integrator((0.0, 0.0, 0.0))
        self.pose = (0.0, 0.0, 0.0)
        self.twist: tuple[float, float] | None = None  # of the last tick integrated

    def advance(self, first_tick: int, left_rad_s: FloatArray,
                right_rad_s: FloatArray) -> tuple[motion.Path2D, tuple[float, float] | None]:
        """The odometry path over the next ticks, and the twist of the tick before them.

        The path has a pose at each of the ticks' boundaries (one more than ticks); the twist
        before the run's first tick is None.
        """
        # body_twist is plain arithmetic, so it takes whole arrays of wheel speeds.
        twist = diff_drive.body_twist(left_rad_s, right_rad_s,  # type: ignore[arg-type]  # typed for floats
                                      wheel_radius_m=self.wheel_radius_m, track_m=self.track_m)
        linear, angular = np.asarray(twist[0], float), np.asarray(twist[1], float)
        x, y, yaw, sums = self.integrator.trial(linear, angular, self.dt_s)
        self.integrator.keep(sums, len(linear))
        x, y, yaw = (np.concatenate(([start], after)) for start, after in zip(
            self.pose, (x, y, yaw), strict=True))
        self.pose = (float(x[-1]), float(y[-1]), float(yaw[-1]))
        before, self.twist = self.twist, (float(linear[-1]), float(angular[-1]))
        return motion.Path2D(self.dt_s, x, y, yaw, linear, angular, first_tick), before


def published(path: motion.Path2D, times_s: FloatArray,
              before: tuple[float, float] | None = None) -> Odometry:
    """What the controller publishes at ``times_s``: the latest update's estimate.

    A time within a tick sees the update at the tick's start: the pose there and the twist
    of the tick before, ``before`` for ``path``'s first tick (None: the run's first tick,
    whose own twist is reported).
    """
    k = path.tick_index(times_s, boundaries=True)
    first_v, first_w = before if before is not None else (path.linear_m_s[0],
                                                         path.angular_rad_s[0])
    linear = np.concatenate(([first_v], path.linear_m_s))
    angular = np.concatenate(([first_w], path.angular_rad_s))
    return Odometry(times_s, path.x_m[k], path.y_m[k], path.yaw_rad[k], linear[k], angular[k])
