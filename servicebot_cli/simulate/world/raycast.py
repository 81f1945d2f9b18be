r"""Rays against boxes, cylinders, the floor and meshes, all rays of a batch at once.

A ray :math:`o + t d` (unit :math:`d`) is moved into each solid's frame and intersected in
closed form: the slab method for boxes, a quadratic and two caps for cylinders, one division
for the floor (z = 0). Meshes go to trimesh (Embree when ``embreex`` is installed). The result
is the distance to the nearest surface the ray enters, inf where it hits nothing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_BOX_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)
_CULL_MARGIN_RAD = 1e-7
"""Bearings this far outside a solid's span are still cast: far above any rounding."""


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


@dataclass(frozen=True)
class Fans:
    """Rays laid out as fans: ray ``i * R + k`` is ray ``k`` of fan ``i``.

    A fan's rays all leave one point; ray ``k`` of fan ``i`` points at the bearing
    ``heading_rad[i] + bearing_rad[k]`` (about z, in the rays' frame). A LIDAR's scans are
    fans.
    """

    heading_rad: FloatArray  # (S,)
    bearing_rad: FloatArray  # (R,)


def cast(origins: FloatArray, directions: FloatArray, solids: Sequence[Solid], *,
         floor: bool = True, meshes: Sequence[Mesh] = (), fans: Fans | None = None) -> FloatArray:
    """Distance along each ray to the first surface it enters [m].

    Args:
        origins: Ray origins, shape (N, 3).
        directions: Unit directions, shape (N, 3).
        solids: Boxes and cylinders.
        floor: Include the plane z = 0.
        meshes: Placed meshes (trimesh.Trimesh), in the same frame.
        fans: How the rays make fans, if they do; level fans are then intersected with a
            solid only where their bearing can meet it (the same distances, less work).

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
    cull = level and fans is not None and fan_cull_works(fans)
    # each fan's first ray's origin: the fan's, which all its rays share
    origin = [c[::len(fans.bearing_rad)] for c in o] if cull and fans is not None else o
    crossed = [solid for solid in solids  # a level scan passes above or below the others
               if not level or _meets_heights(origin[2], *solid.z_range_m)]
    if cull and crossed:
        assert fans is not None
        for solid, (rays, owner) in zip(crossed, facing_rays(fans, origin[0], origin[1],
                                                             crossed), strict=True):
            hit = _fan_entry(origin, d, rays, owner, solid)
            best[rays] = np.minimum(best[rays], hit)
    else:
        for solid in crossed:
            np.minimum(best, _solid_entry(o, d, solid, level), out=best)
    for mesh in meshes:
        np.minimum(best, mesh_distances(mesh, origins, directions), out=best)
    return best


def _meets_heights(z_m: FloatArray, low_m: float, high_m: float) -> bool:
    """Some height ``z_m`` lies in ``[low_m, high_m]``."""
    return bool(np.any((z_m >= low_m) & (z_m <= high_m)))


def _solid_entry(o: list[FloatArray], d: list[FloatArray], solid: Solid,
                 level: bool) -> FloatArray:
    """Entry distance of each ray into ``solid`` (inf for none); ``level``: every d_z is 0."""
    rot = solid.rotation
    # Terms of a zero rotation entry are left out: they add only zeros.
    shifted = [o[j] - solid.center_m[j] for j in range(3)]
    ol = [sum(shifted[j] * rot[j, i] for j in range(3) if rot[j, i] != 0.0) for i in range(3)]
    dl = [sum(d[j] * rot[j, i] for j in range(3) if rot[j, i] != 0.0) for i in range(3)]
    ol = [x if isinstance(x, np.ndarray) else np.zeros_like(o[0]) for x in ol]
    dl = [x if isinstance(x, np.ndarray) else np.zeros_like(o[0]) for x in dl]
    if level and not np.any(dl[2]) and _strictly_within(ol[2], solid.half_m[2]):
        return (box_entry(ol, dl, solid.half_m, axes=2) if solid.kind == "box"
                else _level_cylinder_entry(ol, dl, solid.half_m))
    return (box_entry(ol, dl, solid.half_m) if solid.kind == "box"
            else cylinder_entry(ol, dl, solid.half_m))


def _fan_entry(origin: list[FloatArray], d: list[FloatArray], rays: IntArray, owner: IntArray,
               solid: Solid) -> FloatArray:
    """:func:`_solid_entry` of the level rays ``rays``, of fans ``owner`` from ``origin``.

    A solid turned about z alone, with every fan strictly between its bottom and top, needs
    the rays' x and y only: the same terms, in the same order, as :func:`_solid_entry`; those
    of the origin are worked out once per fan.
    """
    rot = solid.rotation
    turned_about_z = rot[2, 0] == 0.0 and rot[2, 1] == 0.0 and rot[0, 2] == 0.0 \
        and rot[1, 2] == 0.0 and rot[2, 2] == 1.0
    if not turned_about_z or not _strictly_within(origin[2] - solid.center_m[2],
                                                  solid.half_m[2]):
        return _solid_entry([c[owner] for c in origin], [c[rays] for c in d], solid, True)
    shifted = [origin[j] - solid.center_m[j] for j in range(2)]  # per fan
    directions = [d[j][rays] for j in range(2)]
    ol = [sum(shifted[j] * rot[j, i] for j in range(2) if rot[j, i] != 0.0) for i in range(2)]
    dl = [sum(directions[j] * rot[j, i] for j in range(2) if rot[j, i] != 0.0)
          for i in range(2)]
    ol = [x[owner] if isinstance(x, np.ndarray) else np.zeros(len(rays)) for x in ol]
    dl = [x if isinstance(x, np.ndarray) else np.zeros(len(rays)) for x in dl]
    return (box_entry(ol, dl, solid.half_m, axes=2) if solid.kind == "box"
            else _level_cylinder_entry(ol, dl, solid.half_m))


def fan_cull_works(fans: Fans) -> bool:
    """The fans' bearings span at most a full turn (each direction is met once or twice)."""
    bearings = fans.bearing_rad
    return bool(len(bearings)) and float(np.ptp(bearings)) <= 2 * np.pi + 1e-12


