"""The arm controller: ``joint_trajectory`` points followed within the URDF's limits.

Like joint_trajectory_controller given positions only, the reference moves linearly from the
arm's state when the goal arrives to each point in turn, then holds the last one. Every point is
reached: a segment asked for faster than a joint's URDF velocity limit allows is stretched until
it is not, and the points after it come that much later, so the arm passes through each point
(late) instead of cutting the corner toward the next one. While the arm tracks exactly, whole
stretches are filled at once; ticks are stepped one by one only while it lags.
:class:`ArmMotion` gives a run's reference and steps; the simulator keeps the arm's state, so that
an arm held by an obstacle (:mod:`..world.blocking`) follows on from where it was held.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.mimics import Mimics
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
    earlier segments were stretched. A joint whose limit is 0 cannot move and stretches
    nothing.
    """
    values = np.vstack([q0] + [np.array(p.positions, dtype=float) for p in trajectory.points])
    asked = np.diff([0.0] + [p.time_from_start_s for p in trajectory.points])
    if limits is not None:
        # a joint without a limit, or with a limit of 0 (it cannot move: follow() holds it),
        # stretches nothing
        moves = np.nan_to_num(limits.velocity, nan=0.0) > 0.0
        velocity = np.where(moves, limits.velocity, 1.0)
        needed = np.max(np.abs(np.diff(values, axis=0)) * moves / velocity, axis=1,
                        initial=0.0)
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
    if knots_s[1] == knots_s[0]:  # a first point at time 0 that needs no time to reach
        knots_s, values = knots_s[1:], values[1:]
    return np.column_stack([np.interp(times_s, knots_s, values[:, j], left=q0[j])
                            for j in range(len(q0))])


def follow(ref: FloatArray, q0: FloatArray, limits: ArmLimits, dt_s: float, *,
           clip_start: bool = True) -> FloatArray:
    """Joint positions at each tick boundary following ``ref`` (shape (n+1, joints)).

    Each tick moves every joint toward the reference by at most ``velocity * dt_s``
    (:func:`step`). The positions start at ``q0``, moved into the limits unless
    ``clip_start`` is False (a run followed on from where an earlier stretch ended).
    """
    speed, lower, upper = _bounds(limits, dt_s)
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


def step(q: FloatArray, ref_before: FloatArray, ref_after: FloatArray, limits: ArmLimits,
         dt_s: float) -> FloatArray:
    """One tick of :func:`follow` for many rows at once, with the same bits.

    A row on its reference (``ref_before``) whose next reference is reachable in a tick takes
    it exactly; any other moves toward ``ref_after`` by at most ``velocity * dt_s``.

    Args:
        q: Positions at the tick's start, shape (P, joints).
        ref_before: The reference at the tick's start, shape (P, joints).
        ref_after: The reference at its end, shape (P, joints).
        limits: The joints' limits.
        dt_s: Control period [s].

    Returns:
        Positions at the tick's end, shape (P, joints).
    """
    speed, lower, upper = _bounds(limits, dt_s)
    before, after = np.clip(ref_before, lower, upper), np.clip(ref_after, lower, upper)
    tracking = np.max(np.abs(q - before), axis=1, initial=0.0) <= _TRACKING
    slow = ~np.any(np.abs(after - before) > speed * (1 + 1e-9), axis=1)
    return np.where((tracking & slow)[:, None], after, q + np.clip(after - q, -speed, speed))


def _bounds(limits: ArmLimits, dt_s: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The largest step per tick, the lower and the upper limits, with none as infinite."""
    speed = np.where(np.isnan(limits.velocity), np.inf, limits.velocity) * dt_s
    lower = np.where(np.isnan(limits.lower), -np.inf, limits.lower)
    upper = np.where(np.isnan(limits.upper), np.inf, limits.upper)
    return speed, lower, upper


class ArmMotion:
    """The arm controller of a run: its start, its reference over time and its steps.

    An arm without a goal stands where it started (unclipped); one with a goal starts clipped
    into its limits and follows the reference (:func:`follow`, :func:`step`). The caller
    keeps the arm's positions, so that an arm held by an obstacle follows on from where it
    was held.

    A joint that mimics another (``<mimic>``, ``mimics``) is wherever its leader puts it,
    ``multiplier * leader + offset``, at every tick, as Gazebo's ros2_control plugins hold
    it: its own limits do not hold it back.

    Args:
        trajectory: The scenario's goal.
        order: For each of the trajectory's joints, its column among the arm's joints.
        q0: The arm's positions when the run starts (every arm joint) [rad].
        limits: Every arm joint's limits, in the columns' order.
        dt_s: Control period [s].
        mimics: The arm's mimic joints, as columns.
    """

    def __init__(self, trajectory: ArmTrajectory, order: list[int], q0: FloatArray,
                 limits: ArmLimits, dt_s: float, mimics: Mimics | None = None) -> None:
        self.trajectory, self.order, self.q0, self.limits = trajectory, order, q0, limits
        self.dt_s = dt_s
        self.static = not trajectory.points
        self.mimics = mimics or Mimics()

    def start(self) -> FloatArray:
        """The arm's positions at the run's start [rad], shape (joints,)."""
        if self.static:
            return self.mimics.applied(np.array(self.q0, dtype=np.float64))
        _, lower, upper = _bounds(self.limits, self.dt_s)
        return self.mimics.applied(np.asarray(np.clip(self.q0, lower, upper),
                                              dtype=np.float64))

    def references(self, times_s: FloatArray) -> FloatArray:
        """The reference at ``times_s``, shape (len(times_s), joints)."""
        q0 = self.q0
        ref = np.broadcast_to(q0, (len(times_s), len(q0))).copy()
        if self.static:
            return ref
        own = ArmLimits(self.limits.lower[self.order], self.limits.upper[self.order],
                        self.limits.velocity[self.order])
        ref[:, self.order] = reference(self.trajectory, q0[self.order], times_s, own)
        return self.mimics.applied(ref)

    def follow(self, ref: FloatArray, q: FloatArray) -> FloatArray:
        """Positions from ``q`` following ``ref`` (the first row is ``q``), shape (n+1, joints)."""
        if self.static:
            return np.broadcast_to(q, ref.shape).copy()
        return self.mimics.applied(follow(ref, q, self.limits, self.dt_s, clip_start=False))

    def step(self, q: FloatArray, ref_before: FloatArray, ref_after: FloatArray) -> FloatArray:
        """Positions a tick after ``q`` (P, joints) toward the reference (see :func:`step`)."""
        if self.static:
            return np.broadcast_to(q, ref_after.shape).copy()
        return self.mimics.applied(step(q, ref_before, ref_after, self.limits, self.dt_s))
