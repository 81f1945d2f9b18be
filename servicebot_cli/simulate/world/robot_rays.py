r"""Rays against the robot's own collision parts, posed differently in each batch.

The LIDAR and the camera see the robot they stand on. A ray :math:`o + t d` is moved into
each part's frame (:math:`R^T (o - c)`, :math:`R^T d`) and intersected in closed form: the
slab method for boxes, a quadratic and two caps for cylinders, a quadratic for spheres, and
Moller-Trumbore against the triangles of a mesh (for a level fan of rays from one origin,
the LIDAR's, only those that cross its plane). Only the rays through a part's bounding
sphere are intersected with it. A ray that starts inside a part does not see it, as with
Gazebo's ray sensor inside its own link (for a mesh: its nearest triangle faces away, so it
leaves the mesh).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world.raycast import box_entry, cylinder_entry

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_PAIRS_PER_ROUND = 1 << 20  # ray-triangle pairs intersected at once (about 100 MB of temporaries)


def cast_parts(parts: Sequence[Part], transforms: FloatArray, origins: FloatArray,
               directions: FloatArray) -> FloatArray:
    """Distance along each ray to the first part it enters [m], inf for none.

    Only the rays that pass through a part's bounding sphere are intersected with it.

    Args:
        parts: The parts, S of them.
        transforms: ``transform_part_to_frame`` per batch, shape (B, S, 4, 4).
        origins: Ray origins in that frame, shape (B, R, 3) or (R, 3) for every batch.
        directions: Unit directions, same shape as ``origins``.

    Returns:
        Distances, shape (B, R).
    """
    batches, rays = transforms.shape[0], origins.shape[-2]
    best = np.full(batches * rays, np.inf)
    o_full = [np.broadcast_to(origins[..., j], (batches, rays)) for j in range(3)]
    d_full = [np.broadcast_to(directions[..., j], (batches, rays)) for j in range(3)]
    for i, part in enumerate(parts):
        rotation, centre = transforms[:, i, :3, :3], transforms[:, i, :3, 3]
        batch, ray = _through_sphere(o_full, d_full, centre, part.radius_m)
        if not len(batch):
            continue
        # local = R^T (o - c), each sum in the order of the rotation's rows
        shifted = [o_full[j][batch, ray] - centre[batch, j] for j in range(3)]
        d_rays = [d_full[j][batch, ray] for j in range(3)]
        o = [_dot3(shifted, rotation[batch, :, k]) for k in range(3)]
        d = [_dot3(d_rays, rotation[batch, :, k]) for k in range(3)]
        if part.vertices_m is not None and part.faces is not None:
            hit = mesh_entry(o, d, part.vertices_m, part.faces)
        elif part.kind == "box":
            hit = box_entry(o, d, part.half_m)
        elif part.kind == "cylinder":
            hit = cylinder_entry(o, d, part.half_m)
        else:
            hit = sphere_entry(o, d, float(part.half_m[0]))
        flat = batch * rays + ray
        best[flat] = np.minimum(best[flat], hit)
    return best.reshape(batches, rays)


def _dot3(vectors: list[FloatArray], rows: FloatArray) -> FloatArray:
    """``v[0] r[:, 0] + v[1] r[:, 1] + v[2] r[:, 2]``, summed left to right."""
    return vectors[0] * rows[:, 0] + vectors[1] * rows[:, 1] + vectors[2] * rows[:, 2]


def _through_sphere(origins: list[FloatArray], directions: list[FloatArray],
                    centres: FloatArray, radius_m: float) -> tuple[IntArray, IntArray]:
    """Batch and ray indices of the rays that may meet a sphere ahead of their origin.

    A ray from ``o`` along unit ``d`` meets the sphere (centre ``c``, radius ``r``) at some
    ``t >= 0`` only if its distance from the centre is at most ``r`` and ``d . (c - o) >= -r``;
    the radius is taken a little larger so that rounding never drops a ray that hits.
    """
    reach = radius_m * (1 + 1e-6) + 1e-9
    v = [centres[:, None, j] - origins[j] for j in range(3)]
    along = directions[0] * v[0] + directions[1] * v[1] + directions[2] * v[2]
    across = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - along * along
    batch, ray = np.nonzero((across <= reach * reach) & (along >= -reach))
    return batch.astype(np.int64), ray.astype(np.int64)


def sphere_entry(o: list[FloatArray], d: list[FloatArray], radius: float) -> FloatArray:
    """Entry distance into a sphere of ``radius`` centred at the origin."""
    b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2]
    c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - radius**2
    disc = b * b - c
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return np.where((disc >= 0) & (c > 0) & (t >= 0), t, np.inf)


def mesh_entry(o: list[FloatArray], d: list[FloatArray], vertices_m: FloatArray,
               faces: IntArray) -> FloatArray:
    r"""Entry distance into a triangle mesh (Moller-Trumbore), inf where none.

    With :math:`e_1 = v_1 - v_0`, :math:`e_2 = v_2 - v_0`, :math:`p = d \times e_2`,
    :math:`\delta = e_1 \cdot p`, :math:`s = o - v_0`, :math:`q = s \times e_1`: the ray meets
    the triangle at :math:`t = e_2 \cdot q / \delta` when :math:`u = s \cdot p / \delta \ge 0`,
    :math:`v = d \cdot q / \delta \ge 0` and :math:`u + v \le 1`. :math:`\delta > 0` where the
    triangle faces the ray (counter-clockwise seen from outside); a ray whose nearest triangle
    faces away starts inside and enters nothing.
    """
    origins, directions = np.column_stack(o), np.column_stack(d)
    faces = faces[_crossing_the_rays_plane(origins, directions, vertices_m, faces)]
    if not len(faces) or not len(origins):
        return np.full(len(origins), np.inf)
    v0 = vertices_m[faces[:, 0]]
    e1, e2 = vertices_m[faces[:, 1]] - v0, vertices_m[faces[:, 2]] - v0
    out = np.full(len(origins), np.inf)
    step = max(1, _PAIRS_PER_ROUND // len(faces))
    for start in range(0, len(origins), step):
        rays = slice(start, start + step)
        p = np.cross(directions[rays, None, :], e2[None])  # (R, F, 3)
        det = np.einsum("fk,rfk->rf", e1, p)
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / det
            s = origins[rays, None, :] - v0[None]
            u = np.einsum("rfk,rfk->rf", s, p) * inv
            q = np.cross(s, e1[None])
            v = np.einsum("rk,rfk->rf", directions[rays], q) * inv
            t = np.einsum("fk,rfk->rf", e2, q) * inv
            hit = (np.abs(det) > 1e-14) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        t = np.where(hit, t, np.inf)
        nearest = np.argmin(t, axis=1)
        rows = np.arange(len(t))
        entering = det[rows, nearest] > 0
        out[rays] = np.where(entering, t[rows, nearest], np.inf)
    return out


def _crossing_the_rays_plane(origins: FloatArray, directions: FloatArray,
                             vertices_m: FloatArray, faces: IntArray) -> npt.NDArray[np.bool_]:
    """The triangles a fan of rays may meet.

    Where the rays share an origin and lie in one plane (a level LIDAR scan): those with
    corners on both sides of it, or on it: a triangle wholly on one side of the plane meets
    none of its rays. Anything else (rays from different origins, or not in one plane)
    keeps every triangle.
    """
    keep = np.ones(len(faces), dtype=bool)
    if len(origins) < 2 or np.any(origins != origins[0]):
        return keep
    cross = np.cross(directions[0], directions)
    widest = int(np.argmax(np.einsum("ij,ij->i", cross, cross)))
    normal = cross[widest]
    length = float(np.linalg.norm(normal))
    if length < 1e-6:  # the rays are (anti)parallel: no plane of theirs
        return keep
    normal = normal / length
    if np.abs(directions @ normal).max() > 1e-12:  # not in one plane
        return keep
    side = (vertices_m - origins[0]) @ normal  # signed distance of each vertex to the plane
    margin = 1e-9 * (1.0 + float(np.abs(side).max(initial=0.0)))
    corners = side[faces]
    crossing: npt.NDArray[np.bool_] = (corners.min(axis=1) <= margin) \
        & (corners.max(axis=1) >= -margin)
    return crossing
