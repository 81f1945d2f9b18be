r"""Rays against the robot's own collision parts, posed differently in each batch.

The LIDAR and the camera see the robot they stand on. A ray :math:`o + t d` is moved into
each part's frame (:math:`R^T (o - c)`, :math:`R^T d`) and intersected in closed form: the
slab method for boxes, a quadratic and two caps for cylinders, a quadratic for spheres.
A ray that starts inside a part does not see it, as with Gazebo's ray sensor inside its
own link.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world.raycast import box_entry, cylinder_entry

FloatArray = npt.NDArray[np.float64]


def cast_parts(parts: Sequence[Part], transforms: FloatArray, origins: FloatArray,
               directions: FloatArray) -> FloatArray:
    """Distance along each ray to the first part it enters [m], inf for none.

    Args:
        parts: The parts, S of them.
        transforms: ``transform_part_to_frame`` per batch, shape (B, S, 4, 4).
        origins: Ray origins in that frame, shape (B, R, 3) or (R, 3) for every batch.
        directions: Unit directions, same shape as ``origins``.

    Returns:
        Distances, shape (B, R).
    """
    batches, rays = transforms.shape[0], origins.shape[-2]
    best = np.full((batches, rays), np.inf)
    for i, part in enumerate(parts):
        rotation, centre = transforms[:, i, :3, :3], transforms[:, i, :3, 3]
        # local = R^T (o - c): einsum over the rotation's rows
        shifted = origins - centre[:, None, :]
        o = [np.einsum("brj,bj->br", shifted, rotation[:, :, k]) for k in range(3)]
        spec = "rj,bj->br" if directions.ndim == 2 else "brj,bj->br"
        d = [np.einsum(spec, directions, rotation[:, :, k]) for k in range(3)]
        if part.kind == "box":
            hit = box_entry(o, d, part.half_m)
        elif part.kind == "cylinder":
            hit = cylinder_entry(o, d, part.half_m)
        else:
            hit = sphere_entry(o, d, float(part.half_m[0]))
        np.minimum(best, hit, out=best)
    return best


def sphere_entry(o: list[FloatArray], d: list[FloatArray], radius: float) -> FloatArray:
    """Entry distance into a sphere of ``radius`` centred at the origin."""
    b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2]
    c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - radius**2
    disc = b * b - c
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return np.where((disc >= 0) & (c > 0) & (t >= 0), t, np.inf)
