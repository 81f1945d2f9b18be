"""Camera frames: an rgb8 image and a depth image, one ray cast per pixel.

Each pixel's ray leaves the camera through the pinhole that ``camera_info`` describes, scaled
by ``scale`` (``--camera-scale``: 1/8 of 1920x1080 is 240x135), and meets the floor, the
world's solids and meshes, and the robot's own collision parts, in closed form as the LIDAR's
rays do. The nearest surface gives the colour, shaded by the angle between its normal and a
light from above, and the depth: the distance along the optical axis, as a ROS depth image
(32FC1) stores it, +inf where nothing is within the far clip plane. Surfaces nearer than the
near clip plane are not drawn (what lies behind them is). Gazebo's camera noise is gaussian
on the pixel values scaled to [0, 1], then clipped, which is what the noise here does.

The camera link's frame looks along +x (Gazebo's convention); the image is in the optical
frame (z forward, x right, y down), as ``camera_info`` and ``sensor_msgs/Image`` expect.
Pure: every input is an argument.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.sensors import camera_rays
from servicebot_cli.simulate.sensors.camera_info import Intrinsics
from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world import raycast
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
Rgb = tuple[int, int, int]

_LIGHT = np.array([0.4, 0.3, 0.866]) / np.linalg.norm([0.4, 0.3, 0.866])
_AMBIENT = 0.45  # share of a colour lit from any side; the rest follows the light
COMPILED = True
"""Render in numba's compiled loop where it can (False: always the numpy path)."""


@dataclass(frozen=True)
class Palette:
    """Colours of what a camera sees, rgb 0-255.

    Attributes:
        sky: Where a ray meets nothing.
        floor: The floor's two checker colours (1 m squares, so motion shows).
        solids: Per solid kind and name prefix (``wall``, ``box``, ``cylinder``).
        mesh: Mesh obstacles.
        robot: The robot's own links.
    """

    sky: Rgb = (200, 215, 230)
    floor: tuple[Rgb, Rgb] = ((150, 150, 145), (120, 120, 115))
    solids: tuple[tuple[str, Rgb], ...] = (("wall", (225, 215, 190)), ("box", (215, 120, 40)),
                                           ("cylinder", (60, 110, 200)))
    mesh: Rgb = (70, 160, 80)
    robot: Rgb = (60, 60, 65)

    def of_solid(self, solid: Solid) -> Rgb:
        """The colour of ``solid``, by the start of its name."""
        return next((rgb for prefix, rgb in self.solids if solid.name.startswith(prefix)),
                    self.solids[0][1])


@dataclass(frozen=True)
class CameraView:
    """The rays of one camera at one scale.

    Attributes:
        intrinsics: ``camera_info`` of the rendered image (the scaled one).
        directions: Unit ray per pixel in the camera link's frame, row by row, (h * w, 3).
        forward: Each ray's cosine to the optical axis: depth = distance * forward, (h * w,).
        near_m, far_m: Clip planes along the optical axis [m].
    """

    intrinsics: Intrinsics
    directions: FloatArray = field(repr=False)
    forward: FloatArray = field(repr=False)
    near_m: float
    far_m: float

    @property
    def shape(self) -> tuple[int, int]:
        """Image rows and columns."""
        return self.intrinsics.height_px, self.intrinsics.width_px


@dataclass(frozen=True)
class Frame:
    """One rendered frame.

    Attributes:
        rgb: rgb8 pixels, (h, w, 3) uint8, row 0 at the top.
        depth_m: Depth along the optical axis [m], (h, w) float32; +inf: nothing within reach.
    """

    rgb: npt.NDArray[np.uint8]
    depth_m: npt.NDArray[np.float32]


def scaled(intrinsics: Intrinsics, scale: float) -> Intrinsics:
    """``intrinsics`` of the image ``scale`` times the size (at least one pixel each way).

    Focal lengths scale with the width actually kept; the principal point keeps its place
    in the image (gazebo_ros_camera's ``(w + 1) / 2`` of the new size).
    """
    if not scale > 0.0:
        raise ValueError(f"camera scale {scale} is not positive")
    width = max(1, round(intrinsics.width_px * scale))
    height = max(1, round(intrinsics.height_px * scale))
    ratio = width / intrinsics.width_px
    f = intrinsics.k[0] * ratio
    cx, cy = (width + 1) / 2.0, (height + 1) / 2.0
    return Intrinsics(width, height, (f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0),
                      (f, 0.0, cx, 0.0, 0.0, f, cy, 0.0, 0.0, 0.0, 1.0, 0.0),
                      intrinsics.distortion_model, intrinsics.d)


