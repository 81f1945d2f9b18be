r"""The IK search's inner loop, compiled: forward kinematics, Jacobian and damped steps.

A serial chain of revolute and prismatic joints is given as flat arrays (see
:mod:`~servicebot_cli.kinematics.chain_arrays`): for joint ``i``, its placement in its
parent joint ``frames[i] = [R | p]`` (shape (3, 4)), its axis in its own frame, and its kind;
``frames[n]`` is the tool frame in the last joint. Angles are plain numbers here: a
continuous joint has no limits and turns freely.

One attempt is the damped least-squares descent of :mod:`~servicebot_cli.kinematics.inverse`
(Sugihara's damping :math:`\lambda = w \|e\|^2 + \bar w`, here with :math:`w = 0.1`, which
converges in fewer restarts near the edge of the workspace; steps capped, projected into the
limits after every step, stopped when the squared error fell by less than 20 % in two
iterations), with one addition: a joint held at a limit by the projection leaves the next
step when the error pulls it further out. The error is expressed in the root frame:
:math:`e = (p_{target} - p,\ \log_3(R_{target} R^T))`, with the world-aligned Jacobian, or
the position rows alone. :func:`search` runs attempts from given starts until one converges.

The chain's kinematics and error are in :mod:`~servicebot_cli.kinematics.lm_pose`, the
damped step in :mod:`~servicebot_cli.kinematics.lm_step`. Compiled by numba (cached on disk
after the first run, so later processes only load it). The tests hold every function's
results against Pinocchio's. Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

from servicebot_cli.kinematics.lm_pose import errors
from servicebot_cli.kinematics.lm_step import damped_step

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

_DAMPING = 1e-1  # w: damping per squared error
_DAMPING_FLOOR = 1e-9  # w-bar: keeps the system positive definite at singularities
_STALL_RATIO = 0.8  # an attempt stalls when ||e||^2 fell less than this in two iterations
_NEAR2 = 1e-4  # an attempt this close (||e||^2) does not stall: it may be slow near the edge


@njit(cache=True, nogil=True)
def _hold_at_limits(jacobian: FloatArray, error: FloatArray, theta: FloatArray,
                    limits: FloatArray) -> None:
    """Zero the columns of joints at a limit that the error pulls further out.

    Such a joint would be projected back onto its limit after the step; left in, it takes
    up part of the step that the other joints then miss, and the attempt stalls.
    """
    rows, n = jacobian.shape
    for i in range(n):
        low, high = theta[i] <= limits[0, i], theta[i] >= limits[1, i]
        if low or high:
            pull = 0.0
            for r in range(rows):
                pull += jacobian[r, i] * error[r]
            if (low and pull < 0.0) or (high and pull > 0.0):
                for r in range(rows):
                    jacobian[r, i] = 0.0


@njit(cache=True, nogil=True)
def descend(frames: FloatArray, axes: FloatArray, kinds: IntArray, limits: FloatArray,
            target: FloatArray, rows: int, tolerances: FloatArray, max_iterations: int,
            theta: FloatArray) -> tuple[bool, float, int]:
    """One attempt from ``theta``; ``theta`` ends as the attempt's best configuration.

    Returns:
        Converged, the best squared error, iterations used.
    """
    n = kinds.shape[0]
    error, jacobian, step = np.empty(rows), np.empty((6, n)), np.empty(n)
    pose, scratch = np.empty((3, 4)), np.empty((3, 3))
    small = min(rows, n)
    gram, solved = np.empty((small, small)), np.empty(small)
    best = theta.copy()
    best_err2 = math.inf
    earlier = previous = math.inf
    iteration = 0
    for iteration in range(1, max_iterations + 1):
        position, angle = errors(frames, axes, kinds, theta, target, error, jacobian, pose,
                                 scratch)
        err2 = 0.0
        for r in range(rows):
            err2 += error[r] * error[r]
        if err2 < best_err2:
            best[:] = theta
            best_err2 = err2
            if position <= tolerances[0] and angle <= tolerances[1]:
                return True, err2, iteration
        if err2 > _STALL_RATIO * earlier and err2 > _NEAR2:
            break
        earlier, previous = previous, err2
        _hold_at_limits(jacobian[:rows], error, theta, limits)
        damped_step(jacobian[:rows], error, _DAMPING * err2 + _DAMPING_FLOOR, step, gram,
                    solved)
        for i in range(n):
            theta[i] = min(max(theta[i] + step[i], limits[0, i]), limits[1, i])
    theta[:] = best
    return False, best_err2, iteration


@njit(cache=True, nogil=True)
def search(frames: FloatArray, axes: FloatArray, kinds: IntArray, limits: FloatArray,
           target: FloatArray, rows: int, tolerances: FloatArray, max_iterations: int,
           seed: FloatArray, unit: FloatArray,
           out: FloatArray) -> tuple[int, bool, int, float]:
    """Attempts from ``seed`` (when it has n values), then from each row of ``unit``.

    The search stops at the first attempt that converges. ``limits`` (4, n): lower and upper
    limits, then the range random starts come from; a row of ``unit`` (uniform in [0, 1))
    maps into that range.

    Returns:
        Attempts made; whether the last one converged (``out`` holds its answer; otherwise
        ``out`` holds the best try of all); iterations used; the squared error of ``out``.
    """
    n = kinds.shape[0]
    theta = np.empty(n)
    best_err2 = math.inf
    used = 0
    first = 1 if seed.shape[0] == n else 0
    for k in range(unit.shape[0] + first):
        if k < first:
            theta[:] = seed
        else:
            for i in range(n):
                theta[i] = limits[2, i] + (limits[3, i] - limits[2, i]) * unit[k - first, i]
        converged, err2, iterations = descend(frames, axes, kinds, limits, target, rows,
                                              tolerances, max_iterations, theta)
        used += iterations
        if converged:
            out[:] = theta
            return k + 1, True, used, err2
        if err2 < best_err2:
            best_err2 = err2
            out[:] = theta
    return unit.shape[0] + first, False, used, best_err2
