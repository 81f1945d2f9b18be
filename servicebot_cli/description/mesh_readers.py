"""Fast readers for the common mesh formats: STL (binary and ASCII), OBJ and COLLADA.

Each returns the triangles as an ``(n, 3, 3)`` float array (an OBJ also as its vertex
table and faces) in the file's own length unit times COLLADA's ``<unit meter>``, as Assimp
(Gazebo's and RViz's reader) applies it. Loading trimesh costs most of a second, so these
cover the formats robot descriptions use, for ``check`` and for the simulator's link
shapes; anything else goes through trimesh. A test compares them with trimesh on every
mesh of the example-robot-data corpus.

This module is the readers' entry point (:func:`read_indexed` by file suffix) and reads
STL; OBJ is read in :mod:`~servicebot_cli.description.mesh_obj`, COLLADA in
:mod:`~servicebot_cli.description.mesh_collada`, and what they share is in
:mod:`~servicebot_cli.description.mesh_arrays`. ``check`` and the simulator use the names
in ``__all__``.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from servicebot_cli.common.accidents import LFS_POINTER
from servicebot_cli.description.mesh_arrays import FloatArray, IntArray, MeshFormatError, bounds
from servicebot_cli.description.mesh_collada import read_dae, read_dae_bounds
from servicebot_cli.description.mesh_obj import read_obj_indexed
from servicebot_cli.description.safe_xml import declaration_first

__all__ = ["MOST_BYTES", "SUFFIXES", "LfsPointer", "MeshFormatError", "bounds", "read_dae_bounds",
           "read_file", "read_indexed", "read_stl", "read_triangles", "refuse_lfs_pointer",
           "too_large"]

MOST_BYTES = 1_000_000_000
"""The largest mesh file read (a scanned building is a few hundred MB); a 3 GB sparse file
was read whole."""

SUFFIXES = (".stl", ".obj", ".dae")
"""The formats these readers read (any case); others are left to trimesh."""


def too_large(size: int) -> str | None:
    """Why a mesh file of ``size`` bytes is not read, or None when it is not too large."""
    if size <= MOST_BYTES:
        return None
    return f"the file is {size / 1e9:.1f} GB, over the {MOST_BYTES / 1e9:.0f} GB a mesh is read to"


_LFS_POINTER = LFS_POINTER.encode()


class LfsPointer(MeshFormatError):
    """A Git LFS pointer file where the mesh should be: the repository's LFS files not pulled."""


def refuse_lfs_pointer(head: bytes) -> None:
    """Raise :class:`LfsPointer` when a file begins as a Git LFS pointer does.

    A clone without git-lfs (or a download of the repository's archive) has a few lines of
    text naming the mesh's hash where the mesh should be: NVIDIA's urdf-importer-extension
    holds 168 of them.
    """
    if head.startswith(_LFS_POINTER):
        raise LfsPointer("a Git LFS pointer, not the mesh: the repository's large files were "
                         "not fetched; run 'git lfs pull' in it")


def read_file(path: Path) -> bytes:
    """The bytes of the mesh at ``path``; a COLLADA file's with its XML declaration first.

    Raises:
        MeshFormatError: The file is over :data:`MOST_BYTES` (:func:`too_large` says so).
        OSError: It cannot be read.
    """
    why = too_large(path.stat().st_size)
    if why is not None:
        raise MeshFormatError(why)
    data = path.read_bytes()
    refuse_lfs_pointer(data)
    return declaration_first(data) if path.suffix.lower() == ".dae" else data


def read_indexed(suffix: str, data: bytes, *,
                 as_assimp: bool = False) -> tuple[FloatArray, IntArray]:
    """A mesh's vertices (V, 3) and its triangles as rows of them (F, 3), by file suffix.

    An OBJ gives its vertex table; STL and COLLADA a vertex per triangle corner. With
    ``as_assimp``, an OBJ that Assimp reads wrong is refused (:func:`read_obj_indexed`).

    Raises:
        MeshFormatError: Not a readable mesh of its format.
        ValueError: ``suffix`` is none of :data:`SUFFIXES`.
    """
    if suffix.lower() == ".obj":
        return read_obj_indexed(data, as_assimp=as_assimp)
    triangles = read_triangles(suffix, data)
    return triangles.reshape(-1, 3), np.arange(3 * len(triangles), dtype=np.int64).reshape(-1, 3)


def read_triangles(suffix: str, data: bytes) -> FloatArray:
    """The triangles (F, 3, 3) of an STL or COLLADA file, which list each triangle's corners.

    Raises:
        MeshFormatError: Not a readable mesh of its format.
        ValueError: ``suffix`` is neither ``.stl`` nor ``.dae``.
    """
    kind = suffix.lower()
    if kind not in (".stl", ".dae"):
        raise ValueError(f"no fast triangle reader for '{suffix}' files")
    return read_stl(data) if kind == ".stl" else read_dae(data)


def read_stl(data: bytes) -> FloatArray:
    """Triangles of a binary or ASCII STL."""
    if len(data) >= 84:
        count = int.from_bytes(data[80:84], "little")
        if 84 + 50 * count == len(data):
            record = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
            return np.frombuffer(data, record, count, 84)["v"].astype(np.float64)
    head = data[:512].lstrip().lower()
    if not head.startswith(b"solid"):
        raise MeshFormatError("not an STL file (neither binary nor ASCII)")
    numbers = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
    try:
        vertices = np.array(numbers, dtype=np.float64)
    except ValueError:
        raise MeshFormatError("ASCII STL with a vertex that is not three numbers") from None
    if len(vertices) % 3:
        raise MeshFormatError("ASCII STL whose vertex count is not a multiple of 3")
    return vertices.reshape(-1, 3, 3)
