"""The diff-drive controller: timed ``cmd_vel`` in, wheel speeds per control tick out.

It follows diff_drive_controller's update: a command older than ``cmd_vel_timeout_s`` is
replaced by zero, the twist goes through the speed limiter (jerk, acceleration, velocity,
from the last limited command; so a timed-out robot ramps to a stop), turned into wheel
speeds with the controller's ``wheel_separation * multiplier`` and wheel radius,
and the wheel speeds are saturated at the URDF's velocity limit: both sides scaled together
(curvature kept) or each wheel clipped alone (``per-wheel``, what Gazebo does).

Commands are piecewise constant, so the sequential part (rate limiting) only steps tick by
tick while a value is ramping; constant stretches are filled in one numpy operation. A run is
planned a stretch of ticks at a time (:class:`WheelPlanner`); the limiter's state carries over.
A base that gz-sim's DiffDrive system drives runs gz-math's limiter instead (:mod:`.limiter`);
one that Gazebo Classic's diff-drive plugin drives with a wheel acceleration limit has its
wheel speeds ramped as the plugin does (:mod:`.classic_drive`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics import diff_drive
from servicebot_cli.kinematics.drive_geometry import DriveGeometry
from servicebot_cli.simulate.controllers.classic_drive import ClassicDrive, WheelRamp
from servicebot_cli.simulate.controllers.controller_wheels import ControllerWheels
from servicebot_cli.simulate.controllers.limiter import (
    DIFF_DRIVE_CONTROLLER,
    AxisLimits,
    Limiter,
)
from servicebot_cli.simulate.scenario.definition import CmdVel, Controller

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class WheelPlan:
    """Per control tick ``k`` (interval ``[k dt, (k+1) dt)``).

    Attributes:
        dt_s: Control period [s].
        target_linear_m_s, target_angular_rad_s: The command in force (zero after timeout).
        linear_m_s, angular_rad_s: The command after the acceleration limits.
        left_rad_s, right_rad_s: Wheel speeds sent to the hardware, after saturation.
    """

    dt_s: float
    target_linear_m_s: FloatArray
    target_angular_rad_s: FloatArray
    linear_m_s: FloatArray
    angular_rad_s: FloatArray
    left_rad_s: FloatArray
    right_rad_s: FloatArray

    @property
    def ticks(self) -> int:
        """Number of control ticks."""
        return len(self.left_rad_s)


def command_targets(segments: Sequence[CmdVel], ticks: range, dt_s: float,
                    timeout_s: float) -> tuple[FloatArray, FloatArray]:
    """The twist in force at each of ``ticks``: the current segment's, or the last one's.

    A segment publishes from ``start_s`` until ``end_s``; at ``end_s + timeout_s`` its
    command is stale and the target becomes zero.
    """
    times = np.arange(ticks.start, ticks.stop) * dt_s
    linear, angular = np.zeros(len(ticks)), np.zeros(len(ticks))
    for segment in segments:
        # A command sent at end_s is still fresh just before end_s + timeout_s.
        live = (times >= segment.start_s - 1e-9) & (times < segment.end_s + timeout_s - 1e-9)
        linear[live], angular[live] = segment.linear_m_s, segment.angular_rad_s
    return linear, angular


def tick_count(controller: Controller, duration_s: float) -> int:
    """Control ticks in a run of ``duration_s`` (at least one)."""
    return max(1, int(np.ceil(duration_s / (1.0 / controller.update_rate_hz) - 1e-9)))


class WheelPlanner:
    """Wheel speeds of a run of ``duration_s``, planned a stretch of ticks at a time."""

    def __init__(self, segments: Sequence[CmdVel], controller: Controller,
                 geometry: DriveGeometry, duration_s: float,
                 limiter: str = DIFF_DRIVE_CONTROLLER,
                 classic_drive: ClassicDrive | None = None) -> None:
        c = controller
        self.segments, self.controller, self.geometry = segments, controller, geometry
        self.dt_s = 1.0 / c.update_rate_hz
        self.ticks = tick_count(controller, duration_s)
        self.linear = Limiter(AxisLimits.of(
            limiter, c.min_linear_velocity_m_s, c.max_linear_velocity_m_s,
            c.min_linear_acceleration_m_s2, c.max_linear_acceleration_m_s2,
            c.min_linear_jerk_m_s3, c.max_linear_jerk_m_s3), self.dt_s)
        self.angular = Limiter(AxisLimits.of(
            limiter, c.min_angular_velocity_rad_s, c.max_angular_velocity_rad_s,
            c.min_angular_acceleration_rad_s2, c.max_angular_acceleration_rad_s2,
            c.min_angular_jerk_rad_s3, c.max_angular_jerk_rad_s3), self.dt_s)
        self.ramp = None
        if classic_drive is not None and classic_drive.wheel_acceleration_m_s2 > 0:
            # the plugin turns wheel speeds into surface speeds with its own radius
            self.ramp = WheelRamp(classic_drive, self.dt_s,
                                  ControllerWheels.of(controller, geometry).left_radius_m)

    def plan(self, ticks: range) -> WheelPlan:
        """The plan of ``ticks``, which must follow the ticks planned before."""
        target_v, target_w = command_targets(self.segments, ticks, self.dt_s,
                                             self.controller.cmd_vel_timeout_s)
        linear, angular = self.linear.run(target_v), self.angular.run(target_w)
        left, right = _saturated_wheels(linear, angular, self.controller, self.geometry)
        if self.ramp is not None:  # the plugin's wheels ramp: the twist is what they make
            left, right = self.ramp.run(ticks.start, left, right)
            linear, angular = (np.asarray(v, float) for v in diff_drive.body_twist(
                left, right,  # type: ignore[arg-type]  # plain arithmetic on arrays
                wheel_radius_m=self.geometry.wheel_radius_m,
                track_m=self.geometry.track_m * self.controller.wheel_separation_multiplier))
        return WheelPlan(self.dt_s, target_v, target_w, linear, angular, left, right)


def plan_wheels(segments: Sequence[CmdVel], controller: Controller, geometry: DriveGeometry,
                duration_s: float) -> WheelPlan:
    """Wheel speeds for every control tick of a run of ``duration_s``."""
    planner = WheelPlanner(segments, controller, geometry, duration_s)
    return planner.plan(range(planner.ticks))


def _saturated_wheels(linear: FloatArray, angular: FloatArray, controller: Controller,
                      geometry: DriveGeometry) -> tuple[FloatArray, FloatArray]:
    """Wheel speeds per tick, computed once per run of equal commands.

    The controller's own geometry makes them (:mod:`.controller_wheels`); the URDF's
    velocity limit saturates them.
    """
    wheels = ControllerWheels.of(controller, geometry)
    saturate = (diff_drive.saturate_per_wheel if controller.saturation == "per-wheel"
                else diff_drive.saturate_keep_curvature)
    starts = np.flatnonzero((np.diff(linear) != 0) | (np.diff(angular) != 0)) + 1
    starts = np.concatenate(([0], starts))
    lengths = np.diff(np.concatenate((starts, [len(linear)])))
    left_runs, right_runs = np.empty(len(starts)), np.empty(len(starts))
    for i, k in enumerate(starts):
        left, right = wheels.wheel_speeds(float(linear[k]), float(angular[k]))
        left_runs[i], right_runs[i] = saturate(left, right, geometry.max_wheel_speed_rad_s)
    return np.repeat(left_runs, lengths), np.repeat(right_runs, lengths)