def facing_rays(fans: Fans, x_m: FloatArray, y_m: FloatArray,
                solids: Sequence[Solid]) -> list[tuple[IntArray, IntArray]]:
    """Per solid, the level rays whose bearing can meet it, and their fans; fans from (x, y).

    Seen from a fan's origin outside its footprint, the corners of the solid's box span less
    than half a turn of bearing; only the rays within that span (and a margin far above
    rounding) can enter it. A fan from inside the footprint keeps every ray.
    """
    centres = np.array([s.center_m[:2] for s in solids])  # (P, 2)
    corners = np.stack([s.center_m[:2] + (_BOX_CORNERS * s.half_m) @ s.rotation[:2].T
                        for s in solids])  # (P, 8, 2)
    towards = np.arctan2(centres[:, 1] - y_m[:, None], centres[:, 0] - x_m[:, None])  # (S, P)
    spread = np.arctan2(corners[:, :, 1] - y_m[:, None, None],
                        corners[:, :, 0] - x_m[:, None, None])  # (S, P, 8)
    spread = (spread - towards[..., None] + np.pi) % (2 * np.pi) - np.pi  # from the centre
    low = spread.min(axis=2) - _CULL_MARGIN_RAD
    width = spread.max(axis=2) + _CULL_MARGIN_RAD - low
    outside = width < np.pi - 1e-3
    order = np.argsort(fans.bearing_rad, kind="stable")
    bearings = fans.bearing_rad[order]
    start = bearings[0] + (towards + low - fans.heading_rad[:, None] - bearings[0]) % (2 * np.pi)
    rays = len(order)
    first = np.concatenate((np.where(outside, np.searchsorted(bearings, start, "left"), 0),
                            np.searchsorted(bearings, start - 2 * np.pi, "left")))
    stop = np.concatenate((np.where(outside, np.searchsorted(bearings, start + width, "right"),
                                    rays),
                           np.where(outside, np.searchsorted(bearings, start - 2 * np.pi + width,
                                                             "right"), 0)))
    fan = np.concatenate((np.arange(len(x_m)), np.arange(len(x_m))))
    sorted_already = bool(np.all(order == np.arange(rays)))
    return [_spans(fan, first[:, p], stop[:, p], None if sorted_already else order, rays)
            for p in range(len(solids))]


