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

Compiled by numba (cached on disk after the first run, so later processes only load it).
The tests hold every function's results against Pinocchio's. Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

REVOLUTE = 0
PRISMATIC = 1
_DAMPING = 1e-1  # w: damping per squared error
_DAMPING_FLOOR = 1e-9  # w-bar: keeps the system positive definite at singularities
_MAX_STEP = 2.0  # largest step norm [rad or m]
_STALL_RATIO = 0.8  # an attempt stalls when ||e||^2 fell less than this in two iterations
_NEAR2 = 1e-4  # an attempt this close (||e||^2) does not stall: it may be slow near the edge


@njit(cache=True, nogil=True, inline="always")
def _rotate(pose: FloatArray, by: FloatArray) -> None:
    """``pose[:, :3] = pose[:, :3] @ by[:, :3]`` in place (no BLAS: too slow at this size)."""
    for r in range(3):
        a, b, c = pose[r, 0], pose[r, 1], pose[r, 2]
        for k in range(3):
            pose[r, k] = a * by[0, k] + b * by[1, k] + c * by[2, k]


@njit(cache=True, nogil=True, inline="always")
def _advance(pose: FloatArray, by: FloatArray) -> None:
    """``pose = pose @ by`` for ``[R | p]`` poses, in place."""
    for r in range(3):
        pose[r, 3] += pose[r, 0] * by[0, 3] + pose[r, 1] * by[1, 3] + pose[r, 2] * by[2, 3]
    _rotate(pose, by)


@njit(cache=True, nogil=True)
def tool_pose(frames: FloatArray, axes: FloatArray, kinds: IntArray, theta: FloatArray,
              pose: FloatArray, jacobian: FloatArray, turn: FloatArray) -> None:
    """Tool pose ``pose = [R | p]`` (3, 4) in the root frame, and the world-aligned Jacobian.

    ``jacobian`` (6, n): rows 0-2 the tool's linear velocity, rows 3-5 its angular velocity
    in the root frame, per unit joint velocity. ``turn`` (3, 3) is scratch space.
    """
    n = kinds.shape[0]
    pose[:, :] = 0.0
    pose[0, 0] = pose[1, 1] = pose[2, 2] = 1.0
    for i in range(n):
        _advance(pose, frames[i])
        ax, ay, az = axes[i, 0], axes[i, 1], axes[i, 2]
        for r in range(3):  # for now: the joint's origin above its world axis
            jacobian[r, i] = pose[r, 3]
            jacobian[3 + r, i] = pose[r, 0] * ax + pose[r, 1] * ay + pose[r, 2] * az
        if kinds[i] == REVOLUTE:
            c, s = math.cos(theta[i]), math.sin(theta[i])
            t = 1.0 - c
            turn[0, 0], turn[0, 1], turn[0, 2] = t * ax * ax + c, t * ax * ay - s * az, \
                t * ax * az + s * ay
            turn[1, 0], turn[1, 1], turn[1, 2] = t * ax * ay + s * az, t * ay * ay + c, \
                t * ay * az - s * ax
            turn[2, 0], turn[2, 1], turn[2, 2] = t * ax * az - s * ay, t * ay * az + s * ax, \
                t * az * az + c
            _rotate(pose, turn)
        else:
            for r in range(3):
                pose[r, 3] += jacobian[3 + r, i] * theta[i]
    _advance(pose, frames[n])
    for i in range(n):
        wx, wy, wz = jacobian[3, i], jacobian[4, i], jacobian[5, i]
        if kinds[i] == REVOLUTE:  # w x (p_tool - p_joint)
            dx, dy, dz = pose[0, 3] - jacobian[0, i], pose[1, 3] - jacobian[1, i], \
                pose[2, 3] - jacobian[2, i]
            jacobian[0, i] = wy * dz - wz * dy
            jacobian[1, i] = wz * dx - wx * dz
            jacobian[2, i] = wx * dy - wy * dx
        else:
            jacobian[0, i], jacobian[1, i], jacobian[2, i] = wx, wy, wz
            jacobian[3, i] = jacobian[4, i] = jacobian[5, i] = 0.0


