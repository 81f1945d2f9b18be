"""Small numeric helpers shared by the summaries: clean floats and rotation angles."""

from __future__ import annotations

import math

import numpy as np

from servicebot_cli.description.elements import Vec3


def clean(value: float) -> float:
    """``value`` without floating-point dust: 1e-17 becomes 0, 0.30000000000000004 0.3."""
    rounded = round(value, 12)
    return 0.0 if rounded == 0 else rounded


def vec3(values: np.ndarray) -> Vec3:
    """Three cleaned floats from an array of shape (3,)."""
    x, y, z = (clean(float(v)) for v in values)
    return (x, y, z)


def rpy_of(rotation: np.ndarray) -> Vec3:
    """Roll, pitch, yaw [rad] of a rotation matrix, URDF convention ``Rz(y) Ry(p) Rx(r)``."""
    pitch = math.atan2(-rotation[2, 0], math.hypot(rotation[0, 0], rotation[1, 0]))
    if math.cos(pitch) < 1e-9:  # gimbal lock: put all of the rotation in yaw
        return (0.0, clean(pitch), clean(math.atan2(-rotation[0, 1], rotation[1, 1])))
    roll = math.atan2(rotation[2, 1], rotation[2, 2])
    yaw = math.atan2(rotation[1, 0], rotation[0, 0])
    return (clean(roll), clean(pitch), clean(yaw))
