"""Mesh files: read once, summarised as size, volume and second moments.

The one place ``check`` reads mesh files. STL, OBJ and COLLADA go through the fast readers
of :mod:`mesh_readers`; other formats through trimesh, imported only then.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.library_logs import captured
from servicebot_cli.description import mesh_readers

if TYPE_CHECKING:
    from servicebot_cli.check.mesh_store import MeshStore

LARGEST_COORDINATE = 1e9
"""Meshes with coordinates beyond this (in the file's units) get no mass properties."""


class MeshError(Exception):
    """A mesh file that cannot be loaded; the message says why."""


@dataclass(frozen=True)
class MassProperties:
    """Volume and second moments of a closed mesh, for unit density, in the file's units.

    Attributes:
        volume: Enclosed volume.
        centroid: Centre of the enclosed volume.
        second_moment: ``integral of (x - c)(x - c)^T dV`` about ``centroid`` (3x3).
    """

    volume: float
    centroid: tuple[float, float, float]
    second_moment: np.ndarray


@dataclass(frozen=True)
class MeshInfo:
    """What the rules need to know of a mesh, in the file's units (before ``<mesh scale>``).

    Attributes:
        triangles: Number of triangles.
        lower, upper: Corners of the axis-aligned bounding box.
        mass: Volume and moments when asked for and the mesh is closed (every edge shared
            by exactly two triangles), else None.
        closed: Whether the mesh is closed; None when not asked for.
    """

    triangles: int
    lower: tuple[float, float, float]
    upper: tuple[float, float, float]
    mass: MassProperties | None = None
    closed: bool | None = None


def load_mesh(path: Path, with_mass: bool = False) -> MeshInfo:
    """Read and summarise the mesh at ``path``; ``with_mass`` adds volume and moments.

    Raises:
        MeshError: Unreadable, not a mesh of its format, or holding NaNs.
    """
    try:
        data = mesh_readers.read_file(path)
    except mesh_readers.LfsPointer as exc:
        raise MeshError(str(exc)) from None
    except mesh_readers.MeshFormatError as exc:  # too large
        raise MeshError(f"{exc}; is it the right file?") from None
    except OSError as exc:
        raise MeshError(f"cannot read: {exc.strerror or exc}") from None
    suffix = path.suffix.lower()
    try:
        with np.errstate(all="ignore"):  # a file's 1e300 or inf: found not finite below
            return _read(path, data, suffix, with_mass)
    except (mesh_readers.MeshFormatError, ValueError, IndexError) as exc:
        raise MeshError(str(exc) or type(exc).__name__) from None


def _read(path: Path, data: bytes, suffix: str, with_mass: bool) -> MeshInfo:
    """:func:`load_mesh` once the file is read."""
    if suffix == ".dae" and not with_mass:
        return _bounds_only(*mesh_readers.read_dae_bounds(data))
    if suffix == ".obj":  # as Assimp reads it: RViz, Gazebo and MoveIt do
        return summarise_indexed(*mesh_readers.read_indexed(suffix, data, as_assimp=True),
                                 with_mass)
    if suffix == ".ply":  # bounded, with what is wrong said as ik says it
        from servicebot_cli.kinematics.mesh_ply import read_ply

        return summarise_indexed(*read_ply(data), with_mass)
    if not suffix:
        raise MeshError("its name has no suffix (.stl, .dae, .obj), from which Assimp (RViz, "
                        "Gazebo, MoveIt) takes a mesh's format")
    if suffix in mesh_readers.SUFFIXES:  # every triangle's corners, as summarise takes them
        triangles = mesh_readers.read_triangles(suffix, data)
    else:
        triangles = _with_trimesh(path)
    if not np.all(np.isfinite(triangles)):
        raise MeshError("vertices with NaN or infinite coordinates")
    return summarise(triangles, with_mass)


def _bounds_only(count: int, lower: np.ndarray, upper: np.ndarray) -> MeshInfo:
    if not (np.all(np.isfinite(lower)) and np.all(np.isfinite(upper))):
        raise MeshError("vertices with NaN or infinite coordinates")
    return MeshInfo(count, _xyz(lower), _xyz(upper))


def _with_trimesh(path: Path) -> np.ndarray:
    try:
        import trimesh
    except ImportError:  # pragma: no cover - trimesh is a dependency
        raise MeshError(f"no reader for '{path.suffix}' files (install trimesh)") from None
    try:
        with path.open("rb") as handle:
            mesh_readers.refuse_lfs_pointer(handle.read(64))
    except mesh_readers.LfsPointer as exc:
        raise MeshError(str(exc)) from None
    except OSError:
        pass  # trimesh says why below
    try:
        with captured():  # texture chatter: check reports geometry, with its own findings
            loaded = trimesh.load(path, force="mesh", process=False)
    except Exception as exc:  # trimesh raises anything from its many loaders
        raise MeshError(f"it is no {path.suffix} mesh trimesh can read "
                        f"({type(exc).__name__}: {exc})") from None
    if not hasattr(loaded, "triangles"):
        raise MeshError("trimesh found no triangles")
    return np.asarray(loaded.triangles, dtype=np.float64).reshape(-1, 3, 3)


def summarise(triangles: np.ndarray, with_mass: bool = False) -> MeshInfo:
    """Bounding box of ``(n, 3, 3)`` triangles, and their mass properties if asked."""
    if len(triangles) == 0:
        return _empty(with_mass)
    lower, upper = mesh_readers.bounds(triangles.reshape(-1, 3))
    if not with_mass:
        return MeshInfo(len(triangles), _xyz(lower), _xyz(upper))
    return _with_mass(len(triangles), lower, upper, lambda: triangles,
                      lambda size: _closed(_welded(triangles.reshape(-1, 3), size)
                                           .reshape(-1, 3)))


def summarise_indexed(vertices: np.ndarray, faces: np.ndarray,
                      with_mass: bool = False) -> MeshInfo:
    """:func:`summarise` of triangles given as rows ``faces`` (F, 3) of ``vertices`` (V, 3).

    The same summary, from the vertices the faces use, each once: vertices no face uses
    count for nothing, as they are not in the triangles.

    Raises:
        MeshError: A vertex a face uses has a NaN or infinite coordinate.
    """
    if len(faces) == 0:
        return _empty(with_mass)
    used = np.zeros(len(vertices), dtype=bool)
    used[faces.ravel()] = True
    points = vertices if used.all() else vertices[used]
    if not np.all(np.isfinite(points)):
        raise MeshError("vertices with NaN or infinite coordinates")
    lower, upper = mesh_readers.bounds(points)
    if not with_mass:
        return MeshInfo(len(faces), _xyz(lower), _xyz(upper))
    if points is not vertices:  # the faces as rows of the used vertices
        faces = (np.cumsum(used) - 1)[faces]
    return _with_mass(len(faces), lower, upper, lambda: points[faces],
                      lambda size: _closed(_welded(points, size)[faces]))


def _empty(with_mass: bool) -> MeshInfo:
    zero = (0.0, 0.0, 0.0)
    return MeshInfo(0, zero, zero, None, False if with_mass else None)


def _with_mass(count: int, lower: np.ndarray, upper: np.ndarray,
               triangles: Callable[[], np.ndarray], closed_at: Callable[[float], bool]
               ) -> MeshInfo:
    """The summary of ``count`` triangles, with their mass properties if closed.

    ``closed_at(size)`` says whether the mesh is closed; only then are ``triangles()``
    (n, 3, 3) made and measured.
    """
    if not np.maximum(np.abs(lower), np.abs(upper)).max() <= LARGEST_COORDINATE:
        return MeshInfo(count, _xyz(lower), _xyz(upper), None, False)
    closed = closed_at(float(np.abs(upper - lower).max()))
    mass = mass_properties(triangles()) if closed else None
    if mass is not None and not (math.isfinite(mass.volume)
                                 and np.all(np.isfinite(mass.second_moment))):
        mass = None
    return MeshInfo(count, _xyz(lower), _xyz(upper), mass, closed)


def mass_properties(triangles: np.ndarray) -> MassProperties:
    r"""Volume, centroid and second moments of a closed triangle mesh, for unit density.

    Sums signed tetrahedra from the origin: volume :math:`v = \det[a\,b\,c] / 6`, second
    moment :math:`v / 20 (a a^T + b b^T + c c^T + s s^T)` with :math:`s = a + b + c`.
    """
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = a.T, b.T, c.T
    # a . (b x c) by columns: numpy's cross and einsum cost more in calls than in arithmetic
    v = (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)) / 6.0
    s = a + b + c
    volume = float(v.sum())
    weight = (v / 20.0)[:, None]
    moment = (s * weight).T @ s  # a 3 x n by n x 3 product: BLAS, 4x einsum's speed
    for p in (a, b, c):
        moment += (p * weight).T @ p
    centroid = v @ s / (4.0 * volume) if volume else s.mean(axis=0) / 3.0
    if volume < 0:  # inward-facing triangles: same magnitudes
        volume, moment = -volume, -moment
    moment = moment - volume * np.outer(centroid, centroid)
    return MassProperties(volume, _xyz(centroid), moment)


