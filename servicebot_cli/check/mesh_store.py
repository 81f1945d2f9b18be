"""``check urdf --mesh-cache``: mesh summaries kept between runs in the user's cache directory.

Reading meshes is most of a check's time. A summary (:class:`~servicebot_cli.check.meshes.MeshInfo`,
or why the file cannot be read) is a few hundred bytes, stored as JSON under a key of the
file's resolved path, size, modification time and whether mass properties were asked for:
a file that changes in any way gets a new key. Entries are written atomically (a temporary
file renamed into place), so concurrent workers and runs never see half an entry; an entry
that cannot be read is recomputed. Nothing is stored without ``--mesh-cache``.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
from pathlib import Path

import numpy as np

from servicebot_cli.check.meshes import MassProperties, MeshError, MeshInfo

_VERSION = 2  # bumped when what a summary holds, or how it is computed, changes


def default_directory() -> Path:
    """``$XDG_CACHE_HOME/servicebot/meshes``, else ``~/.cache/servicebot/meshes``."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "servicebot" / "meshes"


class MeshStore:
    """Mesh summaries on disk, one small JSON file each."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory

    def _entry(self, path: Path, with_mass: bool) -> Path | None:
        try:
            stat = path.stat()
        except OSError:
            return None
        key = f"{_VERSION}\0{path.resolve()}\0{stat.st_size}\0{stat.st_mtime_ns}\0{with_mass}"
        digest = hashlib.sha256(key.encode("utf-8", "surrogateescape")).hexdigest()
        return self.directory / digest[:2] / f"{digest[2:]}.json"

    def get(self, path: Path, with_mass: bool) -> MeshInfo | MeshError | None:
        """The stored summary of ``path``; None when there is none (or it is unreadable)."""
        entry = self._entry(path, with_mass)
        if entry is None:
            return None
        try:
            return _decode(json.loads(entry.read_text()))
        except (OSError, ValueError, KeyError, TypeError, IndexError):
            return None

    def put(self, path: Path, with_mass: bool, found: MeshInfo | MeshError) -> None:
        """Keep ``found`` for ``path``; a cache that cannot be written is left alone."""
        entry = self._entry(path, with_mass)
        if entry is None:
            return
        try:
            entry.parent.mkdir(parents=True, exist_ok=True)
            handle, temporary = tempfile.mkstemp(dir=entry.parent, suffix=".tmp")
            try:
                with os.fdopen(handle, "w") as out:
                    json.dump(_encode(found), out)
                os.replace(temporary, entry)
            except BaseException:
                Path(temporary).unlink(missing_ok=True)
                raise
        except OSError:
            return


def _encode(found: MeshInfo | MeshError) -> dict[str, object]:
    if isinstance(found, MeshError):
        return {"error": str(found)}
    mass = found.mass
    return {"triangles": found.triangles, "lower": list(found.lower),
            "upper": list(found.upper), "closed": found.closed,
            "mass": None if mass is None else {
                "volume": _number(mass.volume), "centroid": [_number(v) for v in mass.centroid],
                "second_moment": [[_number(v) for v in row]
                                  for row in mass.second_moment.tolist()]}}


def _number(value: float) -> float | str:
    """JSON has no inf or NaN: those as text."""
    return value if math.isfinite(value) else repr(value)


def _decode(data: dict[str, object]) -> MeshInfo | MeshError:
    if "error" in data:
        return MeshError(str(data["error"]))
    mass = data["mass"]
    properties = None
    if isinstance(mass, dict):
        properties = MassProperties(float(mass["volume"]), _xyz(mass["centroid"]),
                                    np.array(mass["second_moment"], dtype=np.float64))
    closed = data["closed"]
    triangles = data["triangles"]
    if not isinstance(triangles, int) or not (closed is None or isinstance(closed, bool)):
        raise TypeError("not a mesh summary")
    return MeshInfo(triangles, _xyz(data["lower"]), _xyz(data["upper"]), properties, closed)


def _xyz(values: object) -> tuple[float, float, float]:
    if not isinstance(values, list) or len(values) != 3:
        raise TypeError("not three numbers")
    x, y, z = (float(v) for v in values)
    return x, y, z
