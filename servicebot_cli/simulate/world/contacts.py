r"""Contacts and clearance between the robot's collision parts and the world's obstacles.

Every part of every link (base, wheels, sensors, arm; primitives and meshes), posed at each
tick with the arm, is tested against every obstacle (boxes, walls, cylinders, meshes). The
floor is not an obstacle: the wheels stand on it.

Cheap bounds come first, for all poses at once with numpy: a part whose bounding sphere
(centre :math:`c`, radius :math:`r`) lies farther than :math:`r` from an obstacle cannot touch
it, and its distance is at least :math:`d(c, \text{obstacle}) - r`. Parts are bounded one by
one only where their group's sphere does not already clear them (:mod:`.part_groups`), and
only the pairs the bounds leave open go to Coal (Pinocchio's collision library: GJK/EPA,
exact for primitives, BVH for meshes). The clearance search is :mod:`.clearance`.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import Part, RobotShape
from servicebot_cli.simulate.world.part_groups import (
    MARGIN_M,
    SLACK_M,
    box_bounds,
    group_bounds,
    part_bounds,
    part_groups,
)
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]


@dataclass(frozen=True)
class Obstacle:
    """One obstacle as the contact tests see it.

    Attributes:
        name: How events name it (``wall 1``, ``mesh 2``).
        kind: ``box``, ``cylinder`` or ``mesh``.
        center_m, rotation, half_m: The solid (for a mesh: its axis-aligned bounding box).
        mesh: A mesh obstacle's triangles, placed in the world.
    """

    name: str
    kind: str
    center_m: FloatArray
    rotation: FloatArray
    half_m: FloatArray
    mesh: Mesh | None = None

    @functools.cached_property
    def geometry(self) -> object:
        """Its Coal collision geometry, made when a test first needs it.

        Most runs need none: the bounds clear every pair, and a process that tests no pair
        never imports Coal.
        """
        import coal  # ships no type information: see pyproject's mypy overrides

        if self.mesh is not None:
            return _bvh(coal, np.asarray(self.mesh.vertices, dtype=np.float64),
                        np.asarray(self.mesh.faces, dtype=np.int64))
        return _primitive(coal, self.kind, self.half_m)

    @functools.cached_property
    def transform(self) -> object:
        """Its Coal pose in the world (a mesh's triangles are placed already)."""
        import coal

        if self.mesh is not None:
            return coal.Transform3s()
        return coal.Transform3s(self.rotation, self.center_m)

    def point_distance_xyz(self, points: list[FloatArray]) -> FloatArray:
        """Distance from points, given as x, y and z arrays of one shape, to the obstacle.

        To its box for a mesh; 0 inside.
        """
        shifted = [points[j] - self.center_m[j] for j in range(3)]
        rot = self.rotation
        local = [sum(shifted[j] * rot[j, i] for j in range(3) if rot[j, i] != 0.0)
                 for i in range(3)]
        local = [x if isinstance(x, np.ndarray) else np.zeros_like(points[0]) for x in local]
        if self.kind == "cylinder":
            radial = np.maximum(np.hypot(local[0], local[1]) - self.half_m[0], 0.0)
            axial = np.maximum(np.abs(local[2]) - self.half_m[2], 0.0)
            return np.asarray(np.hypot(radial, axial), dtype=np.float64)
        outside = [np.maximum(np.abs(local[i]) - self.half_m[i], 0.0) for i in range(3)]
        return np.asarray(np.sqrt(outside[0] * outside[0] + outside[1] * outside[1]
                                  + outside[2] * outside[2]), dtype=np.float64)


def obstacles(solids: Sequence[Solid], meshes: Sequence[Mesh] = ()) -> list[Obstacle]:
    """The world's solids and placed meshes (trimesh), in that order."""
    out = [Obstacle(solid.name, solid.kind, solid.center_m, solid.rotation, solid.half_m)
           for solid in solids]
    for i, mesh in enumerate(meshes, 1):
        vertices = np.asarray(mesh.vertices, dtype=np.float64)
        low, high = vertices.min(axis=0), vertices.max(axis=0)
        out.append(Obstacle(f"mesh {i}", "mesh", (low + high) / 2, np.eye(3), (high - low) / 2,
                            mesh))
    return out


def _bvh(coal: Any, vertices: FloatArray, faces: IntArray) -> object:
    """Coal's bounding volume hierarchy (oriented boxes and swept spheres) of triangles."""
    model = coal.BVHModelOBBRSS()
    model.beginModel(len(faces), len(vertices))
    model.addVertices(vertices)
    model.addTriangles(faces)
    model.endModel()
    return model


def part_geometry(part: Part) -> object:
    """A Coal geometry for a robot part (a BVH of its triangles for a mesh)."""
    import coal

    if part.vertices_m is not None and part.faces is not None:
        return _bvh(coal, part.vertices_m, part.faces)
    return _primitive(coal, part.kind, part.half_m)


def _primitive(coal: Any, kind: str, half_m: FloatArray) -> object:
    """Coal's box, cylinder (about z) or sphere of half extents ``half_m``."""
    if kind == "box":
        return coal.Box(*(2 * half_m))
    if kind == "cylinder":
        return coal.Cylinder(float(half_m[0]), 2 * float(half_m[2]))
    return coal.Sphere(float(half_m[0]))


def posed_parts(shape: RobotShape, x: FloatArray, y: FloatArray, yaw: FloatArray,
                base_height_m: float, q: FloatArray) -> FloatArray:
    """``transform_part_to_world`` of every part at each pose, shape (P, S, 4, 4).

    Args:
        shape: The robot's parts.
        x: Base positions along the world's x [m], shape (P,).
        y: Base positions along the world's y [m], shape (P,).
        yaw: Base headings [rad], shape (P,).
        base_height_m: Height of the base frame above the floor.
        q: The moving joints' positions at those poses, shape (P, J).
    """
    return Placed(shape.transforms_to_base(q), x, y, yaw, base_height_m).posed()


@dataclass(frozen=True, eq=False)
class Placed:
    """The robot's parts at many base poses; whole transforms are made only where asked.

    The contact tests need every part's centre at every pose (for their bounds) but whole
    ``transform_part_to_world`` matrices only for the few pairs Coal measures.

    Attributes:
        parts_to_base: ``transform_part_to_base`` per pose, shape (P, S, 4, 4).
        x_m, y_m, yaw_rad: The base's poses in the world, shape (P,) each.
        base_height_m: Height of the base frame above the floor [m].
    """

    parts_to_base: FloatArray
    x_m: FloatArray
    y_m: FloatArray
    yaw_rad: FloatArray
    base_height_m: float

    def __len__(self) -> int:
        return int(self.parts_to_base.shape[0])

    @property
    def shape(self) -> tuple[int, int]:
        """(poses, parts)."""
        return self.parts_to_base.shape[0], self.parts_to_base.shape[1]

    @functools.cached_property
    def _cos_sin(self) -> tuple[FloatArray, FloatArray]:
        yaw = np.asarray(self.yaw_rad)
        return np.cos(yaw), np.sin(yaw)

    def bases(self, rows: slice | IntArray = slice(None)) -> FloatArray:
        """``transform_base_to_world`` at the poses ``rows``, shape (P, 4, 4)."""
        c, s = self._cos_sin[0][rows], self._cos_sin[1][rows]
        base = np.zeros((len(c), 4, 4))
        base[:, 0, 0], base[:, 0, 1], base[:, 1, 0], base[:, 1, 1] = c, -s, s, c
        base[:, 2, 2] = base[:, 3, 3] = 1.0
        base[:, 0, 3], base[:, 1, 3] = np.asarray(self.x_m)[rows], np.asarray(self.y_m)[rows]
        base[:, 2, 3] = self.base_height_m
        return base

    def posed(self) -> FloatArray:
        """``transform_part_to_world`` of every part at every pose, shape (P, S, 4, 4)."""
        return self.bases()[:, None] @ self.parts_to_base

    def transform(self, pose: int, part: int) -> FloatArray:
        """``transform_part_to_world`` of one part at one pose, (4, 4), as :meth:`posed` has it."""
        return np.asarray(self.bases(np.array([pose]))[0] @ self.parts_to_base[pose, part],
                          dtype=np.float64)

    def rotations(self, pose: IntArray, part: IntArray) -> FloatArray:
        """``rotation_part_to_world`` of parts ``part`` at poses ``pose`` (n,), (n, 3, 3)."""
        c, s = self._cos_sin[0][pose], self._cos_sin[1][pose]
        local = self.parts_to_base[pose, part, :3, :3]
        out = local.copy()
        out[:, 0] = c[:, None] * local[:, 0] - s[:, None] * local[:, 1]
        out[:, 1] = s[:, None] * local[:, 0] + c[:, None] * local[:, 1]
        return out

    def centres(self) -> FloatArray:
        """Each part's centre in the world, shape (P, S, 3)."""
        c, s = self._cos_sin[0][:, None], self._cos_sin[1][:, None]
        local = self.parts_to_base[..., :3, 3]
        out = np.empty(local.shape)
        out[..., 0] = c * local[..., 0] - s * local[..., 1] + np.asarray(self.x_m)[:, None]
        out[..., 1] = s * local[..., 0] + c * local[..., 1] + np.asarray(self.y_m)[:, None]
        out[..., 2] = local[..., 2] + self.base_height_m
        return out


def as_placed(posed: FloatArray | Placed) -> Placed:
    """Whole transforms (P, S, 4, 4) as :class:`Placed` (the base at the world's origin)."""
    if isinstance(posed, Placed):
        return posed
    zeros = np.zeros(len(posed))
    return Placed(np.asarray(posed, dtype=np.float64), zeros, zeros, zeros, 0.0)


class Tester:
    """Coal queries of one robot against one world, with the geometries built once."""

    def __init__(self, shape: RobotShape, world: Sequence[Obstacle]) -> None:
        self.shape = shape
        self.world = list(world)
        self.radius_m = np.array([p.radius_m for p in shape.parts])
        self.half_m = np.array([p.half_m for p in shape.parts]).reshape(-1, 3)
        self.groups = part_groups(shape)

    @functools.cached_property
    def geometries(self) -> list[object]:
        """Each part's Coal geometry, made when a test first needs one."""
        return [part_geometry(p) for p in self.shape.parts]

    def near(self, posed: Placed, below: float) -> tuple[FloatArray, FloatArray]:
        """Each part's centre (P, S, 3), and which groups may hold a part bound below ``below``.

        The second array, shape (P, G, O), holds the groups' bounds where they may (else inf).
        """
        centres = posed.centres()
        bounds = group_bounds(self.world, centres, self.radius_m, self.groups)
        return centres, np.where(bounds <= below + MARGIN_M, bounds, np.inf)

    def pairs(self, centres: FloatArray, pose: IntArray, group: int,
              obstacle: int) -> tuple[FloatArray, IntArray]:
        """The bounds (k, m) of a group's parts at poses ``pose`` (k,), and the parts (m,)."""
        members = self.groups[group]
        inside = centres[pose][:, members]
        return part_bounds(self.world[obstacle], inside, self.radius_m[members]), members

    def closer(self, posed: Placed, centres: FloatArray, pose: IntArray, part: IntArray,
               obstacle: int, bounds: FloatArray) -> FloatArray:
        """Pairs' bounds (n,) made closer with the parts' and the obstacle's boxes.

        ``centres`` are the parts' (P, S, 3); ``pose`` and ``part`` (n,) name the pairs.
        """
        boxes = box_bounds(self.world[obstacle], centres[pose, part],
                           posed.rotations(pose, part), self.half_m[part])
        return np.maximum(bounds, boxes - SLACK_M)

    def touching(self, posed: Placed, pose: int, part: int, obstacle: int) -> bool:
        """Whether a part at ``posed`` pose ``pose`` touches an obstacle."""
        import coal

        transform = posed.transform(pose, part)
        request, result = coal.CollisionRequest(), coal.CollisionResult()
        target = self.world[obstacle]
        coal.collide(self.geometries[part], coal.Transform3s(transform[:3, :3], transform[:3, 3]),
                     target.geometry, target.transform, request, result)
        return bool(result.isCollision())

    def distance(self, posed: Placed, pose: int, part: int, obstacle: int) -> float:
        """Distance between a part and an obstacle [m] (0 when touching)."""
        import coal

        transform = posed.transform(pose, part)
        request, result = coal.DistanceRequest(), coal.DistanceResult()
        target = self.world[obstacle]
        coal.distance(self.geometries[part],
                      coal.Transform3s(transform[:3, :3], transform[:3, 3]),
                      target.geometry, target.transform, request, result)
        return max(float(result.min_distance), 0.0)

    def first_hits(self, posed: FloatArray | Placed) -> tuple[IntArray, IntArray]:
        """Per pose, the first obstacle touched and the part touching it; -1 where free.

        ``posed`` holds the parts at each pose: whole transforms (P, S, 4, 4) or
        :class:`Placed`. "First" is in obstacle order, then part order, so reports are stable.
        Coal tests the pairs whose bounds (sphere, then boxes) are not above 0, of the groups
        whose bound is not.
        """
        posed = as_placed(posed)
        obstacle = np.full(len(posed), -1, dtype=np.int64)
        part = np.full(len(posed), -1, dtype=np.int64)
        if not self.world or not len(posed):
            return obstacle, part
        centres, near = self.near(posed, 0.0)
        found: list[tuple[IntArray, IntArray, IntArray]] = []
        for g, o in zip(*np.nonzero(np.isfinite(near).any(axis=0)), strict=True):
            rows = np.flatnonzero(np.isfinite(near[:, g, o]))
            bounds, members = self.pairs(centres, rows, int(g), int(o))
            k, j = np.nonzero(bounds <= 0.0)
            closer = self.closer(posed, centres, rows[k], members[j], int(o), bounds[k, j])
            k, j = k[closer <= 0.0], j[closer <= 0.0]
            found.append((rows[k], members[j], np.full(len(k), o, dtype=np.int64)))
        if not found:
            return obstacle, part
        poses, parts, obstacles_ = (np.concatenate(column) for column in zip(*found,
                                                                             strict=True))
        for i in np.lexsort((parts, obstacles_, poses)).tolist():
            p, s, o = int(poses[i]), int(parts[i]), int(obstacles_[i])
            if obstacle[p] >= 0 and (o > obstacle[p] or (o == obstacle[p] and s > part[p])):
                continue
            if self.touching(posed, p, s, o):
                obstacle[p], part[p] = o, s
        return obstacle, part