def _xyz(values: np.ndarray) -> tuple[float, float, float]:
    """A 3-vector as three floats, a zero always +0.0.

    The least of 0.0 and -0.0 is whichever comes first, so a bound's sign of zero would
    depend on the order the vertices are read in.
    """
    x, y, z = (float(v) + 0.0 for v in values)
    return x, y, z


def _welded(points: np.ndarray, size: float) -> np.ndarray:
    """A key per point (P,), equal for points that coincide within ``size * 1e-7``.

    The key is a hash of the point's position rounded to that tolerance, so the same
    positions get the same keys whether each is given once (a vertex table) or once per
    corner. Two far positions could share a key only by a 64-bit hash collision.
    """
    tolerance = max(size, 1e-12) * 1e-7
    keys = np.round(points / tolerance).astype(np.int64)
    packed = keys[:, 0] * 73856093 + keys[:, 1] * 19349663 + keys[:, 2] * 83492791
    return _mixed(packed.view(np.uint64))


def _mixed(values: np.ndarray) -> np.ndarray:
    """A 64-bit hash of each of ``values`` (uint64): splitmix64's finaliser, a bijection."""
    mixed: np.ndarray = values ^ (values >> np.uint64(30))
    mixed *= np.uint64(0xBF58476D1CE4E5B9)
    mixed ^= mixed >> np.uint64(27)
    mixed *= np.uint64(0x94D049BB133111EB)
    mixed ^= mixed >> np.uint64(31)
    return mixed


