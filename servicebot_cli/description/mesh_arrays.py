"""What the fast mesh readers share: their error, number lists, face indices, bounds.

Faces given as rows of a vertex table are checked against it (:func:`checked`); polygons are
fan-triangulated (:func:`fan_counts`); :func:`bounds` is the box of a set of points. Used by
:mod:`~servicebot_cli.description.mesh_readers` and the OBJ and COLLADA readers. Pure.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.description import number_text

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]


class MeshFormatError(ValueError):
    """The file is not a readable mesh of its format."""


def checked(vertex_count: int, index: IntArray) -> IntArray:
    """``index`` (F, 3), once every row it names is one of ``vertex_count`` vertices."""
    if len(index) and (index.min() < 0 or index.max() >= vertex_count):
        raise MeshFormatError("a face refers to a vertex that does not exist")
    return index


def fan_counts(vertex_count: int, indices: IntArray, counts: IntArray) -> IntArray:
    """Fan-triangulate polygons given as flat ``indices`` with ``counts`` corners each.

    Polygons of fewer than three corners (a COLLADA polylist's lines) have no area: their
    corners are left out with them. Counts that ask for more corners than ``indices`` has
    are refused before anything is made of them.

    Raises:
        MeshFormatError: Counts beyond the index list, or a face naming a missing vertex.
    """
    if len(counts) and (counts.min() < 0 or int(counts.sum()) > len(indices)):
        raise MeshFormatError("a polygon list shorter than its vertex counts")
    polygons = counts >= 3
    if not polygons.all():
        indices = indices[:int(counts.sum())][np.repeat(polygons, counts)]
        counts = counts[polygons]
    if not len(counts):
        return np.zeros((0, 3), dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    per = counts - 2
    first = np.repeat(starts, per)
    step = np.arange(per.sum()) - np.repeat(np.cumsum(per) - per, per) + 1
    corners = np.stack([first, first + step, first + step + 1], axis=1)
    if corners.max() >= len(indices):
        raise MeshFormatError("a polygon list shorter than its vertex counts")
    return checked(vertex_count, indices[corners])


def numbers(text: str | bytes | None, dtype: type = np.float64) -> np.ndarray:
    """Whitespace-separated numbers (see :mod:`number_text`)."""
    try:
        return number_text.numbers(text, dtype)
    except number_text.NumberListError as exc:
        raise MeshFormatError(str(exc)) from None


def bounds(points: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Lower and upper corners of ``(n, 3)`` points, shape (3,) each (NaN if a point has one).

    One column at a time: numpy reduces ``axis=0`` of an ``(n, 3)`` array twenty times
    slower than it reduces a strided column.
    """
    lower = np.array([points[:, axis].min() for axis in range(3)])
    upper = np.array([points[:, axis].max() for axis in range(3)])
    return lower, upper
