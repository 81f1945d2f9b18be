"""The diff-drive controller: timed ``cmd_vel`` in, wheel speeds per control tick out.

It follows diff_drive_controller's update: a command older than ``cmd_vel_timeout_s`` is
replaced by zero, the twist is rate-limited by the acceleration limits (so a timed-out
robot ramps to a stop), turned into wheel speeds with ``wheel_separation * multiplier``,
and the wheel speeds are saturated at the URDF's velocity limit: both sides scaled together
(curvature kept) or each wheel clipped alone (``per-wheel``, what Gazebo does).

Commands are piecewise constant, so the sequential part (rate limiting) only steps tick by
tick while a value is ramping; constant stretches are filled in one numpy operation.
"""

from __future__ import annotations

import bisect
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics import diff_drive
from servicebot_cli.kinematics.drive_geometry import DriveGeometry
from servicebot_cli.simulate.scenario.definition import CmdVel, Controller

FloatArray = npt.NDArray[np.float64]
_SETTLED = 1e-12  # a ramp this close to its target has arrived


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


def command_targets(segments: Sequence[CmdVel], ticks: int, dt_s: float,
                    timeout_s: float) -> tuple[FloatArray, FloatArray]:
    """The twist in force at each tick: the current segment's, or the last one until timeout.

    A segment publishes from ``start_s`` until ``end_s``; at ``end_s + timeout_s`` its
    command is stale and the target becomes zero.
    """
    times = np.arange(ticks) * dt_s
    linear, angular = np.zeros(ticks), np.zeros(ticks)
    for segment in segments:
        # A command sent at end_s is still fresh just before end_s + timeout_s.
        live = (times >= segment.start_s - 1e-9) & (times < segment.end_s + timeout_s - 1e-9)
        linear[live], angular[live] = segment.linear_m_s, segment.angular_rad_s
    return linear, angular


def rate_limited(target: FloatArray, max_rate: float, dt_s: float) -> FloatArray:
    """``target`` followed with :func:`diff_drive.rate_limit`, starting from zero."""
    out = np.empty_like(target)
    changes = np.flatnonzero(np.diff(target)) + 1
    value, k, n = 0.0, 0, len(target)
    while k < n:
        goal = float(target[k])
        if abs(value - goal) <= _SETTLED:  # settled: hold until the target changes
            value = goal
            nxt = changes[bisect.bisect_right(changes, k)] if len(changes) and \
                changes[-1] > k else n
            out[k:nxt] = value
            k = int(nxt)
            continue
        value = diff_drive.rate_limit(value, goal, max_rate, dt_s)
        out[k] = value
        k += 1
    return out


def plan_wheels(segments: Sequence[CmdVel], controller: Controller, geometry: DriveGeometry,
                duration_s: float) -> WheelPlan:
    """Wheel speeds for every control tick of a run of ``duration_s``."""
    dt = 1.0 / controller.update_rate_hz
    ticks = max(1, int(np.ceil(duration_s / dt - 1e-9)))
    target_v, target_w = command_targets(segments, ticks, dt, controller.cmd_vel_timeout_s)
    linear = rate_limited(target_v, controller.max_linear_acceleration_m_s2, dt)
    angular = rate_limited(target_w, controller.max_angular_acceleration_rad_s2, dt)
    left, right = _saturated_wheels(linear, angular, controller, geometry)
    return WheelPlan(dt, target_v, target_w, linear, angular, left, right)


def _saturated_wheels(linear: FloatArray, angular: FloatArray, controller: Controller,
                      geometry: DriveGeometry) -> tuple[FloatArray, FloatArray]:
    """Wheel speeds per tick, computed once per run of equal commands."""
    track = geometry.track_m * controller.wheel_separation_multiplier
    saturate = (diff_drive.saturate_per_wheel if controller.saturation == "per-wheel"
                else diff_drive.saturate_keep_curvature)
    starts = np.flatnonzero((np.diff(linear) != 0) | (np.diff(angular) != 0)) + 1
    starts = np.concatenate(([0], starts))
    lengths = np.diff(np.concatenate((starts, [len(linear)])))
    left_runs, right_runs = np.empty(len(starts)), np.empty(len(starts))
    for i, k in enumerate(starts):
        left, right = diff_drive.wheel_speeds(float(linear[k]), float(angular[k]),
                                              wheel_radius_m=geometry.wheel_radius_m,
                                              track_m=track)
        left_runs[i], right_runs[i] = saturate(left, right, geometry.max_wheel_speed_rad_s)
    return np.repeat(left_runs, lengths), np.repeat(right_runs, lengths)