def _closed(keys: np.ndarray) -> bool:
    """Every edge of the triangles ``keys`` (n, 3) (welded position keys) shared by exactly two.

    An edge is its two ends' keys, in either order, hashed into one; an edge whose ends
    weld into one point is no edge.
    """
    first, second = keys.T.ravel(), keys[:, [1, 2, 0]].T.ravel()  # each triangle's three edges
    low, high = np.minimum(first, second), np.maximum(first, second)
    edge = low != high
    return _each_twice(_mixed(low[edge]) ^ high[edge])


def _each_twice(keys: np.ndarray) -> bool:
    """Whether every one of ``keys`` (uint64 hashes) is there exactly twice.

    The keys go into buckets by their low bits, counted: a bucket of an odd count holds a
    key an odd number of times; a bucket of two holds one key twice or two keys once each.
    Only the keys of fuller buckets (about a fifth) are sorted, which took most of the time.
    """
    if not len(keys) or len(keys) % 2:
        return False
    size = 1 << (2 * len(keys) - 1).bit_length()  # at least twice as many buckets as keys
    buckets = (keys & np.uint64(size - 1)).astype(np.intp)
    counts = np.bincount(buckets, minlength=size)
    if np.any(counts & 1):
        return False
    some = np.zeros(size, dtype=np.uint64)
    some[buckets] = keys  # one key of each bucket
    pairs = counts[buckets] == 2
    if not np.all(keys[pairs] == some[buckets[pairs]]):
        return False
    rest = np.sort(keys[~pairs])  # the keys of buckets of four or more, every key's copies
    # sorted, every key twice: pairs (0, 1), (2, 3) ... are equal, and neighbouring pairs differ
    return bool(np.all(rest[0::2] == rest[1::2]) and np.all(rest[2::2] != rest[1:-1:2]))


class MeshCache:
    """Loads each mesh file once per run (and again only to add mass properties).

    With a ``store`` (``--mesh-cache``), summaries also come from, and go to, the disk.
    """

    def __init__(self, store: MeshStore | None = None) -> None:
        self._seen: dict[Path, MeshInfo | MeshError] = {}
        self._store = store

    def get(self, path: Path, with_mass: bool = False) -> MeshInfo:
        """The summary of ``path``; raises the same MeshError every time for a bad file."""
        found = self._seen.get(path)
        if found is None or (with_mass and isinstance(found, MeshInfo) and found.closed is None):
            found = self._load(path, with_mass)
            self._seen[path] = found
        if isinstance(found, MeshError):
            raise found
        return found

    def _load(self, path: Path, with_mass: bool) -> MeshInfo | MeshError:
        store = self._store
        found = None if store is None else store.get(path, with_mass)
        if found is None:
            try:
                found = load_mesh(path, with_mass)
            except MeshError as exc:
                found = exc
            if store is not None:
                store.put(path, with_mass, found)
        return found