def _spans(fan: IntArray, first: IntArray, stop: IntArray, order: IntArray | None,
           rays: int) -> tuple[IntArray, IntArray]:
    """The rays at sorted positions ``first[i]`` to ``stop[i] - 1`` of fan ``fan[i]``.

    Returns:
        Their indexes, and the fan of each.
    """
    counts = np.maximum(stop - first, 0)
    position = np.arange(int(counts.sum())) + np.repeat(first - (np.cumsum(counts) - counts),
                                                        counts)
    chosen: IntArray = position if order is None else order[position]
    owner = np.repeat(fan, counts)
    return owner * rays + chosen, owner


def box_entry(o: list[FloatArray], d: list[FloatArray], half: FloatArray, *,
              axes: int = 3) -> FloatArray:
    """Slab method: entry distance into an axis-aligned box centred at the origin.

    ``axes`` 2 leaves out the z slab, which holds all of a level ray's line when it starts
    between the box's bottom and top (the same result).
    """
    near = np.full(np.shape(d[0]), -np.inf)
    far = np.full(np.shape(d[0]), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(axes):
            inv = 1.0 / d[i]
            t1, t2 = (-half[i] - o[i]) * inv, (half[i] - o[i]) * inv
            np.fmax(near, np.fmin(t1, t2), out=near)
            np.fmin(far, np.fmax(t1, t2), out=far)
    return np.where((near <= far) & (near >= 0.0), near, np.inf)


def _strictly_within(z: FloatArray, half: float) -> bool:
    """Every local height strictly between the solid's bottom and top."""
    return bool(np.all((z > -half) & (z < half)))


def _level_cylinder_entry(o: list[FloatArray], d: list[FloatArray],
                          half: FloatArray) -> FloatArray:
    """:func:`cylinder_entry` for level rays starting between the cylinder's caps.

    The side alone: a level ray never meets a cap from there.
    """
    a, c, disc, t_side = _side(o, d, half[0])
    side = np.where((disc >= 0) & (a > 0) & (t_side >= 0), t_side, np.inf)
    return np.where(c < 0, np.inf, side)


def _side(o: list[FloatArray], d: list[FloatArray],
          radius: float) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """A ray against a cylinder's infinite side, radius ``radius`` about the local z axis.

    Returns ``a``, ``c`` (< 0: the ray starts inside), the discriminant, and the nearer root
    ``t`` of :math:`a t^2 + 2 b t + c = 0`.
    """
    a = d[0] * d[0] + d[1] * d[1]
    b = o[0] * d[0] + o[1] * d[1]
    c = o[0] * o[0] + o[1] * o[1] - radius**2
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        t_side = (-b - np.sqrt(np.maximum(disc, 0.0))) / a
    return a, c, disc, t_side


def cylinder_entry(o: list[FloatArray], d: list[FloatArray], half: FloatArray) -> FloatArray:
    """Entry distance into a cylinder of radius ``half[0]`` and half length ``half[2]``."""
    radius, half_length = half[0], half[2]
    a, c, disc, t_side = _side(o, d, radius)
    with np.errstate(divide="ignore", invalid="ignore"):
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
