"""Homogeneous transforms from URDF origins, with numpy only (no model needed)."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.elements import Pose
from servicebot_cli.kinematics.rotations import rpy_rows

FloatArray = npt.NDArray[np.float64]


def rpy_matrix(roll_rad: float, pitch_rad: float, yaw_rad: float) -> FloatArray:
    """Rotation for URDF roll-pitch-yaw: ``Rz(yaw) @ Ry(pitch) @ Rx(roll)`` (fixed axes X, Y, Z).

    One matrix, the same bits as :func:`~servicebot_cli.kinematics.rotations.matrix_from_rpy`
    gives (numpy's sine and cosine, the same products in the same order) in a tenth of the
    time: ``check`` places every collision shape and inertial with it.
    """
    cr, sr = float(np.cos(roll_rad)), float(np.sin(roll_rad))
    cp, sp = float(np.cos(pitch_rad)), float(np.sin(pitch_rad))
    cy, sy = float(np.cos(yaw_rad)), float(np.sin(yaw_rad))
    return np.array(rpy_rows(cr, sr, cp, sp, cy, sy))


def pose_matrix(pose: Pose) -> FloatArray:
    """4x4 transform of an ``<origin>``: child frame expressed in the parent frame."""
    transform = np.eye(4)
    transform[:3, :3] = rpy_matrix(*pose.rpy)
    transform[:3, 3] = pose.xyz
    return transform


def planar_matrix(x_m: float, y_m: float, yaw_rad: float, z_m: float = 0.0) -> FloatArray:
    """4x4 transform of a frame at ``(x, y)``, turned by ``yaw`` about z, ``z_m`` up."""
    c, s = math.cos(yaw_rad), math.sin(yaw_rad)
    return np.array([[c, -s, 0.0, x_m], [s, c, 0.0, y_m], [0.0, 0.0, 1.0, z_m],
                     [0.0, 0.0, 0.0, 1.0]])
