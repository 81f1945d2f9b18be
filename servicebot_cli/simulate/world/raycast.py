r"""Rays against boxes, cylinders, the floor and meshes, all rays of a batch at once.

A ray :math:`o + t d` (unit :math:`d`) is moved into each solid's frame and intersected in
closed form: the slab method for boxes, a quadratic and two caps for cylinders, one division
for the floor (z = 0). Meshes go to trimesh (Embree when ``embreex`` is installed). The result
is the distance to the nearest surface the ray enters, inf where it hits nothing.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]


class RayQueries(Protocol):
    """trimesh's ray queries on one mesh (``mesh.ray``), as the simulator calls them."""

    def intersects_location(self, ray_origins: FloatArray, ray_directions: FloatArray,
                            multiple_hits: bool = ...) -> tuple[FloatArray, IntArray, IntArray]:
        """Hit points, the ray of each hit and the triangle it hit."""
        ...


class Mesh(Protocol):
    """A triangle mesh placed in the world (a ``trimesh.Trimesh``)."""

    @property
    def ray(self) -> RayQueries:
        """Ray queries against this mesh."""
        ...

    @property
    def vertices(self) -> FloatArray:
        """Vertex positions in the world [m], shape (V, 3)."""
        ...

    @property
    def faces(self) -> IntArray:
        """Vertex indices of each triangle, shape (F, 3)."""
        ...


def cast(origins: FloatArray, directions: FloatArray, solids: Sequence[Solid], *,
         floor: bool = True, meshes: Sequence[Mesh] = ()) -> FloatArray:
    """Distance along each ray to the first surface it enters [m].

    Args:
        origins: Ray origins, shape (N, 3).
        directions: Unit directions, shape (N, 3).
        solids: Boxes and cylinders.
        floor: Include the plane z = 0.
        meshes: Placed meshes (trimesh.Trimesh), in the same frame.

    Returns:
        Distances, shape (N,); inf where a ray hits nothing.
    """
    # Components as separate contiguous arrays: numpy is several times faster on those
    # than on reductions along a short last axis.
    o = [np.ascontiguousarray(origins[:, i]) for i in range(3)]
    d = [np.ascontiguousarray(directions[:, i]) for i in range(3)]
    level = bool(np.all(d[2] == 0.0))
    best = np.full(len(directions), np.inf)
    if floor and not level:
        with np.errstate(divide="ignore", invalid="ignore"):
            t = -o[2] / d[2]
        np.minimum(best, np.where((d[2] < 0) & (t >= 0), t, np.inf), out=best)
    for solid in solids:
        low, high = solid.z_range_m
        if level and not np.any((o[2] >= low) & (o[2] <= high)):
            continue  # a horizontal scan that passes above or below the solid
        rot = solid.rotation
        # Terms of a zero rotation entry are left out: they add only zeros.
        shifted = [o[j] - solid.center_m[j] for j in range(3)]
        ol = [sum(shifted[j] * rot[j, i] for j in range(3) if rot[j, i] != 0.0)
              for i in range(3)]
        dl = [sum(d[j] * rot[j, i] for j in range(3) if rot[j, i] != 0.0) for i in range(3)]
        ol = [x if isinstance(x, np.ndarray) else np.zeros_like(best) for x in ol]
        dl = [x if isinstance(x, np.ndarray) else np.zeros_like(best) for x in dl]
        if level and not np.any(dl[2]) and _strictly_within(ol[2], solid.half_m[2]):
            hit = (_level_box_entry(ol, dl, solid.half_m) if solid.kind == "box"
                   else _level_cylinder_entry(ol, dl, solid.half_m))
        else:
            hit = (box_entry(ol, dl, solid.half_m) if solid.kind == "box"
                   else cylinder_entry(ol, dl, solid.half_m))
        np.minimum(best, hit, out=best)
    for mesh in meshes:
        np.minimum(best, mesh_distances(mesh, origins, directions), out=best)
    return best