@njit(cache=True, nogil=True)
def rotation_error(target: FloatArray, pose: FloatArray, out: FloatArray,
                   m: FloatArray) -> float:
    r"""``out[3:6] = log3(R_target R^T)`` (the root-frame rotation vector); returns its angle.

    The angle is :math:`\operatorname{atan2}(\sin, \cos)`, exact near 0 and near pi.
    ``m`` (3, 3) is scratch space.
    """
    for r in range(3):
        for c in range(3):
            m[r, c] = target[r, 0] * pose[c, 0] + target[r, 1] * pose[c, 1] \
                + target[r, 2] * pose[c, 2]
    vx, vy, vz = m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]
    cosine = 0.5 * (m[0, 0] + m[1, 1] + m[2, 2] - 1.0)
    sine = 0.5 * math.sqrt(vx * vx + vy * vy + vz * vz)
    angle = math.atan2(sine, cosine)
    if angle < 1e-5:
        k = 0.5 + angle * angle / 12.0
        out[3], out[4], out[5] = k * vx, k * vy, k * vz
    elif angle < 3.0:
        k = 0.5 * angle / sine
        out[3], out[4], out[5] = k * vx, k * vy, k * vz
    else:  # near pi: the axis from the symmetric part, its sign from the skew part
        scale = 1.0 / (2.0 * (1.0 - cosine))  # (m + m^T) / 2 = c I + (1 - c) n n^T
        k = 0
        if m[1, 1] > m[k, k]:
            k = 1
        if m[2, 2] > m[k, k]:
            k = 2
        axis = np.empty(3)
        axis[k] = math.sqrt(max(0.0, (m[k, k] - cosine) * 2.0 * scale))
        for j in range(3):
            if j != k:
                axis[j] = (m[k, j] + m[j, k]) * scale / axis[k]
        if axis[0] * vx + axis[1] * vy + axis[2] * vz < 0.0:
            axis = -axis
        norm = math.sqrt(axis[0] ** 2 + axis[1] ** 2 + axis[2] ** 2)
        for j in range(3):
            out[3 + j] = angle * axis[j] / norm
    return angle


@njit(cache=True, nogil=True)
def _solve_spd(a: FloatArray, b: FloatArray) -> None:
    """Solve ``a x = b`` in place (``b`` becomes ``x``) by Cholesky; ``a`` is overwritten."""
    n = b.shape[0]
    for j in range(n):
        d = a[j, j]
        for k in range(j):
            d -= a[j, k] * a[j, k]
        d = math.sqrt(d)
        a[j, j] = d
        for i in range(j + 1, n):
            s = a[i, j]
            for k in range(j):
                s -= a[i, k] * a[j, k]
            a[i, j] = s / d
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= a[i, k] * b[k]
        b[i] = s / a[i, i]
    for i in range(n - 1, -1, -1):
        s = b[i]
        for k in range(i + 1, n):
            s -= a[k, i] * b[k]
        b[i] = s / a[i, i]


@njit(cache=True, nogil=True)
def _gram(matrix: FloatArray, damping: float, out: FloatArray) -> None:
    """``out = M M^T + damping I`` for a small ``M`` (``out`` is (rows, rows))."""
    rows, cols = matrix.shape
    for i in range(rows):
        for j in range(i + 1):
            s = 0.0
            for k in range(cols):
                s += matrix[i, k] * matrix[j, k]
            out[i, j] = out[j, i] = s
        out[i, i] += damping


@njit(cache=True, nogil=True)
def _step(jacobian: FloatArray, error: FloatArray, damping: float, step: FloatArray,
          gram: FloatArray, solved: FloatArray) -> None:
    """The damped least-squares step, capped at :data:`_MAX_STEP`, into ``step``.

    ``gram`` (k, k) and ``solved`` (k,), k the smaller side of the Jacobian, are scratch.
    """
    rows, cols = jacobian.shape
    if rows <= cols:  # J^T (J J^T + lambda I)^-1 e
        _gram(jacobian, damping, gram)
        solved[:] = error
        _solve_spd(gram, solved)
        for c in range(cols):
            step[c] = 0.0
            for r in range(rows):
                step[c] += jacobian[r, c] * solved[r]
    else:  # (J^T J + lambda I)^-1 J^T e
        _gram(jacobian.T, damping, gram)
        for c in range(cols):
            step[c] = 0.0
            for r in range(rows):
                step[c] += jacobian[r, c] * error[r]
        _solve_spd(gram, step)
    size2 = 0.0
    for i in range(cols):
        size2 += step[i] * step[i]
    if size2 > _MAX_STEP * _MAX_STEP:
        scale = _MAX_STEP / math.sqrt(size2)
        for i in range(cols):
            step[i] *= scale


@njit(cache=True, nogil=True)
def errors(frames: FloatArray, axes: FloatArray, kinds: IntArray, theta: FloatArray,
           target: FloatArray, error: FloatArray, jacobian: FloatArray, pose: FloatArray,
           scratch: FloatArray) -> tuple[float, float]:
    """Fill ``error`` (rows,), ``jacobian`` (6, n) and ``pose`` (3, 4) at ``theta``.

    Rows are 6 (full pose) or 3 (position only: the first three rows count).
    ``scratch`` (3, 3) is scratch space.

    Returns:
        The position error [m] and the orientation error [rad] (0 for position only).
    """
    tool_pose(frames, axes, kinds, theta, pose, jacobian, scratch)
    for r in range(3):
        error[r] = target[r, 3] - pose[r, 3]
    position = math.sqrt(error[0] ** 2 + error[1] ** 2 + error[2] ** 2)
    if error.shape[0] == 3:
        return position, 0.0
    return position, rotation_error(target, pose, error, scratch)


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
        _step(jacobian[:rows], error, _DAMPING * err2 + _DAMPING_FLOOR, step, gram, solved)
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
