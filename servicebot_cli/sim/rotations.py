"""Quaternions (x, y, z, w), as ROS messages carry them, for many rotations at once."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]


def from_matrix(rotation: FloatArray) -> FloatArray:
    """Quaternion of a rotation matrix (3, 3), with w >= 0."""
    m = rotation
    w = np.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2.0
    x = np.copysign(np.sqrt(max(0.0, 1.0 + m[0, 0] - m[1, 1] - m[2, 2])) / 2.0, m[2, 1] - m[1, 2])
    y = np.copysign(np.sqrt(max(0.0, 1.0 - m[0, 0] + m[1, 1] - m[2, 2])) / 2.0, m[0, 2] - m[2, 0])
    z = np.copysign(np.sqrt(max(0.0, 1.0 - m[0, 0] - m[1, 1] + m[2, 2])) / 2.0, m[1, 0] - m[0, 1])
    q = np.array([x, y, z, w])
    return q / np.linalg.norm(q)


def about_axis(axis: FloatArray, angle_rad: FloatArray) -> FloatArray:
    """Quaternions of rotations by ``angle_rad`` (N,) about unit ``axis`` (3,), shape (N, 4)."""
    half = np.asarray(angle_rad) / 2.0
    s = np.sin(half)
    return np.column_stack((axis[0] * s, axis[1] * s, axis[2] * s, np.cos(half)))


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
