r"""The compiled IK loop's kinematics: tool pose, world-aligned Jacobian and pose error.

A serial chain of revolute and prismatic joints is given as flat arrays (see
:mod:`~servicebot_cli.kinematics.chain_arrays`): for joint ``i``, its placement in its
parent joint ``frames[i] = [R | p]`` (shape (3, 4)), its axis in its own frame, and its kind
(:data:`REVOLUTE` or :data:`PRISMATIC`); ``frames[n]`` is the tool frame in the last joint.
The error is expressed in the root frame: :math:`e = (p_{target} - p,\ \log_3(R_{target}
R^T))`, or the position rows alone.

Compiled by numba (cached on disk after the first run), for
:mod:`~servicebot_cli.kinematics.lm_kernel`. The tests hold every function's results against
Pinocchio's. Pure.
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
