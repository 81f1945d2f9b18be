"""The arm controller: ``joint_trajectory`` points followed within the URDF's limits.

Like joint_trajectory_controller given positions only, the reference moves linearly from the
arm's state when the goal arrives to each point in turn, then holds the last one. Every point is
reached: a segment asked for faster than a joint's URDF velocity limit allows is stretched until
it is not, and the points after it come that much later, so the arm passes through each point
(late) instead of cutting the corner toward the next one. While the arm tracks exactly, whole
stretches are filled at once; ticks are stepped one by one only while it lags.
:class:`ArmMotion` follows a run a stretch of ticks at a time.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.scenario.definition import ArmTrajectory

FloatArray = npt.NDArray[np.float64]
_TRACKING = 1e-12  # [rad]: the joint is on its reference


@dataclass(frozen=True)
class ArmLimits:
    """Per joint, in trajectory order: position limits [rad] and velocity limits [rad/s]."""

    lower: FloatArray
    upper: FloatArray
    velocity: FloatArray


def knots(trajectory: ArmTrajectory, q0: FloatArray,
          limits: ArmLimits | None = None) -> tuple[FloatArray, FloatArray]:
    """When [s] the reference passes each point, and the points (the first row is ``q0``).

    With ``limits`` (for the trajectory's joints, in its order), each segment lasts at least as
    long as its slowest joint needs at its velocity limit; later points are delayed by what
    earlier segments were stretched.
    """
    values = np.vstack([q0] + [np.array(p.positions, dtype=float) for p in trajectory.points])
    asked = np.diff([0.0] + [p.time_from_start_s for p in trajectory.points])
    if limits is not None:
        velocity = np.where(np.isnan(limits.velocity), np.inf, limits.velocity)
        needed = np.max(np.abs(np.diff(values, axis=0)) / velocity, axis=1, initial=0.0)
        asked = np.maximum(asked, needed)
    return trajectory.start_s + np.concatenate([[0.0], np.cumsum(asked)]), values


def reference(trajectory: ArmTrajectory, q0: FloatArray, times_s: FloatArray,
              limits: ArmLimits | None = None) -> FloatArray:
    """The interpolated reference at ``times_s``, shape (len(times_s), joints).

    ``limits`` (the trajectory's joints, in its order) retime it as :func:`knots` says.
    """
    if not trajectory.points:
        return np.broadcast_to(q0, (len(times_s), len(q0))).copy()
    knots_s, values = knots(trajectory, q0, limits)
    if knots_s[1] == knots_s[0]:  # a first point at time 0 replaces the current state
        knots_s, values = knots_s[1:], values[1:]
    return np.column_stack([np.interp(times_s, knots_s, values[:, j], left=q0[j])
                            for j in range(len(q0))])


def follow(ref: FloatArray, q0: FloatArray, limits: ArmLimits, dt_s: float, *,
           clip_start: bool = True) -> FloatArray:
    """Joint positions at each tick boundary following ``ref`` (shape (n+1, joints)).

    Each tick moves every joint toward the reference by at most ``velocity * dt_s``. The
    positions start at ``q0``, moved into the limits unless ``clip_start`` is False (a run
    followed on from where an earlier stretch ended).
    """
    speed = np.where(np.isnan(limits.velocity), np.inf, limits.velocity) * dt_s
    lower = np.where(np.isnan(limits.lower), -np.inf, limits.lower)
    upper = np.where(np.isnan(limits.upper), np.inf, limits.upper)
    ref = np.clip(ref, lower, upper)
    n = len(ref) - 1
    q = np.empty_like(ref)
    q[0] = np.clip(q0, lower, upper) if clip_start else q0
    too_fast = np.flatnonzero(np.any(np.abs(np.diff(ref, axis=0)) > speed * (1 + 1e-9), axis=1))
    k = 0
    while k < n:
        if np.max(np.abs(q[k] - ref[k]), initial=0.0) <= _TRACKING:
            i = bisect.bisect_left(too_fast, k)
            j = int(too_fast[i]) if i < len(too_fast) else n
            if j > k:  # on the reference and it is slow enough: follow it exactly
                q[k + 1:j + 1] = ref[k + 1:j + 1]
                k = j
                continue
        q[k + 1] = q[k] + np.clip(ref[k + 1] - q[k], -speed, speed)
        k += 1
    return q


class ArmMotion:
    """The arm's positions over a run, a stretch of tick boundaries at a time.

    Args:
        trajectory: The scenario's goal.
        order: For each of the trajectory's joints, its column among the arm's joints.
        q0: The arm's positions when the run starts (every arm joint) [rad].
        limits: Every arm joint's limits, in the columns' order.
        dt_s: Control period [s].
    """

    def __init__(self, trajectory: ArmTrajectory, order: list[int], q0: FloatArray,
                 limits: ArmLimits, dt_s: float) -> None:
        self.trajectory, self.order, self.q0, self.limits = trajectory, order, q0, limits
        self.dt_s = dt_s
        self.q: FloatArray | None = None  # where the last stretch ended

    def advance(self, times_s: FloatArray) -> FloatArray:
        """Positions at the tick boundaries ``times_s``, shape (len(times_s), joints).

        The first boundary is the one the last stretch ended at.
        """
        q0 = self.q0
        if not self.trajectory.points:
            return np.broadcast_to(q0, (len(times_s), len(q0))).copy()
        ref = np.broadcast_to(q0, (len(times_s), len(q0))).copy()
        own = ArmLimits(self.limits.lower[self.order], self.limits.upper[self.order],
                        self.limits.velocity[self.order])
        ref[:, self.order] = reference(self.trajectory, q0[self.order], times_s, own)
        q = follow(ref, q0 if self.q is None else self.q, self.limits, self.dt_s,
                   clip_start=self.q is None)
        self.q = q[-1].copy()
        return q
