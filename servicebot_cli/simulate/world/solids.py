"""The world's solids, and whether the robot's footprint touches them.

Walls, boxes and cylinders become :class:`Solid` objects: boxes (a wall is a thin box) and
vertical cylinders with a pose. The robot's footprint is a rectangle in the base frame that
reaches from the floor to the top of the base; it touches a solid when their floor shapes
overlap (separating axis test) and their heights overlap. Everything is vectorised over poses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.scenario.definition import World

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]


@dataclass(frozen=True)
class Solid:
    """A box or a cylinder (axis along its local z) placed in some frame.

    Attributes:
        name: How events and plots name it (``wall 1``, ``box 2``, ``cylinder 1``).
        kind: ``box`` or ``cylinder``.
        center_m: Centre, shape (3,).
        rotation: Local axes in the parent frame (columns), shape (3, 3).
        half_m: Box half sizes; for a cylinder ``(radius, radius, half length)``.
    """

    name: str
    kind: str
    center_m: FloatArray
    rotation: FloatArray
    half_m: FloatArray

    @property
    def z_range_m(self) -> tuple[float, float]:
        """Lowest and highest z of the solid [m]."""
        reach = np.abs(self.rotation) @ self.half_m
        return float(self.center_m[2] - reach[2]), float(self.center_m[2] + reach[2])

    def floor_corners(self) -> FloatArray:
        """A box's corners on the floor plane, counter-clockwise, shape (4, 2)."""
        hx, hy = self.half_m[0], self.half_m[1]
        local = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
        return self.center_m[:2] + local @ self.rotation[:2, :2].T


