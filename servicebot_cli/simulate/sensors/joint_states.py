"""Joint states: every movable joint's position and velocity, as joint_state_broadcaster.

Wheel joints turn with their side's speed (times their axis sign) and their positions are
not wrapped; arm joints come from the trajectory follower. Within a control tick speeds are
constant, so positions between tick boundaries are interpolated exactly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class JointStates:
    """JointState messages: ``positions``/``velocities`` (N, joints) in ``names`` order."""

    names: tuple[str, ...]
    times_s: FloatArray
    positions: FloatArray
    velocities: FloatArray


def at_times(names: tuple[str, ...], positions: FloatArray, dt_s: float,
             times_s: FloatArray, first_tick: int = 0) -> JointStates:
    """Sample joint positions given at tick boundaries at ``times_s``.

    ``positions`` (n+1, joints) are at the boundaries of ticks ``first_tick`` ..
    ``first_tick + n``; times outside them are clamped to them.
    """
    n = len(positions) - 1
    velocity_per_tick = np.diff(positions, axis=0) / dt_s
    k = np.clip(np.floor(times_s / dt_s + 1e-9).astype(np.int64) - first_tick, 0, n - 1)
    tau = np.clip(times_s - (k + first_tick) * dt_s, 0.0, dt_s)[:, None]
    return JointStates(names, times_s, positions[k] + velocity_per_tick[k] * tau,
                       velocity_per_tick[k])
