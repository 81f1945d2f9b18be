"""Homogeneous transforms from URDF origins, with numpy only (no model needed)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.elements import Pose

FloatArray = npt.NDArray[np.float64]


def rpy_matrix(roll_rad: float, pitch_rad: float, yaw_rad: float) -> FloatArray:
    """Rotation for URDF roll-pitch-yaw: ``Rz(yaw) @ Ry(pitch) @ Rx(roll)`` (fixed axes X, Y, Z)."""
    cr, sr = np.cos(roll_rad), np.sin(roll_rad)
    cp, sp = np.cos(pitch_rad), np.sin(pitch_rad)
    cy, sy = np.cos(yaw_rad), np.sin(yaw_rad)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def pose_matrix(pose: Pose) -> FloatArray:
    """4x4 transform of an ``<origin>``: child frame expressed in the parent frame."""
    transform = np.eye(4)
    transform[:3, :3] = rpy_matrix(*pose.rpy)
    transform[:3, 3] = pose.xyz
    return transform