def yaw_rotation(yaw_rad: float) -> FloatArray:
    """Rotation about z by ``yaw_rad``."""
    c, s = math.cos(yaw_rad), math.sin(yaw_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def world_solids(world: World) -> list[Solid]:
    """Walls, boxes and cylinders of a scenario's world, named in file order."""
    solids = []
    for i, wall in enumerate(world.walls, 1):
        (x0, y0), (x1, y1) = wall.from_m, wall.to_m
        length = math.hypot(x1 - x0, y1 - y0)
        solids.append(Solid(
            f"wall {i}", "box", np.array([(x0 + x1) / 2, (y0 + y1) / 2, wall.height_m / 2]),
            yaw_rotation(math.atan2(y1 - y0, x1 - x0)),
            # Walls reach half a thickness past their ends, so corners close.
            np.array([length / 2 + wall.thickness_m / 2, wall.thickness_m / 2, wall.height_m / 2]),
        ))
    for i, box in enumerate(world.boxes, 1):
        solids.append(Solid(f"box {i}", "box", np.array(box.center_m, float),
                            yaw_rotation(box.yaw_rad), np.array(box.size_m, float) / 2))
    for i, cyl in enumerate(world.cylinders, 1):
        solids.append(Solid(f"cylinder {i}", "cylinder",
                            np.array([cyl.center_m[0], cyl.center_m[1], cyl.height_m / 2]),
                            np.eye(3), np.array([cyl.radius_m, cyl.radius_m, cyl.height_m / 2])))
    return solids


@dataclass(frozen=True)
class Footprint:
    """The base's outline in its own frame and its height above the floor [m]."""

    x_min_m: float
    x_max_m: float
    y_min_m: float
    y_max_m: float
    top_m: float

    def corners(self) -> FloatArray:
        """Corners in the base frame, counter-clockwise, shape (4, 2)."""
        return np.array([[self.x_max_m, self.y_max_m], [self.x_min_m, self.y_max_m],
                         [self.x_min_m, self.y_min_m], [self.x_max_m, self.y_min_m]])

    @property
    def radius_m(self) -> float:
        """Radius of the circle around the base origin that holds the footprint."""
        return float(np.max(np.hypot(*self.corners().T)))


def _world_corners(footprint: Footprint, x: FloatArray, y: FloatArray,
                   yaw: FloatArray) -> FloatArray:
    """Footprint corners in the world for each pose, shape (P, 4, 2)."""
    c, s = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    local = footprint.corners()
    return np.stack((x[:, None] + c * local[:, 0] - s * local[:, 1],
                     y[:, None] + s * local[:, 0] + c * local[:, 1]), axis=-1)


def _floor_solids(solids: list[Solid], footprint: Footprint) -> list[tuple[int, Solid]]:
    """Solids that stand within the footprint's height and have a vertical axis."""
    kept = []
    for i, solid in enumerate(solids):
        low, high = solid.z_range_m
        if high > 0.0 and low < footprint.top_m and abs(solid.rotation[2, 2]) > 1 - 1e-9:
            kept.append((i, solid))
    return kept


def footprint_hits(footprint: Footprint, solids: list[Solid], x: FloatArray, y: FloatArray,
                   yaw: FloatArray) -> IntArray:
    """Index of the first solid each pose's footprint overlaps, -1 where free."""
    hit = np.full(len(x), -1, dtype=np.int64)
    if not len(x):
        return hit
    corners = None
    for i, solid in reversed(_floor_solids(solids, footprint)):  # first in file order wins
        reach = footprint.radius_m + float(np.hypot(*solid.half_m[:2]))
        near = np.flatnonzero(np.hypot(x - solid.center_m[0], y - solid.center_m[1]) < reach)
        if not len(near):
            continue
        if corners is None:
            corners = _world_corners(footprint, x, y, yaw)
        if solid.kind == "cylinder":
            inside = _circle_distance(footprint, solid, x[near], y[near], yaw[near]) < 0.0
        else:
            inside = _polygons_overlap(corners[near], solid.floor_corners())
        hit[near[inside]] = i
    return hit


def _polygons_overlap(corners: FloatArray, other: FloatArray) -> npt.NDArray[np.bool_]:
    """Separating axis test of convex quads ``corners`` (P, 4, 2) against ``other`` (4, 2)."""
    overlap = np.ones(len(corners), dtype=bool)
    edges_a = np.roll(corners, -1, axis=1) - corners  # (P, 4, 2)
    axes = [edges_a[:, 0], edges_a[:, 1]]
    edges_b = np.roll(other, -1, axis=0) - other
    axes += [np.broadcast_to(edges_b[0], corners[:, 0].shape),
             np.broadcast_to(edges_b[1], corners[:, 0].shape)]
    for axis in axes:
        normal = np.stack((-axis[:, 1], axis[:, 0]), axis=-1)  # (P, 2)
        pa = np.einsum("pkd,pd->pk", corners, normal)
        pb = other @ normal.T  # (4, P)
        separated = (pa.max(axis=1) <= pb.min(axis=0)) | (pb.max(axis=0) <= pa.min(axis=1))
        overlap &= ~separated
    return overlap


def _circle_distance(footprint: Footprint, solid: Solid, x: FloatArray, y: FloatArray,
                     yaw: FloatArray) -> FloatArray:
    """Signed distance from each footprint to a vertical cylinder (negative: overlapping)."""
    dx, dy = float(solid.center_m[0]) - x, float(solid.center_m[1]) - y
    c, s = np.cos(yaw), np.sin(yaw)
    lx, ly = c * dx + s * dy, -s * dx + c * dy  # the centre in the base frame
    qx = np.clip(lx, footprint.x_min_m, footprint.x_max_m)
    qy = np.clip(ly, footprint.y_min_m, footprint.y_max_m)
    outside = np.hypot(lx - qx, ly - qy)
    depth = np.minimum.reduce([lx - footprint.x_min_m, footprint.x_max_m - lx,
                               ly - footprint.y_min_m, footprint.y_max_m - ly])
    return np.where(outside > 0, outside, -depth) - float(solid.half_m[0])


def footprint_clearance(footprint: Footprint, solids: list[Solid], x: FloatArray, y: FloatArray,
                        yaw: FloatArray) -> tuple[FloatArray, IntArray]:
    """Distance from each footprint to the nearest solid on the floor, and which one.

    Zero where touching; inf (and -1) in an empty world.
    """
    best, which = np.full(len(x), np.inf), np.full(len(x), -1, dtype=np.int64)
    corners = _world_corners(footprint, x, y, yaw) if len(x) else np.zeros((0, 4, 2))
    for i, solid in _floor_solids(solids, footprint):
        if solid.kind == "cylinder":
            gap = np.maximum(_circle_distance(footprint, solid, x, y, yaw), 0.0)
        else:
            other = solid.floor_corners()
            gap = np.minimum(_points_to_polygon(corners, other),
                             _points_to_polygon(np.broadcast_to(other, corners.shape), corners))
            gap = np.where(_polygons_overlap(corners, other), 0.0, gap)
        closer = gap < best
        best, which = np.where(closer, gap, best), np.where(closer, i, which)
    return best, which


def _points_to_polygon(points: FloatArray, polygon: FloatArray) -> FloatArray:
    """Smallest distance from any of ``points`` (P, 4, 2) to the edges of ``polygon``.

    ``polygon`` is (4, 2) or (P, 4, 2).
    """
    poly = np.broadcast_to(polygon, points.shape)
    best = np.full(len(points), np.inf)
    for e in range(4):
        ax, ay = poly[:, e, 0][:, None], poly[:, e, 1][:, None]
        bx, by = poly[:, (e + 1) % 4, 0][:, None], poly[:, (e + 1) % 4, 1][:, None]
        ex, ey = bx - ax, by - ay
        px, py = points[:, :, 0] - ax, points[:, :, 1] - ay
        t = np.clip((px * ex + py * ey) / (ex * ex + ey * ey), 0.0, 1.0)
        dx, dy = px - t * ex, py - t * ey
        np.minimum(best, np.sqrt((dx * dx + dy * dy).min(axis=1)), out=best)
    return best


def _point_distance(solid: Solid, x: FloatArray, y: FloatArray) -> FloatArray:
    """Floor distance from points to a solid's outline (0 inside)."""
    dx, dy = x - float(solid.center_m[0]), y - float(solid.center_m[1])
    if solid.kind == "cylinder":
        return np.maximum(np.hypot(dx, dy) - float(solid.half_m[0]), 0.0)
    r = solid.rotation
    r00, r01, r10, r11 = float(r[0, 0]), float(r[0, 1]), float(r[1, 0]), float(r[1, 1])
    lx, ly = r00 * dx + r10 * dy, r01 * dx + r11 * dy
    ox = np.maximum(np.abs(lx) - float(solid.half_m[0]), 0.0)
    oy = np.maximum(np.abs(ly) - float(solid.half_m[1]), 0.0)
    return np.hypot(ox, oy)


@dataclass(frozen=True)
class Closest:
    """The closest the footprint came to an obstacle: distance [m], pose index, solid index."""

    distance_m: float
    index: int
    solid: int


def closest_approach(footprint: Footprint, solids: list[Solid], x: FloatArray, y: FloatArray,
                     yaw: FloatArray) -> Closest:
    """The smallest footprint clearance over all poses, computed exactly where it can occur.

    For a pose whose origin is at distance ``d`` from a solid, the clearance lies in
    ``[d - rho, d]`` (``rho`` the footprint's radius); only pairs whose lower bound is below
    the best upper bound can hold the minimum, so only those are measured.
    """
    candidates = _floor_solids(solids, footprint)
    if not candidates or not len(x):
        return Closest(float("inf"), -1, -1)
    rho = footprint.radius_m
    # The base origin lies inside the footprint, so its own distance is an upper bound.
    point = [_point_distance(s, x, y) for _, s in candidates]
    upper = min(float(d.min()) for d in point)
    best = Closest(float("inf"), -1, -1)
    for (i, solid), d in zip(candidates, point, strict=True):
        near = np.flatnonzero(d - rho <= upper)
        if not len(near):
            continue
        gap, _ = footprint_clearance(footprint, [solid], x[near], y[near], yaw[near])
        k = int(np.argmin(gap))
        if gap[k] < best.distance_m:
            best = Closest(float(gap[k]), int(near[k]), i)
    return best
