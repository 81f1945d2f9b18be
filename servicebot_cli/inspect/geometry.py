"""Visual geometry placed in the root frame, its meshes, and bounding boxes.

Primitives are bounded exactly (a cylinder's box follows from its axis, not from a polygon);
meshes are read with trimesh, found through the description's package resolver, and
measured vertex by vertex. A mesh that cannot be found or read is reported, not fatal:
``inspect`` still shows everything else, and ``check`` is the place to fix it.
"""

from __future__ import annotations

import io
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import PackageNotFound, ServicebotError
from servicebot_cli.description import mesh_readers
from servicebot_cli.description.elements import Shape
from servicebot_cli.description.safe_xml import declaration_first
from servicebot_cli.kinematics.mesh_wheels import scaled
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
FAR_M = 1e6
"""Sizes and places beyond this [m] are no robot's: such shapes are not drawn or bounded."""


@dataclass(frozen=True)
class PosedShape:
    """A visual shape and ``transform_shape_to_root`` (4x4) at some configuration."""

    link: str
    shape: Shape
    transform: FloatArray = field(compare=False)


@dataclass(frozen=True)
class Mesh:
    """Mesh vertices [m] (scaled, in the shape frame), shape (n, 3), and triangles (m, 3)."""

    vertices: FloatArray
    faces: npt.NDArray[np.int64]


@dataclass
class MeshLibrary:
    """Loads each mesh file once and remembers the ones that failed.

    Attributes:
        resolver: Finds ``package://`` files.
        base_dir: Directory that relative mesh paths are relative to.
        problems: One line per mesh that could not be used.
    """

    resolver: PackageResolver
    base_dir: Path
    problems: list[str] = field(default_factory=list)
    _cache: dict[str, Mesh | None] = field(default_factory=dict)
    # a missing package's message: its problem line, its first mesh, how many it hides
    _hidden: dict[str, tuple[int, str, int]] = field(default_factory=dict)

    def _no_package(self, filename: str, message: str) -> None:
        """One problem line per missing package, saying how many meshes it hides."""
        line, first, count = self._hidden.get(message, (len(self.problems), filename, 0))
        count += 1
        if count == 1:
            self.problems.append(f"mesh {filename}: {message}")
        else:
            self.problems[line] = f"{count} meshes ({first} and others): {message}"
        self._hidden[message] = (line, first, count)

    def points(self, shape: Shape) -> FloatArray | None:
        """The vertices of ``shape``'s mesh, scaled; None if unusable."""
        mesh = self.get(shape.geometry.filename or "")
        return None if mesh is None else scaled(mesh.vertices, shape.geometry.scale)

    def get(self, filename: str) -> Mesh | None:
        """The mesh at ``filename`` (as written in the URDF), unscaled; None if unusable."""
        if filename not in self._cache:
            self._cache[filename] = self._load(filename)
        return self._cache[filename]

    def _load(self, filename: str) -> Mesh | None:
        try:
            path = self.resolver.resolve_uri(filename, self.base_dir)
        except PackageNotFound as exc:  # once per package: Pepper's hid 47 meshes
            self._no_package(filename, str(exc))
            return None
        except ServicebotError as exc:
            self.problems.append(f"mesh {filename}: {exc}")
            return None
        if not os.path.isfile(path):
            self.problems.append(f"mesh {filename}: no such file ({path})")
            return None
        if path.suffix.lower() in mesh_readers.SUFFIXES:
            read = _with_our_readers(path)
            if isinstance(read, str):
                self.problems.append(f"mesh {filename}: cannot read: {read}")
                return None
            return self._usable(filename, *read)
        import trimesh

        from servicebot_cli.common.library_logs import captured

        try:
            # numpy's overflow warnings on huge coordinates are not ours to show: the
            # coordinates are refused below, in our words
            with captured() as said, np.errstate(all="ignore"):
                loaded = _load_with_trimesh(trimesh, path)
            self.problems.extend(f"mesh {filename}: {line}" for line in dict.fromkeys(said))
            if not isinstance(loaded, trimesh.Trimesh):
                raise TypeError(f"not a triangle mesh but a {type(loaded).__name__}")
            vertices, faces = _triangles(loaded.vertices, loaded.faces)
        except Exception as exc:  # noqa: BLE001 -- trimesh raises many types for bad files
            self.problems.append(f"mesh {filename}: cannot read: {type(exc).__name__}: {exc}")
            return None
        return self._usable(filename, vertices, faces)

    def _usable(self, filename: str, vertices: FloatArray,
                faces: npt.NDArray[np.int64]) -> Mesh | None:
        """The mesh, or None with a problem line when there is nothing sane to draw."""
        if len(vertices) == 0:
            self.problems.append(f"mesh {filename}: has no vertices")
            return None
        if not np.all(np.isfinite(vertices)) or np.max(np.abs(vertices)) > FAR_M:
            self.problems.append(f"mesh {filename}: not drawn: it has coordinates that are not "
                                 f"finite numbers within {FAR_M:g} (check reports it)")
            return None
        return Mesh(vertices, faces)


