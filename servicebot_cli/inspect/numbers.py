"""Small numeric helpers shared by the summaries: clean floats and rotation angles."""

from __future__ import annotations

import numpy as np

from servicebot_cli.description.elements import Vec3
from servicebot_cli.kinematics.rotations import rpy_from_matrix


def clean(value: float) -> float:
    """``value`` without floating-point dust: 1e-17 becomes 0, 0.30000000000000004 0.3."""
    rounded = round(value, 12)
    return 0.0 if rounded == 0 else rounded


def vec3(values: np.ndarray) -> Vec3:
    """Three cleaned floats from an array of shape (3,)."""
    x, y, z = (clean(float(v)) for v in values)
    return (x, y, z)


def rpy_of(rotation: np.ndarray) -> Vec3:
    """Roll, pitch, yaw [rad] of a rotation matrix, cleaned; the same convention as ``fk``."""
    return vec3(rpy_from_matrix(rotation))
