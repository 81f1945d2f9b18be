"""Where a wheel drawn as a mesh is, and its radius: from the mesh's vertices.

A wheel whose link has no cylinder or sphere (a CAD export: every link a mesh) rolls on
what its collision mesh is. About the joint's axis, a wheel's mesh is round: as wide across
the axis, each way, as twice its farthest vertex from the axis. Its middle is the wheel's
centre, which may sit along the axle from the joint (tortoisebot's wheels are 0.014 m
outward of their joints), and that farthest distance its radius. A mesh that is not round
says nothing. Collision meshes come first, as they are what touches the floor.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Link, Shape
    from servicebot_cli.description.packages import PackageResolver

FloatArray = npt.NDArray[np.float64]
MeshPoints = Callable[["Shape"], "FloatArray | None"]
"""The vertices (n, 3) of a mesh shape, scaled as its ``<mesh scale>`` says, in the shape's
own frame [m]; None when the mesh cannot be read."""

ROUND = 0.05
"""How far a wheel mesh's width across its axis, each way, may fall short of its diameter."""


def round_mesh(link: Link, axis_in_link: FloatArray,
               points: MeshPoints) -> tuple[FloatArray, float] | None:
    """The centre (in the link's frame) [m] and radius [m] of the link's round mesh.

    The first mesh, collisions before visuals, round about ``axis_in_link`` (of unit
    length): as wide across the axis, each way, as the farthest vertex is from the axis
    through its middle, which a box or a bracket is not (its corners are farther out).
    None where no mesh is.
    """
    for shape in (*link.collisions, *link.visuals):
        if shape.geometry.kind != "mesh":
            continue
        vertices = points(shape)
        if vertices is None or not len(vertices):
            continue
        placed = pose_matrix(shape.origin)
        found = _round(vertices, placed[:3, :3].T @ axis_in_link)
        if found is None:
            continue
        centre, radius = found
        return (placed @ np.append(centre, 1.0))[:3], radius
    return None


def _round(vertices: FloatArray, axis: FloatArray) -> tuple[FloatArray, float] | None:
    """The middle and radius of ``vertices`` about ``axis`` (unit, their frame), if round."""
    across = np.linalg.svd(axis.reshape(1, 3))[2][1:]  # two unit vectors normal to the axis
    frame = np.vstack([axis, across])  # rows: the axis, then across it
    local = vertices @ frame.T
    lower, upper = local.min(axis=0), local.max(axis=0)
    middle = (lower + upper) / 2
    radius = float(np.max(np.linalg.norm(local[:, 1:] - middle[1:], axis=1)))
    widths = upper[1:] - lower[1:]
    if not (np.isfinite(radius) and radius > 0 and np.all(widths >= (1 - ROUND) * 2 * radius)):
        return None
    return middle @ frame, radius


def no_points(shape: Shape) -> None:
    """No mesh read: for what needs only which joints the wheels are, not where."""
    return None


def file_points(resolver: PackageResolver | None, base_dir: Path) -> MeshPoints:
    """Mesh vertices read from the files (STL, OBJ, COLLADA), each file once.

    ``resolver`` finds ``package://`` meshes (default: the file's workspace and the
    environment's packages); ``base_dir`` is where relative names start.
    """
    from servicebot_cli.description.packages import PackageResolver

    finder = resolver or PackageResolver.from_environment(context=base_dir)

    def path_of(shape: Shape) -> Path | None:
        try:
            return finder.resolve_uri(shape.geometry.filename or "", base_dir)
        except Exception:  # noqa: BLE001 -- a package nowhere, a remote mesh: nothing known
            return None

    return points_at(path_of, {})


def points_at(path_of: Callable[[Shape], Path | None],
              read: dict[Path, FloatArray | None]) -> MeshPoints:
    """The vertices of the file ``path_of`` finds for a shape (None: none), scaled.

    Each file is read once into ``read``, which may outlive the reader (a run's cache).
    """
    def points(shape: Shape) -> FloatArray | None:
        path = path_of(shape)
        if path is None:
            return None
        if path not in read:
            read[path] = read_vertices(path)
        return scaled(read[path], shape.geometry.scale)

    return points


def read_vertices(path: Path) -> FloatArray | None:
    """The vertices of the mesh file ``path`` (STL, OBJ, COLLADA); None if unreadable."""
    from servicebot_cli.common.inputs import not_a_file
    from servicebot_cli.description import mesh_readers

    if path.suffix.lower() not in mesh_readers.SUFFIXES or not_a_file(path) is not None:
        return None  # a pipe would block, a device read without end
    try:
        data = mesh_readers.read_file(path)
        with np.errstate(all="ignore"):
            vertices, _ = mesh_readers.read_indexed(path.suffix, data)
    except (OSError, mesh_readers.MeshFormatError, ValueError, IndexError):
        return None
    return vertices if len(vertices) and np.all(np.isfinite(vertices)) else None


def scaled(vertices: FloatArray | None, scale: tuple[float, float, float]) -> FloatArray | None:
    """A mesh file's ``vertices`` with its shape's ``scale`` applied."""
    return None if vertices is None else vertices * np.asarray(scale, dtype=np.float64)