def box_entry(o: list[FloatArray], d: list[FloatArray], half: FloatArray) -> FloatArray:
    """Slab method: entry distance into an axis-aligned box centred at the origin."""
    near = np.full(np.shape(d[0]), -np.inf)
    far = np.full(np.shape(d[0]), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(3):
            inv = 1.0 / d[i]
            t1, t2 = (-half[i] - o[i]) * inv, (half[i] - o[i]) * inv
            np.fmax(near, np.fmin(t1, t2), out=near)
            np.fmin(far, np.fmax(t1, t2), out=far)
    return np.where((near <= far) & (near >= 0.0), near, np.inf)


def _strictly_within(z: FloatArray, half: float) -> bool:
    """Every local height strictly between the solid's bottom and top."""
    return bool(np.all((z > -half) & (z < half)))


def _level_box_entry(o: list[FloatArray], d: list[FloatArray], half: FloatArray) -> FloatArray:
    """:func:`box_entry` for level rays starting between the box's bottom and top.

    With local ``d[2] == 0`` the z slab holds all of the line (its bounds are -inf and inf),
    so leaving it out gives the same result.
    """
    near = np.full(np.shape(d[0]), -np.inf)
    far = np.full(np.shape(d[0]), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(2):
            inv = 1.0 / d[i]
            t1, t2 = (-half[i] - o[i]) * inv, (half[i] - o[i]) * inv
            np.fmax(near, np.fmin(t1, t2), out=near)
            np.fmin(far, np.fmax(t1, t2), out=far)
    return np.where((near <= far) & (near >= 0.0), near, np.inf)


def _level_cylinder_entry(o: list[FloatArray], d: list[FloatArray],
                          half: FloatArray) -> FloatArray:
    """:func:`cylinder_entry` for level rays starting between the cylinder's caps.

    The side alone: a level ray never meets a cap from there.
    """
    radius = half[0]
    a = d[0] * d[0] + d[1] * d[1]
    b = o[0] * d[0] + o[1] * d[1]
    c = o[0] * o[0] + o[1] * o[1] - radius**2
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        t_side = (-b - np.sqrt(np.maximum(disc, 0.0))) / a
        side = np.where((disc >= 0) & (a > 0) & (t_side >= 0), t_side, np.inf)
    return np.where(c < 0, np.inf, side)


def cylinder_entry(o: list[FloatArray], d: list[FloatArray], half: FloatArray) -> FloatArray:
    """Entry distance into a cylinder of radius ``half[0]`` and half length ``half[2]``."""
    radius, half_length = half[0], half[2]
    a = d[0] * d[0] + d[1] * d[1]
    b = o[0] * d[0] + o[1] * d[1]
    c = o[0] * o[0] + o[1] * o[1] - radius**2
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        t_side = (-b - np.sqrt(np.maximum(disc, 0.0))) / a
        z = o[2] + t_side * d[2]
        side = np.where((disc >= 0) & (a > 0) & (t_side >= 0) & (np.abs(z) <= half_length),
                        t_side, np.inf)
        t_cap = (-np.sign(d[2]) * half_length - o[2]) / d[2]
        px, py = o[0] + t_cap * d[0], o[1] + t_cap * d[1]
        cap = np.where((t_cap >= 0) & (px * px + py * py <= radius**2), t_cap, np.inf)
    inside = (c < 0) & (np.abs(o[2]) < half_length)  # a ray from inside sees no entry
    return np.where(inside, np.inf, np.fmin(side, cap))


def mesh_distances(mesh: Mesh, origins: FloatArray, directions: FloatArray) -> FloatArray:
    """First hit on a trimesh mesh per ray."""
    out = np.full(len(directions), np.inf)
    locations, index_ray, _ = mesh.ray.intersects_location(
        np.ascontiguousarray(origins), np.ascontiguousarray(directions), multiple_hits=False)
    if len(index_ray):
        distance = np.einsum("ij,ij->i", locations - origins[index_ray], directions[index_ray])
        np.minimum.at(out, index_ray, distance)
    return out
