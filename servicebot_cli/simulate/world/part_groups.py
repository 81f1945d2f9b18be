r"""Bounds of the robot's parts a group at a time: the parts fixed on the base, the moving ones.

A group's sphere, centre :math:`m` and radius :math:`R`, holds the bounding sphere of each of
its parts (centre :math:`c_i`, radius :math:`r_i`, :math:`|c_i - m| + r_i \le R`). A point's
distance to an obstacle changes no faster than the point moves, so every part's bound is at
least the group's:

.. math:: d(c_i, \text{obstacle}) - r_i \ge d(m, \text{obstacle}) - R

A part's sphere is loose around a flat box; where it leaves a pair open, the part's box (the
box around a cylinder, sphere or mesh) and the obstacle's box (around a cylinder or mesh),
both seen in the obstacle's frame, bound it closer (:func:`box_bounds`).

Most poses of a run are far from most obstacles: two bounds per pose and obstacle (one per
group) clear them, and the parts are bounded one by one only where a group's bound does not.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import RobotShape

if TYPE_CHECKING:
    from servicebot_cli.simulate.world.contacts import Obstacle

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
MARGIN_M = 1e-9
"""A group bound above a threshold by more than this clears its parts' bounds in floating
point too (their rounding differs from the group's by about 1e-16 m)."""
SLACK_M = 1e-6
"""Taken off a box bound, which can come as close as it likes to the true distance: Coal's
answers, exact to far better than this, then never fall below it."""


def part_groups(shape: RobotShape) -> list[IntArray]:
    """The parts' indices: those fixed on the base, then the moving ones (no empty group)."""
    fixed = shape.fixed()
    groups = [np.flatnonzero(fixed), np.flatnonzero(~fixed)]
    return [g.astype(np.int64) for g in groups if len(g)]


def group_bounds(world: Sequence[Obstacle], centres: FloatArray, radius_m: FloatArray,
                 groups: Sequence[IntArray]) -> FloatArray:
    """Lower bound of every part-obstacle distance of each group, shape (P, G, O).

    Args:
        world: The obstacles, O of them.
        centres: Each part's centre in the world at each pose, shape (P, S, 3).
        radius_m: Each part's bounding radius, shape (S,).
        groups: The parts of each group, G of them.
    """
    out = np.empty((len(centres), len(groups), len(world)))
    for g, members in enumerate(groups):
        inside = centres[:, members]  # (P, k, 3)
        middle = (inside.min(axis=1) + inside.max(axis=1)) / 2
        offset = inside - middle[:, None]
        reach = np.sqrt(np.einsum("pki,pki->pk", offset, offset)) + radius_m[members]
        radius = reach.max(axis=1)
        points = [np.ascontiguousarray(middle[:, i]) for i in range(3)]
        for o, obstacle in enumerate(world):
            out[:, g, o] = obstacle.point_distance_xyz(points) - radius
    return out


def part_bounds(obstacle: Obstacle, centres: FloatArray, radius_m: FloatArray) -> FloatArray:
    """Lower bound of the distance from parts to ``obstacle``, shape (P, k).

    Args:
        obstacle: The obstacle.
        centres: The parts' centres in the world, shape (P, k, 3).
        radius_m: Their bounding radii, shape (k,).
    """
    points = [np.ascontiguousarray(centres[..., i]) for i in range(3)]
    return obstacle.point_distance_xyz(points) - radius_m


def box_bounds(obstacle: Obstacle, centres: FloatArray, rotations: FloatArray,
               half_m: FloatArray) -> FloatArray:
    r"""Lower bound of the distance from boxes to ``obstacle``, shape (n,).

    In the obstacle's frame a box (centre :math:`c`, rotation :math:`M`, half sizes
    :math:`h`) lies within the axis-aligned box of half sizes :math:`|M| h`; the distance
    between that box and the obstacle's is :math:`\|\max(|c| - h_o - |M| h, 0)\|`.

    Args:
        obstacle: The obstacle (its box).
        centres: The boxes' centres in the world, shape (n, 3).
        rotations: Their rotations in the world, shape (n, 3, 3).
        half_m: Their half sizes, shape (n, 3).
    """
    local = (centres - obstacle.center_m) @ obstacle.rotation
    turned = np.abs(np.einsum("ji,njk->nik", obstacle.rotation, rotations))
    extent = np.einsum("nik,nk->ni", turned, half_m)
    gap = np.maximum(np.abs(local) - obstacle.half_m - extent, 0.0)
    return np.asarray(np.sqrt(np.einsum("ni,ni->n", gap, gap)), dtype=np.float64)
