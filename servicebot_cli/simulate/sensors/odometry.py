"""Wheel odometry as diff_drive_controller computes it: dead reckoning from the encoders.

Each control tick the controller reads how far the left and right wheels turned, turns that
into a body twist with its own ``wheel_separation * multiplier`` and wheel radii
(:mod:`~servicebot_cli.simulate.controllers.controller_wheels`), and
integrates the arc exactly. The floor's slip is unknown to it, so with slip configured (or a
multiplier that does not match the floor) the odometry drifts from the ground truth.

Gazebo Classic's diff-drive plugin with its default ``odometry_source`` (WORLD) publishes the
ground truth instead (:func:`in_world`; gazebo_ros_pkgs' ``UpdateOdometryWorld``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.controllers.controller_wheels import ControllerWheels
from servicebot_cli.simulate.world import motion

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Odometry:
    """Odometry messages: pose in the ``odom`` frame and body twist.

    Dead reckoning starts at zero; odometry from the world (``in_world``) is the base's pose
    in the world, at the height ``z_m`` of its origin, with a sideways speed
    ``lateral_m_s`` (None: zero).
    """

    times_s: FloatArray
    x_m: FloatArray
    y_m: FloatArray
    yaw_rad: FloatArray
    linear_m_s: FloatArray
    angular_rad_s: FloatArray
    in_world: bool = False
    z_m: float = 0.0
    lateral_m_s: FloatArray | None = None


class Odometer:
    """The controller's dead reckoning, a stretch of ticks at a time, from the wheel speeds."""

    def __init__(self, dt_s: float, wheels: ControllerWheels) -> None:
        self.dt_s, self.wheels = dt_s, wheels
        self.integrator = motion.Integrator((0.0, 0.0, 0.0))
        self.pose = (0.0, 0.0, 0.0)
        self.twist: tuple[float, float] | None = None  # of the last tick integrated

    def advance(self, first_tick: int, left_rad_s: FloatArray,
                right_rad_s: FloatArray) -> tuple[motion.Path2D, tuple[float, float] | None]:
        """The odometry path over the next ticks, and the twist of the tick before them.

        The path has a pose at each of the ticks' boundaries (one more than ticks); the twist
        before the run's first tick is None.
        """
        linear, angular = self.wheels.twist(left_rad_s, right_rad_s)
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


def at_rest(times_s: FloatArray) -> Odometry:
    """Odometry never updated: at the origin, heading 0, at rest, at ``times_s``.

    What Gazebo Classic's ROS 2 diff drive publishes with an ``<odometry_source>`` that is
    neither ENCODER (0) nor WORLD (1): it updates neither, and sends its initial message.
    """
    zeros = np.zeros_like(times_s)
    return Odometry(times_s, zeros, zeros, zeros, zeros, zeros)


def in_world(truth: motion.Path2D, times_s: FloatArray, before: tuple[float, float],
             height_m: float) -> Odometry:
    """Gazebo Classic's WORLD odometry at ``times_s``: the model's true pose and velocity.

    The pose is the base's in the world at the latest tick start, at ``height_m`` (its
    origin's height); the twist is the world velocity of the tick before (``before`` for
    ``truth``'s first tick), turned into the base frame as the plugin does it, with the
    heading as a C ``float``: ``x = cosf(yaw) vx + sinf(yaw) vy``,
    ``y = cosf(yaw) vy - sinf(yaw) vx``.
    """
    seen = published(truth, times_s, before)
    yaw = np.asarray(np.remainder(seen.yaw_rad + np.pi, 2 * np.pi) - np.pi, np.float32)
    c, s = np.cos(yaw).astype(float), np.sin(yaw).astype(float)
    vx, vy = seen.linear_m_s * np.cos(seen.yaw_rad), seen.linear_m_s * np.sin(seen.yaw_rad)
    return Odometry(times_s, seen.x_m, seen.y_m, seen.yaw_rad, c * vx + s * vy,
                    seen.angular_rad_s, in_world=True, z_m=height_m, lateral_m_s=c * vy - s * vx)