def camera_view(intrinsics: Intrinsics, near_m: float, far_m: float) -> CameraView:
    """The ray through the centre of each pixel of ``intrinsics``' image.

    Pixel ``(u, v)`` (column, row, from 0) has its centre at ``u + 1, v + 1`` in the one-based
    coordinates ``camera_info``'s principal point is given in.
    """
    width, height = intrinsics.width_px, intrinsics.height_px
    fx, cx, fy, cy = intrinsics.k[0], intrinsics.k[2], intrinsics.k[4], intrinsics.k[5]
    u, v = np.meshgrid(np.arange(width) + 1.0, np.arange(height) + 1.0)
    optical = np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)], axis=-1).reshape(-1, 3)
    optical /= np.linalg.norm(optical, axis=1, keepdims=True)
    # optical (x right, y down, z forward) to link (x forward, y left, z up)
    directions = np.stack([optical[:, 2], -optical[:, 0], -optical[:, 1]], axis=1)
    return CameraView(intrinsics, directions, optical[:, 2].copy(), near_m, far_m)


@dataclass(frozen=True)
class Scene:
    """What a camera can see, placed in the world.

    Attributes:
        solids: Walls, boxes and cylinders.
        meshes: Mesh obstacles (trimesh meshes), in the world frame.
        parts: The robot's collision parts.
        part_transforms: ``transform_part_to_world`` of each part for this frame, (S, 4, 4).
        palette: Their colours.
    """

    solids: Sequence[Solid] = ()
    meshes: Sequence[raycast.Mesh] = ()
    parts: Sequence[Part] = ()
    part_transforms: FloatArray | None = None
    palette: Palette = Palette()


def render(view: CameraView, transform_camera_to_world: FloatArray, scene: Scene,
           noise_stddev: float = 0.0, rng: np.random.Generator | None = None) -> Frame:
    """The frame the camera at ``transform_camera_to_world`` sees of ``scene``."""
    rotation, origin = transform_camera_to_world[:3, :3], transform_camera_to_world[:3, 3]
    directions = view.directions @ rotation.T
    origins = np.broadcast_to(origin, directions.shape)
    half_angle = math.acos(min(1.0, float(np.min(view.forward))))
    surfaces = [s for s in _surfaces(scene)
                if _in_view(s, scene, origin, rotation[:, 0], half_angle)]
    compiled = _compiled(view, origin, directions, scene, surfaces)
    colour, distance = compiled if compiled is not None else _numpy_path(
        view, origins, directions, scene, surfaces)
    seen = np.isfinite(distance)
    rows, columns = view.shape
    if noise_stddev > 0.0:
        generator = rng if rng is not None else np.random.default_rng(0)
        colour = colour + generator.normal(0.0, noise_stddev * 255.0, colour.shape)
    rgb = np.clip(np.rint(colour), 0, 255).astype(np.uint8).reshape(rows, columns, 3)
    depth_m = np.where(seen, distance * view.forward, np.inf).astype(np.float32)
    return Frame(rgb, depth_m.reshape(rows, columns))


def _numpy_path(view: CameraView, origins: FloatArray, directions: FloatArray, scene: Scene,
                surfaces: list[Surface]) -> tuple[FloatArray, FloatArray]:
    """Colour (N, 3) and distance (N,) of each ray, surface by surface in numpy."""
    triangles: dict[int, IntArray] = {}  # per mesh: the triangle each ray met first
    d = camera_rays.columns(directions)
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
            light = _AMBIENT + (1.0 - _AMBIENT) * np.abs(normals @ _LIGHT)
            colour[hit] = base * light[:, None]
    return colour, distance


