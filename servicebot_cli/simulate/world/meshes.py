"""Mesh files: obstacles placed in the world (trimesh), and links' collision meshes.

A mesh obstacle (a room, a shelf) is placed with its pose and scale. LIDAR rays hit it through
trimesh (Embree when ``embreex`` is installed); the robot's links touch its surface through
Coal (:mod:`.contacts`). A link's collision mesh is read with its ``scale`` for
:mod:`..shape`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.located import Located
from servicebot_cli.simulate.shape import MeshReader, MeshUnreadable
from servicebot_cli.simulate.world.raycast import Mesh

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Geometry
    from servicebot_cli.description.packages import PackageResolver

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_HEIGHTS = (0.02, 0.5, 0.98)  # fractions of the base's height where the outline is tested


def load_meshes(scenario: Scenario, base_dir: Path) -> list[Mesh]:
    """The scenario's meshes, placed in the world (relative files are from ``base_dir``).

    Raises:
        ScenarioError: A missing or unreadable mesh, naming the scenario line.
    """
    if not scenario.world.meshes:
        return []
    import trimesh

    from servicebot_cli.common.library_logs import captured  # logging: only with meshes

    located = scenario.source or Located({}, {}, scenario.name)
    meshes: list[Mesh] = []
    for i, spec in enumerate(scenario.world.meshes):
        path = Path(spec.file) if Path(spec.file).is_absolute() else base_dir / spec.file
        where = ("world", "meshes", i, "file")
        if not os.path.isfile(path):
            raise located.error(where, f"'{spec.file}' is not a file (looked in {path})")
        try:
            with captured():  # texture chatter: only the geometry matters here
                mesh = trimesh.load(path, force="mesh")
        except Exception as exc:  # trimesh raises many types for unreadable files
            raise located.error(where, f"cannot load '{spec.file}' as a mesh: {exc}") from None
        if not isinstance(mesh, trimesh.Trimesh) or not len(mesh.faces):
            raise located.error(where, f"'{spec.file}' has no triangles")
        if not np.all(np.isfinite(mesh.vertices)) or _not_finite(path):
            # trimesh drops a face with a 'v nan nan nan' corner: a box with holes in it
            raise located.error(where, f"'{spec.file}' has coordinates that are not finite")
        transform = np.eye(4)
        transform[:3, :3] = rpy_matrix(*spec.rpy_rad) * spec.scale
        transform[:3, 3] = spec.xyz_m
        mesh.apply_transform(transform)
        meshes.append(mesh)
    return meshes


def _not_finite(path: Path) -> bool:
    """Whether a file the fast readers read (STL, OBJ, COLLADA) has a coordinate not finite."""
    from servicebot_cli.description import mesh_readers

    if path.suffix.lower() not in mesh_readers.SUFFIXES:
        return False
    try:
        _load_triangles(path)
    except MeshUnreadable as exc:
        return "not finite" in str(exc)
    return False


def link_mesh_reader(resolver: PackageResolver, base_dir: Path) -> MeshReader:
    """Reads a link's mesh ``<geometry>``: its file resolved and loaded, and scaled.

    Each file is loaded once; ``base_dir`` is where relative references start.
    """
    loaded: dict[Path, tuple[FloatArray, IntArray]] = {}

    def read(geometry: Geometry) -> tuple[FloatArray, IntArray]:
        try:
            path = resolver.resolve_uri(geometry.filename or "", base_dir)
        except Exception as exc:  # PackageNotFound and friends: the message says where
            raise MeshUnreadable(str(exc)) from None
        if path not in loaded:
            loaded[path] = _load_triangles(path)
        vertices, faces = loaded[path]
        return vertices * np.asarray(geometry.scale, dtype=np.float64), faces

    return read


def _load_triangles(path: Path) -> tuple[FloatArray, IntArray]:
    """Vertices (V, 3) and triangles (F, 3) of a mesh file.

    STL, OBJ and COLLADA are read by the fast readers (COLLADA's ``<unit meter>`` applied, as
    Gazebo and RViz apply it; trimesh leaves it out); other formats by trimesh.

    Raises:
        MeshUnreadable: Missing, unreadable, empty, or with coordinates that are not finite.
    """
    if not os.path.isfile(path):
        raise MeshUnreadable(f"{path} is not a file")
    from servicebot_cli.description import mesh_readers

    if path.suffix.lower() in mesh_readers.SUFFIXES:
        try:
            vertices, faces = mesh_readers.read_indexed(path.suffix, path.read_bytes())
        except (OSError, mesh_readers.MeshFormatError, ValueError, IndexError) as exc:
            raise MeshUnreadable(f"cannot read {path}: {exc}") from None
    else:
        vertices, faces = _with_trimesh(path)
    if not len(faces):
        raise MeshUnreadable(f"{path} has no triangles")
    if not np.all(np.isfinite(vertices)):
        raise MeshUnreadable(f"{path} has coordinates that are not finite")
    return vertices, faces


def _with_trimesh(path: Path) -> tuple[FloatArray, IntArray]:
    import trimesh

    from servicebot_cli.common.library_logs import captured  # logging: only with meshes

    try:
        with captured():  # texture chatter: only the geometry matters here
            mesh = trimesh.load(path, force="mesh")
    except Exception as exc:  # trimesh raises many types for unreadable files
        raise MeshUnreadable(f"trimesh cannot read {path}: {exc}") from None
    if not isinstance(mesh, trimesh.Trimesh):
        raise MeshUnreadable(f"{path} has no triangles")
    return (np.asarray(mesh.vertices, dtype=np.float64),
            np.asarray(mesh.faces, dtype=np.int64))
