"""Collision meshes read by the project's own readers before coal (Assimp) gets them.

Assimp trusts a mesh file: a PLY face naming a vertex that does not exist crashes the
process, and a header claiming 400 million vertices makes it allocate gigabytes (in native
code, where SIGTERM waits). So each collision mesh is first read here, by the bounded
readers of :mod:`~servicebot_cli.description.mesh_readers` (STL, OBJ, COLLADA) and
:mod:`~servicebot_cli.kinematics.mesh_ply` (PLY); one they cannot read, or that has no
triangles, is refused in one line naming the link and the file. Other formats go to Assimp
as they are. Each file is read once per process.

When coal still fails, :func:`coal_reason` keeps the words of its message that say why.
"""

from __future__ import annotations

import os
import re
import warnings
from collections.abc import Collection, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.errors import PackageNotFound, RemoteResource, UnknownScheme
from servicebot_cli.common.inputs import not_a_file

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

_NO_TRIANGLES = "it has no triangles"
_NOT_FINITE = "vertices with NaN or infinite coordinates"


@dataclass(frozen=True)
class CollisionMesh:
    """A ``<collision>`` mesh of a link.

    Attributes:
        link: The link's name.
        filename: The reference as written in the URDF.
        path: The file it resolves to (absolute).
    """

    link: str
    filename: str
    path: Path


def collision_meshes(robot: RobotDescription, resolver: PackageResolver,
                     omit: Collection[str] = (), skippable: bool = True
                     ) -> Iterator[CollisionMesh]:
    """``robot``'s collision meshes, their ``package://`` references resolved.

    Meshes whose filename is in ``omit`` are left out. ``skippable``: the command has
    ``--allow-collisions`` to do without the check, and the messages say so.

    Raises:
        PackageNotFound: A mesh in a package that is nowhere.
    """
    base_dir = robot.path.parent
    hint = "; --allow-collisions skips the check" if skippable else ""
    for link in robot.links:
        for shape in link.collisions:
            filename = shape.geometry.filename
            if shape.geometry.kind == "mesh" and filename and filename not in omit:
                try:
                    path = resolver.resolve_uri(filename, base_dir)
                except RemoteResource:
                    raise RemoteResource(f"collision mesh '{filename}' of link '{link.name}' "
                                         "is fetched over the network, which the collision "
                                         f"check does not do{hint}") from None
                except UnknownScheme as exc:
                    raise UnknownScheme(f"collision mesh '{filename}' of link '{link.name}': "
                                        f"{exc}{hint}") from None
                except PackageNotFound as exc:  # say what needs it, and how to do without
                    raise PackageNotFound(f"collision mesh '{filename}' of link '{link.name}': "
                                          f"{exc}" + ("; or --allow-collisions skips the "
                                                      "collision check that reads it"
                                                      if skippable else "")) from None
                yield CollisionMesh(link.name, filename, path.absolute())


def mesh_problem(robot: RobotDescription, meshes: Iterable[CollisionMesh],
                 skippable: bool = True) -> str | None:
    """The line that refuses the first collision mesh coal must not get; None: all fine."""
    for mesh in meshes:
        reason = _problem(mesh.path)
        if reason is None:
            continue
        what = "has no triangles" if reason == _NO_TRIANGLES else f"cannot be read: {reason}"
        return (f"{robot.display}: collision mesh '{mesh.filename}' of link '{mesh.link}' "
                f"{what} (run servicebot check {robot.display})"
                + ("; --allow-collisions skips the check" if skippable else ""))
    return None


_seen: dict[Path, tuple[tuple[int, int], str | None]] = {}
"""Each mesh file read so far: its size and time of change, and what is wrong with it."""


def _problem(path: Path) -> str | None:
    """What keeps ``path`` from coal (a short reason), or None; read once per process."""
    problem = not_a_file(path)
    if problem is not None:
        return f"{path} {problem}"
    try:
        status = os.stat(path)
    except OSError as exc:  # gone since
        return f"{exc.strerror or 'cannot open it'}: {path}"
    key = (status.st_size, status.st_mtime_ns)
    found = _seen.get(path)
    if found is not None and found[0] == key:
        return found[1]
    reason = _read(path, status.st_size)
    _seen[path] = (key, reason)
    return reason


def _read(path: Path, size: int) -> str | None:
    from servicebot_cli.description import mesh_readers  # only for a robot with meshes

    suffix = path.suffix.lower()
    if suffix not in (*mesh_readers.SUFFIXES, ".ply"):
        return None  # Assimp's alone to read
    too_large = mesh_readers.too_large(size)
    if too_large is not None:
        return too_large
    try:
        data = path.read_bytes()
    except OSError as exc:
        return f"{exc.strerror or 'cannot read it'}: {path}"
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")  # numpy's overflow words: the result says it
            return _mesh_problem(suffix, data)
    except (ValueError, IndexError) as exc:  # MeshFormatError is a ValueError
        return " ".join(str(exc).split()) or type(exc).__name__


def _mesh_problem(suffix: str, data: bytes) -> str | None:
    from servicebot_cli.description import mesh_readers
    from servicebot_cli.description.safe_xml import declaration_first
    from servicebot_cli.kinematics.mesh_ply import read_ply

    if suffix == ".dae":  # as check reads it: the counts, not the index lists (bounded)
        count, lower, upper = mesh_readers.read_dae_bounds(declaration_first(data))
        if not count:
            return _NO_TRIANGLES
        if count * 6 > len(data):  # a triangle's three indices take two bytes each at least
            return (f"it declares {count} triangles, more than its {len(data)} bytes hold")
        if not (np.isfinite(lower).all() and np.isfinite(upper).all()):
            return _NOT_FINITE
        return None
    vertices, faces = (read_ply(data) if suffix == ".ply"
                       else mesh_readers.read_indexed(suffix, data, as_assimp=True))
    if not len(faces):
        return _NO_TRIANGLES
    corners = vertices[faces]
    if not np.isfinite(corners).all():
        return _NOT_FINITE
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    if ((a == b).all(axis=1) | (b == c).all(axis=1) | (a == c).all(axis=1)).all():
        return "every triangle has two corners at one point (Assimp drops those)"
    return None


_COAL_MESSAGE = re.compile(r"\bmessage:\s*(.*)", re.DOTALL)
_HINT = "Hint: the mesh directory may be wrong."
_NOT_LOADED = "Could not load resource "


def coal_reason(text: str, meshes: list[CollisionMesh]) -> tuple[CollisionMesh | None, str]:
    """The mesh coal's error ``text`` is about (if one of ``meshes``), and why, in short.

    Keeps what follows coal's ``message:`` (not its source file and function), and drops
    Assimp's hint on the mesh directory when the file is there.
    """
    text = " ".join(text.split())
    found = _COAL_MESSAGE.search(text)
    reason = found.group(1) if found else text
    mesh = None
    if reason.startswith(_NOT_LOADED):
        rest = reason[len(_NOT_LOADED):]
        for candidate in sorted(meshes, key=lambda m: -len(str(m.path))):
            if rest.startswith(str(candidate.path)):
                mesh, reason = candidate, rest[len(str(candidate.path)):].strip()
                break
    reason = reason.replace("std::bad_alloc", "out of memory")
    if reason.endswith(_HINT) and mesh is not None and os.path.isfile(mesh.path):
        reason = reason[:-len(_HINT)].strip()
    return mesh, reason.rstrip(" .") or "Assimp cannot load it"
