r"""A camera's rays against one of the robot's mesh parts, in numpy: the compiled walk's numbers.

The numpy path's counterpart of :func:`~servicebot_cli.simulate.sensors.camera_bvh.mesh_entry`:
the rays are moved into the part's frame (:math:`R^T (o - c)`, :math:`R^T d`) and met with
every triangle of the part by the Moller-Trumbore test, written in the same order of
operations, so each distance is the same number. The nearest triangle (ties: the lowest
numbered) is the entry if it faces the ray; if it faces away, the ray starts inside and
enters nothing. Only rays through the part's bounding sphere are tested. Pure.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.sensors.camera_mesh import Triangles
from servicebot_cli.simulate.sensors.camera_rays import into_frame

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_PAIRS = 1_000_000  # ray-triangle pairs at a time


def mesh_part_hits(transform: FloatArray, radius_m: float, origin: FloatArray,
                   d: list[FloatArray], triangles: Triangles, start: int,
                   stop: int) -> tuple[FloatArray, IntArray]:
    """Entry distance along each ray into a mesh part [m] (inf: none), and the triangle.

    Args:
        transform: ``transform_part_to_world``, (4, 4).
        radius_m: Radius of the sphere about the part's origin that holds it.
        origin: The rays' common origin in the world, (3,).
        d: The rays' unit directions, x, y and z columns.
        triangles: Every mesh part's triangles, each in its part's frame.
        start: The part's first triangle.
        stop: One past its last.

    Returns:
        Distance (N,) and triangle (N,), -1 where none.
    """
    o, local = into_frame(transform, origin, d)
    distance = np.full(len(d[0]), np.inf)
    found = np.full(len(d[0]), -1, np.int64)
    reach = radius_m * (1.0 + 1e-9) + 1e-12
    square = o[0] * o[0] + o[1] * o[1] + o[2] * o[2]
    along = o[0] * local[0] + o[1] * local[1] + o[2] * local[2]
    rays = np.flatnonzero((square <= reach * reach)
                          | ((along < 0.0) & (square - along * along <= reach * reach)))
    span = slice(start, stop)
    corner, e1, e2 = triangles.corner[span], triangles.edge_1[span], triangles.edge_2[span]
    s = [o[i] - corner[:, i] for i in range(3)]
    q = [s[1] * e1[:, 2] - s[2] * e1[:, 1], s[2] * e1[:, 0] - s[0] * e1[:, 2],
         s[0] * e1[:, 1] - s[1] * e1[:, 0]]
    numerator_t = e2[:, 0] * q[0] + e2[:, 1] * q[1] + e2[:, 2] * q[2]
    step = max(1, _PAIRS // max(1, stop - start))
    for first in range(0, len(rays), step):
        chosen = rays[first:first + step]
        d0, d1, d2 = (local[i][chosen, None] for i in range(3))
        p = [d1 * e2[:, 2] - d2 * e2[:, 1], d2 * e2[:, 0] - d0 * e2[:, 2],
             d0 * e2[:, 1] - d1 * e2[:, 0]]
        det = e1[:, 0] * p[0] + e1[:, 1] * p[1] + e1[:, 2] * p[2]
        with np.errstate(divide="ignore", invalid="ignore"):
            u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det
            v = (d0 * q[0] + d1 * q[1] + d2 * q[2]) / det
            t = numerator_t / det
        hit = (np.abs(det) >= 1e-15) & (u >= 0.0) & (u <= 1.0) & (v >= 0.0) \
            & (u + v <= 1.0) & (t >= 0.0)
        t = np.where(hit, t, np.inf)
        nearest = np.argmin(t, axis=1)
        rows = np.arange(len(chosen))
        entering = np.isfinite(t[rows, nearest]) & (det[rows, nearest] > 0.0)
        distance[chosen] = np.where(entering, t[rows, nearest], np.inf)
        found[chosen] = np.where(entering, start + nearest, -1)
    return distance, found


def mesh_part_normals(transform: FloatArray, triangles: Triangles,
                      found: IntArray) -> FloatArray:
    """The world unit normal of each of the part's triangles ``found``, (n, 3)."""
    normal, rotation = triangles.normal[found], transform[:3, :3]
    return np.column_stack([rotation[r, 0] * normal[:, 0] + rotation[r, 1] * normal[:, 1]
                            + rotation[r, 2] * normal[:, 2] for r in range(3)])
