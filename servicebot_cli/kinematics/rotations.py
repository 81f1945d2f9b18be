r"""Rotations as people write them: roll-pitch-yaw and unit quaternions (x, y, z, w).

Roll-pitch-yaw follows URDF: fixed axes X, then Y, then Z,

.. math:: R = R_z(\text{yaw}) \, R_y(\text{pitch}) \, R_x(\text{roll}),

with pitch in [-pi/2, pi/2]. At pitch = +-pi/2 (gimbal lock) only roll -+ yaw is defined;
yaw is then reported as 0. Quaternions are ``(x, y, z, w)`` with ``w >= 0``.

Every function takes one matrix (3, 3) or a stack (..., 3, 3), so batch mode converts a
whole chunk of poses in one call. Pure numpy.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

AXES = ("roll", "pitch", "yaw")
_GIMBAL_COS = 1e-9  # below this cos(pitch), roll and yaw are not separable


class BadRotation(ValueError):
    """A quaternion of zero length, or a value that is not a rotation."""


def rpy_from_matrix(rotation: FloatArray) -> FloatArray:
    """Roll, pitch, yaw [rad] of rotation matrices, shape (..., 3, 3) -> (..., 3)."""
    r = np.asarray(rotation, dtype=float)
    cos_pitch = np.hypot(r[..., 0, 0], r[..., 1, 0])
    pitch = np.arctan2(-r[..., 2, 0], cos_pitch)
    locked = cos_pitch < _GIMBAL_COS
    roll = np.where(locked, np.arctan2(-r[..., 1, 2], r[..., 1, 1]),
                    np.arctan2(r[..., 2, 1], r[..., 2, 2]))
    yaw = np.where(locked, 0.0, np.arctan2(r[..., 1, 0], r[..., 0, 0]))
    return np.stack([roll, pitch, yaw], axis=-1)


def matrix_from_rpy(rpy_rad: FloatArray) -> FloatArray:
    """Rotation matrices for roll, pitch, yaw [rad], shape (..., 3) -> (..., 3, 3)."""
    a = np.asarray(rpy_rad, dtype=float)
    cr, sr = np.cos(a[..., 0]), np.sin(a[..., 0])
    cp, sp = np.cos(a[..., 1]), np.sin(a[..., 1])
    cy, sy = np.cos(a[..., 2]), np.sin(a[..., 2])
    rows = rpy_rows(cr, sr, cp, sp, cy, sy)
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def rpy_rows(cr: Any, sr: Any, cp: Any, sp: Any, cy: Any, sy: Any) -> list[list[Any]]:
    """The rows of ``Rz(yaw) @ Ry(pitch) @ Rx(roll)``, from the angles' cosines and sines.

    Floats for one matrix, arrays for many: the same products either way.
    """
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def quaternion_from_matrix(rotation: FloatArray) -> FloatArray:
    """Unit quaternions ``(x, y, z, w)``, ``w >= 0``, shape (..., 3, 3) -> (..., 4).

    Uses the largest of the four candidate denominators (Shepperd's method), so it is
    accurate for every rotation, including half turns.
    """
    r = np.asarray(rotation, dtype=float)
    m00, m11, m22 = r[..., 0, 0], r[..., 1, 1], r[..., 2, 2]
    candidates = np.stack([1 + m00 - m11 - m22, 1 - m00 + m11 - m22,
                           1 - m00 - m11 + m22, 1 + m00 + m11 + m22], axis=-1)
    best = np.argmax(candidates, axis=-1)
    q = np.empty(r.shape[:-2] + (4,))
    d21 = r[..., 2, 1] - r[..., 1, 2]
    d02 = r[..., 0, 2] - r[..., 2, 0]
    d10 = r[..., 1, 0] - r[..., 0, 1]
    s01 = r[..., 0, 1] + r[..., 1, 0]
    s02 = r[..., 0, 2] + r[..., 2, 0]
    s12 = r[..., 1, 2] + r[..., 2, 1]
    forms = [np.stack(f, axis=-1) for f in (
        (candidates[..., 0], s01, s02, d21),
        (s01, candidates[..., 1], s12, d02),
        (s02, s12, candidates[..., 2], d10),
        (d21, d02, d10, candidates[..., 3]),
    )]
    for k, form in enumerate(forms):
        chosen = best == k
        q[chosen] = form[chosen]
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    return np.where(q[..., 3:4] < 0, -q, q)


def matrix_from_quaternion(xyzw: FloatArray) -> FloatArray:
    """Rotation matrix of a quaternion ``(x, y, z, w)``, normalised first.

    Raises:
        BadRotation: The quaternion has (nearly) zero length or is not finite.
    """
    q = np.asarray(xyzw, dtype=float)
    if not np.all(np.isfinite(q)):
        raise BadRotation(f"quaternion {tuple(float(v) for v in q)} is not finite; give x y z "
                          "w as finite numbers")
    with np.errstate(over="ignore"):
        norm = float(np.linalg.norm(q))
    if not math.isfinite(norm):  # (1e308, 1e308, 0, 0): a direction, its length too large
        q = q / np.abs(q).max()
        norm = float(np.linalg.norm(q))
    if norm < 1e-9:
        raise BadRotation(f"quaternion {tuple(float(v) for v in q)} has no direction "
                          "(length 0); give x y z w with a non-zero length")
    x, y, z, w = q / norm
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def matrices_from_quaternions(xyzw: FloatArray) -> FloatArray | None:
    """Rotation matrices of many quaternions, as :func:`matrix_from_quaternion` makes each.

    The same numbers, bit for bit: each length is ``sqrt(q.dot(q))``, as ``np.linalg.norm``
    of one quaternion computes it, and the rest are the same element-wise operations.

    Args:
        xyzw: Quaternions ``(x, y, z, w)``, shape (m, 4), any length.

    Returns:
        Shape (m, 3, 3); None when one of them has (nearly) zero length or is not finite
        (:func:`matrix_from_quaternion` of that one says which).
    """
    q = np.ascontiguousarray(xyzw, dtype=np.float64)
    dot = np.ndarray.dot
    with np.errstate(over="ignore", invalid="ignore"):  # one by one then, for the message
        norm = np.sqrt(np.array([dot(row, row) for row in q]).reshape(len(q)))
    if not (np.isfinite(norm).all() and (norm >= 1e-9).all()):
        return None
    x, y, z, w = (q / norm[:, None]).T
    return np.stack([
        1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y),
    ], axis=-1).reshape(len(q), 3, 3)


def rpy_rate_rows(rpy_rad: FloatArray) -> FloatArray:
    r"""Rows mapping angular velocity (world frame) to roll, pitch, yaw rates.

    With :math:`\phi, \theta, \psi` = roll, pitch, yaw,

    .. math::
        \dot\theta = -\sin\psi\,\omega_x + \cos\psi\,\omega_y, \quad
        \dot\psi = \omega_z + \tan\theta (\cos\psi\,\omega_x + \sin\psi\,\omega_y), \quad
        \dot\phi = (\cos\psi\,\omega_x + \sin\psi\,\omega_y) / \cos\theta.

    The pitch row is defined everywhere; roll and yaw rows grow without bound at the gimbal
    lock, where the damping of the solver keeps the steps finite.

    Returns:
        Shape (3, 3): rows for roll, pitch, yaw.
    """
    _, pitch, yaw = rpy_rad
    cy, sy = math.cos(yaw), math.sin(yaw)
    cp = math.cos(pitch)
    cp = math.copysign(max(abs(cp), _GIMBAL_COS), cp)
    tp = math.sin(pitch) / cp
    return np.array([
        [cy / cp, sy / cp, 0.0],
        [-sy, cy, 0.0],
        [cy * tp, sy * tp, 1.0],
    ])


def wrap_angle(angle_rad: FloatArray | float) -> FloatArray | float:
    """Angles wrapped into [-pi, pi)."""
    return (np.asarray(angle_rad) + math.pi) % (2 * math.pi) - math.pi
