"""The most inertia a link's mass can have within its geometry: SB301 where no solid is known.

A link whose collision mesh is open (neuronbot2's lidar) has no volume to compare its inertia
with, and went unchecked: a 0.362 kg part 0.1 m across declared 6e7 kg m^2. Whatever the
shape, a mass whose every part lies within ``R`` of its centre of mass has no moment above
``m R^2``. ``R`` here is the farthest corner, from the inertial origin, of the boxes around
the link's collision and visual shapes (both: a placeholder collision sphere may be smaller
than the body), for a link that has collision shapes. Pure.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.check import values
from servicebot_cli.check.env import CheckEnv, MeshError, MeshNotFound
from servicebot_cli.kinematics.transforms import rpy_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Link, Shape
    from servicebot_cli.description.robot import RobotDescription

BEYOND = 10.0
"""How far over ``m R^2`` a moment must be to be reported: the bound holds for mass inside the
shapes drawn, and a link's drawn shapes may leave out some of its parts."""


def farthest_m(robot: RobotDescription, link: Link, env: CheckEnv,
               centre: np.ndarray) -> float | None:
    """The farthest any of the link's shapes reaches from ``centre`` [m]; None: not known.

    None for a link without collision shapes: a visual alone may be a marker (PR2's 1 mm
    sensor boxes), not the body.
    """
    if not link.collisions:
        return None
    shapes = (*link.collisions, *link.visuals)
    farthest = 0.0
    for shape in shapes:
        corners = _corners(robot, shape, env)
        if corners is None:
            return None
        farthest = max(farthest, float(np.linalg.norm(corners - centre, axis=1).max()))
    return farthest


def _corners(robot: RobotDescription, shape: Shape, env: CheckEnv) -> np.ndarray | None:
    """The 8 corners of the box around ``shape``, in the link frame; None: not known."""
    if not values.usable_shape(shape):
        return None
    geometry = shape.geometry
    if geometry.kind == "box" and geometry.size:
        half = np.abs(np.array(geometry.size, dtype=float)) / 2
        low, high = -half, half
    elif geometry.kind in ("cylinder", "sphere") and geometry.radius is not None:
        r = abs(geometry.radius)
        length = abs(geometry.length or 0.0) / 2 if geometry.kind == "cylinder" else r
        low, high = np.array([-r, -r, -length]), np.array([r, r, length])
    elif geometry.kind == "mesh" and env.load_meshes:
        try:
            info = env.mesh(robot, shape)
        except (MeshNotFound, MeshError):
            return None
        scale = np.array(geometry.scale, dtype=float)
        ends = np.array([info.lower, info.upper]) * scale
        low, high = ends.min(axis=0), ends.max(axis=0)
    else:
        return None
    corners = np.array(list(itertools.product(*zip(low, high, strict=True))))
    placed: np.ndarray = corners @ rpy_matrix(*shape.origin.rpy).T + np.array(shape.origin.xyz)
    return placed if np.all(np.isfinite(placed)) else None
