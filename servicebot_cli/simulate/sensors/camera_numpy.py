"""A camera frame in numpy, surface by surface: the path without numba, and its reference.

For scenes without mesh obstacles it gives the bytes of the compiled loop
(:mod:`~servicebot_cli.simulate.sensors.camera_kernel`): the same formulas in the same order
of operations, ties between equal distances going to the surface listed first (the floor,
the solids, the meshes, the robot's parts). Mesh obstacles go through trimesh's ray queries;
the robot's mesh parts through :mod:`.camera_mesh_rays`, the compiled walk's numbers. Pure.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.sensors import camera_mesh_rays, camera_noise, camera_rays
from servicebot_cli.simulate.sensors.camera_image import (
    AMBIENT,
    LIGHT,
    CameraView,
    Rgb,
    Scene,
)
from servicebot_cli.simulate.world import raycast

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
Surface = tuple[str, int]
"""``("floor", 0)``, ``("solid", i)``, ``("mesh", i)`` or ``("part", i)``."""


def render(view: CameraView, rotation: FloatArray, origin: FloatArray, scene: Scene,
           key: np.uint64, scale: float, rgb: npt.NDArray[np.uint8],
           depth_m: npt.NDArray[np.float32]) -> None:
    """Fill ``rgb`` (N, 3) and, unless it is empty, ``depth_m`` (N,), as the compiled loop."""
    d = [view.directions[:, 0] * rotation[i, 0] + view.directions[:, 1] * rotation[i, 1]
         + view.directions[:, 2] * rotation[i, 2] for i in range(3)]
    directions = np.column_stack(d)
    surfaces = [s for s in _surfaces(scene)
                if _in_view(s, scene, origin, rotation[:, 0], view.half_angle_rad)]
    triangles: dict[Surface, IntArray] = {}  # per mesh: the triangle each ray met first
    origins = np.broadcast_to(origin, directions.shape)
    distances = np.stack([_distances(s, scene, origins, d, triangles) for s in surfaces])
    depth = distances * view.forward
    distances[(depth < view.near_m) | (depth > view.far_m)] = np.inf
    nearest = np.argmin(distances, axis=0)
    distance = distances[nearest, np.arange(len(nearest))]
    seen = np.isfinite(distance)
    colour = np.tile(np.array(scene.palette.sky, dtype=np.float64), (len(nearest), 1))
    points = origins + directions * np.where(seen, distance, 0.0)[:, None]
    for index, surface in enumerate(surfaces):
        hit = seen & (nearest == index)
        if np.any(hit):
            base, normals = _looks(surface, scene, points[hit], triangles, hit)
            light = AMBIENT + (1.0 - AMBIENT) * np.abs(normals @ LIGHT)
            colour[hit] = base * light[:, None]
    if scale > 0.0:
        colour = colour + camera_noise.standard_normal(key, len(colour)) * scale
    rgb[:] = np.clip(np.rint(colour), 0, 255).astype(np.uint8)
    if depth_m.size:
        depth_m[:] = np.where(seen, distance * view.forward, np.inf).astype(np.float32)


def _surfaces(scene: Scene) -> list[Surface]:
    return [("floor", 0), *(("solid", i) for i in range(len(scene.solids))),
            *(("mesh", i) for i in range(len(scene.meshes))),
            *(("part", i) for i in range(len(scene.parts)))]


def _in_view(surface: Surface, scene: Scene, origin: FloatArray, axis: FloatArray,
             half_angle_rad: float) -> bool:
    """Whether a ray of the view can meet ``surface`` (the floor and meshes always can)."""
    kind, index = surface
    if kind == "solid":
        solid = scene.solids[index]
        radius = camera_rays.bounding_radius(solid.kind, solid.half_m)
        return camera_rays.in_view(solid.center_m, radius, origin, axis, half_angle_rad)
    if kind == "part":
        assert scene.part_transforms is not None
        return camera_rays.in_view(scene.part_transforms[index][:3, 3],
                                   scene.parts[index].radius_m, origin, axis, half_angle_rad)
    return True


def _distances(surface: Surface, scene: Scene, origins: FloatArray, d: list[FloatArray],
               triangles: dict[Surface, IntArray]) -> FloatArray:
    kind, index = surface
    origin = origins[0]
    if kind == "floor":
        return camera_rays.floor_distances(origin, d)
    if kind == "solid":
        solid = scene.solids[index]
        transform = np.eye(4)
        transform[:3, :3], transform[:3, 3] = solid.rotation, solid.center_m
        return camera_rays.primitive_distances(solid.kind, solid.half_m, transform, origin, d)
    if kind == "mesh":
        directions = np.column_stack(d)
        distances, triangles[surface] = _mesh_hits(scene.meshes[index], origins, directions)
        return distances
    assert scene.part_transforms is not None
    part = scene.parts[index]
    if part.kind == "mesh":
        shapes = scene.part_triangles
        distances, triangles[surface] = camera_mesh_rays.mesh_part_hits(
            scene.part_transforms[index], part.radius_m, origin, d, shapes.triangles,
            int(shapes.start[index]), int(shapes.stop[index]))
        return distances
    return camera_rays.primitive_distances(part.kind, part.half_m,
                                           scene.part_transforms[index], origin, d)


def _mesh_hits(mesh: raycast.Mesh, origins: FloatArray,
               directions: FloatArray) -> tuple[FloatArray, IntArray]:
    """First hit on a mesh per ray: distance (inf for none) and triangle (-1 for none)."""
    distances = np.full(len(directions), np.inf)
    triangle = np.full(len(directions), -1, dtype=np.int64)
    locations, rays, hit = mesh.ray.intersects_location(
        np.ascontiguousarray(origins), np.ascontiguousarray(directions), multiple_hits=False)
    if len(rays):
        along = np.einsum("ij,ij->i", locations - origins[rays], directions[rays])
        distances[rays], triangle[rays] = along, hit
    return distances, triangle


def _looks(surface: Surface, scene: Scene, points: FloatArray,
           triangles: dict[Surface, IntArray],
           hit: npt.NDArray[np.bool_]) -> tuple[FloatArray, FloatArray]:
    """Base colour (n, 3) and unit normal (n, 3) at ``points`` (rays ``hit``) on ``surface``."""
    kind, index = surface
    if kind == "floor":
        squares = (np.floor(points[:, 0]) + np.floor(points[:, 1])).astype(np.int64) % 2
        normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
        return np.array(scene.palette.floor, dtype=np.float64)[squares], normals
    if kind == "solid":
        solid = scene.solids[index]
        local = (points - solid.center_m) @ solid.rotation
        normals = camera_rays.primitive_normals(solid.kind, solid.half_m, local) @ solid.rotation.T
        return _flat(scene.palette.of_solid(solid), len(points)), normals
    if kind == "mesh":
        return _flat(scene.mesh_colour(index), len(points)), _mesh_normals(
            scene.meshes[index], triangles[surface][hit])
    assert scene.part_transforms is not None
    part, transform = scene.parts[index], scene.part_transforms[index]
    if part.kind == "mesh":
        return _flat(scene.part_colour(index), len(points)), camera_mesh_rays.mesh_part_normals(
            transform, scene.part_triangles.triangles, triangles[surface][hit])
    local = (points - transform[:3, 3]) @ transform[:3, :3]
    normals = camera_rays.primitive_normals(part.kind, part.half_m, local) @ transform[:3, :3].T
    return _flat(scene.part_colour(index), len(points)), normals


def _flat(rgb: Rgb, count: int) -> FloatArray:
    return np.tile(np.array(rgb, dtype=np.float64), (count, 1))


def _mesh_normals(mesh: raycast.Mesh, triangles: IntArray) -> FloatArray:
    """The unit normal of each of ``triangles`` of ``mesh``."""
    corners = mesh.vertices[mesh.faces[triangles]]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    found: FloatArray = normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True),
                                             1e-300)
    return found
