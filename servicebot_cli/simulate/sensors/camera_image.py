"""Camera frames: an rgb8 image and a depth image, one ray cast per pixel.

Each pixel's ray leaves the camera through the pinhole that ``camera_info`` describes, scaled
by ``scale`` (``--camera-scale``: 1/8 of 1920x1080 is 240x135), and meets the floor, the
world's solids and meshes, and the robot's own collision parts (primitives in closed form,
as the LIDAR's rays do; mesh parts through a hierarchy of their triangles, in their own
frame). The nearest surface gives the colour (the scenario's, the URDF material's, else
:class:`Palette`'s), shaded by the angle between its normal and a light from above, and the
depth: the distance along the optical axis, as a ROS depth image (32FC1) stores it, +inf
where nothing is within the far clip plane. Surfaces nearer than the near clip plane are not
drawn (what lies behind them is). Gazebo's camera noise is gaussian on the pixel values
scaled to [0, 1], then clipped, which is what the noise here does
(:mod:`~servicebot_cli.simulate.sensors.camera_noise`).

Frames are drawn by numba's compiled loop (:mod:`.camera_kernel`); without numba, by the
numpy path (:mod:`.camera_numpy`), which gives the same bytes for scenes without mesh
obstacles (mesh parts included).
The camera link's frame looks along +x (Gazebo's convention); the image is in the optical
frame (z forward, x right, y down), as ``camera_info`` and ``sensor_msgs/Image`` expect.
Pure: every input is an argument.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.sensors import camera_mesh, camera_noise
from servicebot_cli.simulate.sensors.camera_info import Intrinsics, principal_point
from servicebot_cli.simulate.shape import KINDS, Part
from servicebot_cli.simulate.world import raycast
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
Rgb = tuple[int, int, int]

PART_KINDS = (*KINDS, "mesh")
"""Kinds as the compiled loop numbers them (``camera_primitives``' BOX .. MESH)."""
LIGHT = np.array([0.4, 0.3, 0.866]) / np.linalg.norm([0.4, 0.3, 0.866])
AMBIENT = 0.45  # share of a colour lit from any side; the rest follows the light
COMPILED = True
"""Render in numba's compiled loop (False: always the numpy path)."""


def rgb_of(colour: Sequence[float]) -> Rgb:
    """Rgb 0-255 of a colour given as three numbers in [0, 1]."""
    r, g, b = (int(round(255.0 * c)) for c in colour)
    return r, g, b


@dataclass(frozen=True)
class Palette:
    """Colours of what a camera sees, rgb 0-255, where the scenario and the URDF give none.

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
        """The colour of ``solid``: its own, else by the start of its name."""
        if solid.color is not None:
            return rgb_of(solid.color)
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

    @functools.cached_property
    def pinhole(self) -> FloatArray:
        """fx, cx, fy, cy of ``intrinsics``, (4,), the principal point one-based.

        As the culling reads it: a ``centred`` one is given from the image's edge, half a
        pixel before.
        """
        k, shift = self.intrinsics.k, 0.5 if self.intrinsics.centred else 0.0
        return np.array([k[0], k[2] + shift, k[4], k[5] + shift], dtype=np.float64)

    @functools.cached_property
    def half_angle_rad(self) -> float:
        """Half angle of the cone about the optical axis that holds every ray [rad]."""
        return math.acos(min(1.0, float(np.min(self.forward))))


@dataclass(frozen=True)
class Frame:
    """One rendered frame.

    Attributes:
        rgb: rgb8 pixels, (h, w, 3) uint8, row 0 at the top.
        depth_m: Depth along the optical axis [m], (h, w) float32; +inf: nothing within reach.
            Empty, (0, 0), when no depth image was asked for.
    """

    rgb: npt.NDArray[np.uint8]
    depth_m: npt.NDArray[np.float32]


def scaled(intrinsics: Intrinsics, scale: float) -> Intrinsics:
    """``intrinsics`` of the image ``scale`` times the size (at least one pixel each way).

    Focal lengths scale with the width actually kept; the principal point keeps its place
    in the image (gazebo_ros_camera's ``(w + 1) / 2`` of the new size; gz-sensors' centre).
    """
    if not scale > 0.0:
        raise ValueError(f"camera scale {scale} is not positive")
    width = max(1, round(intrinsics.width_px * scale))
    height = max(1, round(intrinsics.height_px * scale))
    ratio = width / intrinsics.width_px
    f = intrinsics.k[0] * ratio
    cx, cy = principal_point(width, height, intrinsics.centred)
    return Intrinsics(width, height, (f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0),
                      (f, 0.0, cx, 0.0, 0.0, f, cy, 0.0, 0.0, 0.0, 1.0, 0.0),
                      intrinsics.distortion_model, intrinsics.d, intrinsics.centred)


def camera_view(intrinsics: Intrinsics, near_m: float, far_m: float) -> CameraView:
    """The ray through the centre of each pixel of ``intrinsics``' image.

    Pixel ``(u, v)`` (column, row, from 0) has its centre at ``u + 1, v + 1`` in the one-based
    coordinates gazebo_ros_camera's principal point is given in, at ``u + 0.5, v + 0.5`` from
    the image's edge in gz-sensors' (``centred``): the same rays.
    """
    width, height = intrinsics.width_px, intrinsics.height_px
    fx, cx, fy, cy = intrinsics.k[0], intrinsics.k[2], intrinsics.k[4], intrinsics.k[5]
    first = 0.5 if intrinsics.centred else 1.0
    u, v = np.meshgrid(np.arange(width) + first, np.arange(height) + first)
    optical = np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)], axis=-1).reshape(-1, 3)
    optical /= np.linalg.norm(optical, axis=1, keepdims=True)
    # optical (x right, y down, z forward) to link (x forward, y left, z up)
    directions = np.stack([optical[:, 2], -optical[:, 0], -optical[:, 1]], axis=1)
    return CameraView(intrinsics, directions, optical[:, 2].copy(), near_m, far_m)


@dataclass(frozen=True)
class Scene:
    """What a camera can see, placed in the world.

    Attributes:
        solids: Walls, boxes and cylinders (each with its colour, or the palette's).
        meshes: Mesh obstacles (trimesh meshes), in the world frame.
        parts: The robot's collision parts.
        part_transforms: ``transform_part_to_world`` of each part for this frame, (S, 4, 4).
        palette: Colours where none is given.
        part_rgb: Colour of each part (its link's URDF material); empty: the palette's.
        mesh_rgb: Colour of each mesh; empty: the palette's.
    """

    solids: Sequence[Solid] = ()
    meshes: Sequence[raycast.Mesh] = ()
    parts: Sequence[Part] = ()
    part_transforms: FloatArray | None = None
    palette: Palette = Palette()
    part_rgb: Sequence[Rgb] = ()
    mesh_rgb: Sequence[Rgb] = ()

    def posed(self, part_transforms: FloatArray) -> Scene:
        """This scene with the parts at ``part_transforms``; what does not move is kept."""
        moved = dataclasses.replace(self, part_transforms=part_transforms)
        for name in ("packed_world", "triangles", "part_triangles"):  # once for every pose
            moved.__dict__[name] = getattr(self, name)
        return moved

    def part_colour(self, index: int) -> Rgb:
        """The colour of part ``index``."""
        return self.part_rgb[index] if self.part_rgb else self.palette.robot

    def mesh_colour(self, index: int) -> Rgb:
        """The colour of mesh ``index``."""
        return self.mesh_rgb[index] if self.mesh_rgb else self.palette.mesh

    @functools.cached_property
    def packed_world(self) -> tuple[FloatArray, ...]:
        """The solids as the compiled loop reads them, then each part's kind, size, colour."""
        kinds = [PART_KINDS.index(s.kind) for s in self.solids]
        part_kinds = [PART_KINDS.index(p.kind) for p in self.parts]
        return (np.array(kinds, np.int64), _rows([s.half_m for s in self.solids], (3,)),
                _rows([s.rotation for s in self.solids], (3, 3)),
                _rows([s.center_m for s in self.solids], (3,)),
                _rows([self.palette.of_solid(s) for s in self.solids], (3,)),
                np.array(part_kinds, np.int64), _rows([p.half_m for p in self.parts], (3,)),
                _rows([self.part_colour(i) for i in range(len(self.parts))], (3,)))

    @functools.cached_property
    def triangles(self) -> camera_mesh.Triangles:
        """The meshes' triangles and their hierarchy, for the compiled loop."""
        return camera_mesh.triangles(self.meshes, [self.mesh_colour(i)
                                                   for i in range(len(self.meshes))])

    @functools.cached_property
    def part_triangles(self) -> camera_mesh.PartTriangles:
        """The mesh parts' triangles, each part's in its own frame under its own root."""
        return camera_mesh.part_triangles(self.parts)


def _rows(values: Sequence[object], shape: tuple[int, ...]) -> FloatArray:
    return np.array(values, dtype=np.float64).reshape(len(values), *shape)


def render(view: CameraView, transform_camera_to_world: FloatArray, scene: Scene,
           noise_stddev: float = 0.0, rng: np.random.Generator | None = None, *,
           depth: bool = True) -> Frame:
    """The frame the camera at ``transform_camera_to_world`` sees of ``scene``.

    With noise, the frame takes one key from ``rng`` (seed 0 when None); ``depth`` False
    leaves the frame's depth image empty.
    """
    poses = None if scene.part_transforms is None else scene.part_transforms[None]
    return render_frames(view, transform_camera_to_world[None], scene, poses, noise_stddev,
                         rng if rng is not None else np.random.default_rng(0), depth=depth)[0]


def render_frames(view: CameraView, transforms_camera_to_world: FloatArray, scene: Scene,
                  part_transforms: FloatArray | None, noise_stddev: float,
                  rng: np.random.Generator, *, depth: bool = True) -> tuple[Frame, ...]:
    """Frames from the camera at each of ``transforms_camera_to_world`` (F, 4, 4).

    ``part_transforms`` (F, S, 4, 4) places ``scene``'s parts in each frame. With noise,
    each frame takes one key from ``rng``, in order; the frames are the bytes that
    :func:`render` gives for each alone.
    """
    count = len(transforms_camera_to_world)
    keys = np.array([camera_noise.frame_key(rng) if noise_stddev > 0.0 else 0
                     for _ in range(count)], dtype=np.uint64)
    rows, columns = view.shape
    rgb = np.empty((count, rows * columns, 3), dtype=np.uint8)
    depth_m = np.empty((count, rows * columns if depth else 0), dtype=np.float32)
    rotations = np.ascontiguousarray(transforms_camera_to_world[:, :3, :3], dtype=np.float64)
    origins = np.ascontiguousarray(transforms_camera_to_world[:, :3, 3], dtype=np.float64)
    poses = np.zeros((count, 0, 4, 4)) if part_transforms is None else part_transforms
    if not (COMPILED and _compiled(view, rotations, origins, scene, poses, keys,
                                   noise_stddev * 255.0, rgb, depth_m)):
        from servicebot_cli.simulate.sensors import camera_numpy

        for f in range(count):
            camera_numpy.render(view, rotations[f], origins[f], scene.posed(poses[f]), keys[f],
                                noise_stddev * 255.0, rgb[f], depth_m[f])
    return tuple(Frame(rgb[f].reshape(rows, columns, 3),
                       depth_m[f].reshape(rows, columns) if depth
                       else np.zeros((0, 0), np.float32)) for f in range(count))


def load_renderer() -> bool:
    """Import numba and the compiled loop ahead of the first frame; False without numba."""
    try:
        from servicebot_cli.simulate.sensors import camera_kernel  # noqa: F401 -- loading
    except ModuleNotFoundError as exc:
        if exc.name != "numba":
            raise
        return False
    return True


def _compiled(view: CameraView, rotations: FloatArray, origins: FloatArray, scene: Scene,
              part_transforms: FloatArray, keys: npt.NDArray[np.uint64], scale: float,
              rgb: npt.NDArray[np.uint8], depth_m: npt.NDArray[np.float32]) -> bool:
    """Fill ``rgb`` and ``depth_m`` in numba's compiled loop; False without numba."""
    if not load_renderer():
        return False
    import numba  # type: ignore[import-untyped, import-not-found, unused-ignore]

    from servicebot_cli.simulate.sensors import camera_kernel
    kinds, halves, rotations_s, centres, colours, part_kinds, part_halves, part_colours = \
        scene.packed_world
    t, p = scene.triangles, scene.part_triangles
    roots = np.concatenate((np.full(len(kinds), -1, np.int64), p.root))
    with numba.parallel_chunksize(1):  # a frame at a time to whichever thread is free
        camera_kernel.render(
            rotations, origins, (view.directions, view.forward, view.shape[1], view.near_m,
                                 view.far_m, view.pinhole),
            (kinds, halves, rotations_s, centres, colours),
            (part_kinds, part_halves, part_colours,
             np.ascontiguousarray(part_transforms[:, :, :3, :3]),
             np.ascontiguousarray(part_transforms[:, :, :3, 3])),
            _arrays(t), (_arrays(p.triangles), roots),
            (np.array(scene.palette.floor, dtype=np.float64),
             np.array(scene.palette.sky, dtype=np.float64), LIGHT, AMBIENT),
            (keys, scale, camera_noise.normal_table()), rgb, depth_m)
    return True


def _arrays(t: camera_mesh.Triangles) -> tuple[npt.NDArray[np.generic], ...]:
    """``t``'s arrays in the order the compiled loop unpacks them."""
    return (t.corner, t.edge_1, t.edge_2, t.normal, t.colour, t.low, t.high, t.first, t.count)


def field_of_view_rad(intrinsics: Intrinsics) -> float:
    """The horizontal field of view ``intrinsics`` describe [rad]."""
    return 2.0 * math.atan(intrinsics.width_px / (2.0 * intrinsics.k[0]))