def _with_our_readers(path: Path) -> tuple[FloatArray, npt.NDArray[np.int64]] | str:
    """STL, OBJ and COLLADA as ``check`` and ``simulate`` read them, or why they cannot be.

    The same triangles as trimesh (a test holds them to it on every mesh of
    example-robot-data), in a fraction of its time, and past the defects Assimp reads past
    (velodyne_simulator's ``name="<STL_BINARY>"``).
    """
    try:
        data = mesh_readers.read_file(path)
        with np.errstate(all="ignore"):  # a file's 1e300: refused in our words by _usable
            vertices, faces = mesh_readers.read_indexed(path.suffix, data)
    except OSError as exc:
        return exc.strerror or str(exc)
    except (mesh_readers.MeshFormatError, ValueError, IndexError) as exc:
        return str(exc) or type(exc).__name__
    return vertices, faces.astype(np.int64)


def _triangles(points: Any, triangles: Any) -> tuple[FloatArray, npt.NDArray[np.int64]]:
    """A trimesh mesh's vertices as an (n, 3) array and its faces as an (m, 3) array.

    Raises:
        ValueError: The vertices are not 3D points (trimesh keeps an OBJ's ``v`` lines of
            two numbers as 2D points) or the faces are not triangles of them.
    """
    vertices = np.asarray(points, dtype=np.float64)
    faces = np.asarray(triangles, dtype=np.int64)
    if vertices.ndim != 2:
        raise ValueError("its vertices are not a list of points")
    if vertices.shape[1] != 3:
        raise ValueError(f"its vertices have {vertices.shape[1]} coordinates, not 3")
    if len(faces) and (faces.ndim != 2 or faces.shape[1] != 3 or faces.min() < 0
                       or faces.max() >= len(vertices)):
        raise ValueError("its faces are not triangles of its vertices")
    return vertices, faces


def _load_with_trimesh(trimesh: Any, path: Path) -> Any:
    """``trimesh.load`` of ``path``, as Assimp reads it.

    A COLLADA file whose ``<?xml ...?>`` follows blank lines (Assimp reads it, lxml refuses
    it) is read with the declaration moved first.
    """
    if path.suffix.lower() == ".dae":
        data = path.read_bytes()
        fixed = declaration_first(data)
        if fixed is not data:
            return trimesh.load(io.BytesIO(fixed), file_type="dae", force="mesh",
                                resolver=trimesh.resolvers.FilePathResolver(str(path)))
    return trimesh.load(str(path), force="mesh")


def mesh_library(robot: RobotDescription, resolver: PackageResolver) -> MeshLibrary:
    """A MeshLibrary for ``robot``'s meshes (relative paths from its file's directory)."""
    return MeshLibrary(resolver, robot.path.parent)


def posed_visuals(robot: RobotDescription,
                  link_transforms: Mapping[str, FloatArray]) -> list[PosedShape]:
    """Every visual shape of every placed link, in URDF order."""
    posed = []
    for link in robot.links:
        transform = link_transforms.get(link.name)
        if transform is None:
            continue
        for shape in link.visuals:
            if shape.geometry.kind:
                posed.append(PosedShape(link.name, shape, transform @ pose_matrix(shape.origin)))
    return posed


def unusable(posed: PosedShape) -> str | None:
    """Why a placed shape cannot be drawn or bounded, or None when it can.

    A size or a place that is not a finite number within :data:`FAR_M` is no robot's: check
    reports the value; inspect leaves the shape out instead of drawing nonsense.
    """
    g = posed.shape.geometry
    sizes = [v for v in (g.radius, g.length, *(g.size or ()), *g.scale) if v is not None]
    if not all(math.isfinite(v) and abs(v) <= FAR_M for v in sizes):
        return f"a size is not a finite number within {FAR_M:g} m"
    t = posed.transform
    if not np.all(np.isfinite(t)) or np.max(np.abs(t[:3, 3])) > FAR_M:
        return f"its origin is not a finite place within {FAR_M:g} m"
    return None


def shape_bounds(posed: PosedShape, meshes: MeshLibrary) -> FloatArray | None:
    """Axis-aligned box ``[[xmin, ymin, zmin], [xmax, ymax, zmax]]`` [m] of a placed shape.

    For a cylinder of radius r and length l whose axis has unit direction a, the half extent
    along world axis i is ``|a_i| l / 2 + r sqrt(1 - a_i^2)``.
    """
    g, t = posed.shape.geometry, posed.transform
    centre, rotation = t[:3, 3], t[:3, :3]
    if unusable(posed):
        return None
    if g.kind == "box" and g.size is not None:
        half = np.abs(rotation) @ (np.abs(np.array(g.size, dtype=float)) / 2)
    elif g.kind == "cylinder" and g.radius is not None and g.length is not None:
        axis = rotation[:, 2]
        half = np.abs(axis) * abs(g.length) / 2 + abs(g.radius) * np.sqrt(
            np.clip(1 - axis**2, 0, 1))
    elif g.kind == "sphere" and g.radius is not None:
        half = np.full(3, abs(g.radius))
    elif g.kind == "mesh" and g.filename:
        mesh = meshes.get(g.filename)
        if mesh is None:
            return None
        points = (mesh.vertices * np.array(g.scale)) @ rotation.T + centre
        return np.array([points.min(axis=0), points.max(axis=0)])
    else:
        return None
    if not np.all(np.isfinite(half)):
        return None
    return np.array([centre - half, centre + half])


def bounding_box(shapes: list[PosedShape], meshes: MeshLibrary) -> FloatArray | None:
    """The box around every shape, ``[[min xyz], [max xyz]]`` [m]; None when there is none."""
    boxes = [b for b in (shape_bounds(s, meshes) for s in shapes) if b is not None]
    if not boxes:
        return None
    stacked = np.array(boxes)
    return np.array([stacked[:, 0].min(axis=0), stacked[:, 1].max(axis=0)])

