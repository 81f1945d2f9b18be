r"""diff_drive_controller's speed limiter: jerk, then acceleration, then velocity.

Each control tick the controller limits the command :math:`v` against the two commands it
sent before, :math:`v_0` and :math:`v_1` (already limited), in this order:

.. math::
   v &\leftarrow v_0 + (v_0 - v_1) + \mathrm{clamp}\big((v - v_0) - (v_0 - v_1),
        2 j_{min} \Delta t^2, 2 j_{max} \Delta t^2\big) \\
   v &\leftarrow v_0 + \mathrm{clamp}(v - v_0, a_{min} \Delta t, a_{max} \Delta t) \\
   v &\leftarrow \mathrm{clamp}(v, v_{min}, v_{max})

(ros2_controllers' ``SpeedLimiter::limit``; a limit that is off is infinite). gz-sim's DiffDrive
system runs gz-math's ``SpeedLimiter`` instead (gz-math ``src/SpeedLimiter.cc``): the same three
clamps, but the jerk bound is :math:`j \Delta t^2` (no factor 2) and an unset minimum stays
:math:`-\infty` (:meth:`AxisLimits.gz`). Because the
ramp starts from the last *limited* command, a command far above the velocity limit stops
as soon as the limit allows, instead of ramping down from the unlimited value.
While the command and the output hold still, whole stretches are filled at once.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
DIFF_DRIVE_CONTROLLER, GZ_MATH = "diff_drive_controller", "gz-math"
"""Whose speed limiter a base runs: ros2_controllers' or gz-math's (gz-sim's DiffDrive)."""


@dataclass(frozen=True)
class AxisLimits:
    """Limits of one axis; infinite where the controller has none."""

    min_velocity: float = -math.inf
    max_velocity: float = math.inf
    min_acceleration: float = -math.inf
    max_acceleration: float = math.inf
    min_jerk: float = -math.inf
    max_jerk: float = math.inf
    jerk_dt2: float = 2.0
    r"""The jerk bounds' factor of :math:`\Delta t^2`: 2 in ros2_controllers, 1 in gz-math."""

    @classmethod
    def mirrored(cls, min_velocity: float, max_velocity: float, min_acceleration: float,
                 max_acceleration: float, min_jerk: float, max_jerk: float) -> AxisLimits:
        """Limits where an unset minimum (-inf) mirrors a set maximum, as the controller does."""
        def low(minimum: float, maximum: float) -> float:
            return -maximum if minimum == -math.inf and math.isfinite(maximum) else minimum

        return cls(low(min_velocity, max_velocity), max_velocity,
                   low(min_acceleration, max_acceleration), max_acceleration,
                   low(min_jerk, max_jerk), max_jerk)

    @classmethod
    def gz(cls, min_velocity: float, max_velocity: float, min_acceleration: float,
           max_acceleration: float, min_jerk: float, max_jerk: float) -> AxisLimits:
        """gz-math's limits: an unset minimum stays -inf, whatever the maximum.

        gz-math's ``SpeedLimiter`` starts every bound at +-infinity and gz-sim's
        ``DiffDrive::Configure`` only calls ``SetMin*`` for a ``<min_*>`` tag it finds.
        """
        return cls(min_velocity, max_velocity, min_acceleration, max_acceleration,
                   min_jerk, max_jerk, jerk_dt2=1.0)

    @classmethod
    def of(cls, limiter: str, *bounds: float) -> AxisLimits:
        """``bounds`` (min, max of velocity, acceleration, jerk) as ``limiter`` reads them."""
        min_v, max_v, min_a, max_a, min_j, max_j = bounds
        make = cls.gz if limiter == GZ_MATH else cls.mirrored
        return make(min_v, max_v, min_a, max_a, min_j, max_j)

    def step(self, v: float, v0: float, v1: float, dt_s: float) -> float:
        """One tick of the limiter: the command ``v`` after ``v0`` and ``v1`` were sent."""
        if math.isfinite(self.min_jerk) or math.isfinite(self.max_jerk):
            dv0 = v0 - v1
            dt2 = self.jerk_dt2 * dt_s * dt_s
            v = v0 + dv0 + min(max(v - v0 - dv0, self.min_jerk * dt2), self.max_jerk * dt2)
        v = v0 + min(max(v - v0, self.min_acceleration * dt_s), self.max_acceleration * dt_s)
        return min(max(v, self.min_velocity), self.max_velocity)


class Limiter:
    """One axis of the limiter, run a stretch of ticks at a time (it remembers ``v0``, ``v1``)."""

    def __init__(self, limits: AxisLimits, dt_s: float) -> None:
        self.limits, self.dt_s = limits, dt_s
        self.v0 = self.v1 = 0.0  # the robot starts at rest

    def run(self, target: FloatArray) -> FloatArray:
        """The commands sent at the next ``len(target)`` ticks for the targets ``target``."""
        limits, dt_s = self.limits, self.dt_s
        out = np.empty_like(target)
        changes = np.flatnonzero(np.diff(target)) + 1
        v0, v1 = self.v0, self.v1
        k, n = 0, len(target)
        while k < n:
            goal = float(target[k])
            v = limits.step(goal, v0, v1, dt_s)
            out[k] = v
            if v == v0 and limits.step(goal, v, v, dt_s) == v:
                # settled: from here the same output until the target changes
                i = bisect.bisect_right(changes, k)
                stop = int(changes[i]) if i < len(changes) else n
                out[k:stop] = v
                v0 = v1 = v
                k = stop
                continue
            v1, v0 = v0, v
            k += 1
        self.v0, self.v1 = v0, v1
        return out


def limited(target: FloatArray, limits: AxisLimits, dt_s: float) -> FloatArray:
    """The commands sent at each tick for the targets ``target``, starting from rest."""
    return Limiter(limits, dt_s).run(target)