def _compiled(view: CameraView, origin: FloatArray, directions: FloatArray, scene: Scene,
              surfaces: list[Surface]) -> tuple[FloatArray, FloatArray] | None:
    """The same, in numba's compiled loop; None with meshes in view or without numba."""
    if not COMPILED or any(kind == "mesh" for kind, _ in surfaces):
        return None
    try:
        from servicebot_cli.simulate.sensors import camera_kernel
    except ModuleNotFoundError as exc:
        if exc.name != "numba":
            raise
        return None
    solids = [scene.solids[i] for kind, i in surfaces if kind == "solid"]
    parts = [i for kind, i in surfaces if kind == "part"]
    kinds = [*(s.kind for s in solids), *(scene.parts[i].kind for i in parts)]
    transforms = scene.part_transforms if scene.part_transforms is not None \
        else np.zeros((0, 4, 4))
    palette = scene.palette
    count = len(kinds)
    colour, distance = np.empty((len(directions), 3)), np.empty(len(directions))
    camera_kernel.shade(
        np.ascontiguousarray(origin, dtype=np.float64), np.ascontiguousarray(directions),
        view.forward, view.near_m, view.far_m,
        np.array([("box", "cylinder", "sphere").index(k) for k in kinds], dtype=np.int64),
        np.array([*(s.half_m for s in solids), *(scene.parts[i].half_m for i in parts)],
                 dtype=np.float64).reshape(count, 3),
        np.array([*(s.rotation for s in solids), *(transforms[i][:3, :3] for i in parts)],
                 dtype=np.float64).reshape(count, 3, 3),
        np.array([*(s.center_m for s in solids), *(transforms[i][:3, 3] for i in parts)],
                 dtype=np.float64).reshape(count, 3),
        np.array([*(palette.of_solid(s) for s in solids), *(palette.robot for _ in parts)],
                 dtype=np.float64).reshape(count, 3),
        np.array(palette.floor, dtype=np.float64), np.array(palette.sky, dtype=np.float64),
        _LIGHT, _AMBIENT, colour, distance)
    return colour, distance


# -- surfaces: the floor, each solid, each mesh, each robot part ---------------------------

Surface = tuple[str, int]
"""``("floor", 0)``, ``("solid", i)``, ``("mesh", i)`` or ``("part", i)``."""


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
               triangles: dict[int, IntArray]) -> FloatArray:
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
        distances, triangles[index] = _mesh_hits(scene.meshes[index], origins, directions)
        return distances
    assert scene.part_transforms is not None
    part = scene.parts[index]
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


def _looks(surface: Surface, scene: Scene, points: FloatArray, triangles: dict[int, IntArray],
           hit: npt.NDArray[np.bool_]) -> tuple[FloatArray, FloatArray]:
    """Base colour (n, 3) and unit normal (n, 3) at ``points`` (rays ``hit``) on ``surface``."""
    kind, index = surface
    palette = scene.palette
    if kind == "floor":
        squares = (np.floor(points[:, 0]) + np.floor(points[:, 1])).astype(np.int64) % 2
        normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
        return np.array(palette.floor, dtype=np.float64)[squares], normals
    if kind == "solid":
        solid = scene.solids[index]
        local = (points - solid.center_m) @ solid.rotation
        normals = camera_rays.primitive_normals(solid.kind, solid.half_m, local) @ solid.rotation.T
        return _flat(palette.of_solid(solid), len(points)), normals
    if kind == "mesh":
        return _flat(palette.mesh, len(points)), _mesh_normals(scene.meshes[index],
                                                               triangles[index][hit])
    assert scene.part_transforms is not None
    part, transform = scene.parts[index], scene.part_transforms[index]
    local = (points - transform[:3, 3]) @ transform[:3, :3]
    normals = camera_rays.primitive_normals(part.kind, part.half_m, local) @ transform[:3, :3].T
    return _flat(palette.robot, len(points)), normals


def _flat(rgb: Rgb, count: int) -> FloatArray:
    return np.tile(np.array(rgb, dtype=np.float64), (count, 1))


def _mesh_normals(mesh: raycast.Mesh, triangles: IntArray) -> FloatArray:
    """The unit normal of each of ``triangles`` of ``mesh``."""
    corners = mesh.vertices[mesh.faces[triangles]]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    found: FloatArray = normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True),
                                             1e-300)
    return found


def field_of_view_rad(intrinsics: Intrinsics) -> float:
    """The horizontal field of view ``intrinsics`` describe [rad]."""
    return 2.0 * math.atan(intrinsics.width_px / (2.0 * intrinsics.k[0]))
