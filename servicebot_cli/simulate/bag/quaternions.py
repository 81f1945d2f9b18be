"""Quaternions (x, y, z, w), as ROS messages carry them, for many rotations at once.

Matrices become quaternions with ``kinematics.rotations.quaternion_from_matrix``.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]


def about_axis(axis: FloatArray, angle_rad: FloatArray) -> FloatArray:
    """Quaternions of rotations by ``angle_rad`` about unit ``axis``.

    ``axis`` (..., 3) and ``angle_rad`` broadcast against each other without the axis'
    last dimension: an axis (3,) and angles (N,) give (N, 4); axes (J, 3) and angles (N, J)
    give (N, J, 4).
    """
    half = np.asarray(angle_rad) / 2.0
    s = np.sin(half)
    return np.stack((axis[..., 0] * s, axis[..., 1] * s, axis[..., 2] * s,
                     np.broadcast_to(np.cos(half), s.shape)), axis=-1)


def yaw(yaw_rad: FloatArray) -> FloatArray:
    """Quaternions of rotations about z, shape (N, 4)."""
    return about_axis(np.array([0.0, 0.0, 1.0]), yaw_rad)


def multiply(a: FloatArray, b: FloatArray) -> FloatArray:
    """Hamilton products ``a * b`` (rotation ``b`` then ``a``); (N, 4) or (4,) each."""
    ax, ay, az, aw = np.moveaxis(np.broadcast_to(a, np.broadcast_shapes(a.shape, b.shape)), -1, 0)
    bx, by, bz, bw = np.moveaxis(np.broadcast_to(b, np.broadcast_shapes(a.shape, b.shape)), -1, 0)
    return np.stack((aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz), axis=-1)
