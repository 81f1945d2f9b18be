"""A fast reader of Wavefront OBJ meshes: the vertex table and triangles as rows of it.

Vertex and face lines are cut out of the file in runs of neighbouring lines (or found by
regular expression) and parsed by numpy in one pass (faces in
:mod:`~servicebot_cli.description.mesh_obj_faces`); a file that pass cannot read is read
line by line. Pure.
"""

from __future__ import annotations

import re

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.mesh_arrays import (
    FloatArray,
    IntArray,
    MeshFormatError,
    checked,
    fan_counts,
    numbers,
)
from servicebot_cli.description.mesh_obj_assimp import assimp_misread
from servicebot_cli.description.mesh_obj_faces import face_corners
from servicebot_cli.description.number_text import plain_numbers

# an OBJ's vertex and face lines after a newline; the first line is matched on its own
_OBJ_VERTEX = re.compile(rb"\n[ \t]*v[ \t]([^\r\n]*)")
_OBJ_FACE = re.compile(rb"\n[ \t]*f[ \t]([^\r\n]*)")
_OBJ_FIRST_LINE = re.compile(rb"[ \t]*([vf])[ \t]([^\r\n]*)")
_V, _F, _T, _SPACE, _TAB, _NEWLINE = 118, 102, 116, 32, 9, 10
_FEW_RUNS = 64  # runs of vertex or face lines cut out one by one; more, if a line in eight

Lines = tuple[bytes, int]  # the contents of some lines after their keyword, joined by newlines


def read_obj_indexed(data: bytes, *, as_assimp: bool = False) -> tuple[FloatArray, IntArray]:
    """A Wavefront OBJ's vertex table (V, 3) and triangles as rows of it (F, 3), from 0.

    Polygons are fan-triangulated. Vertex and face lines are cut out of the file in runs
    of neighbouring lines and parsed by numpy; a file this cannot read in one pass
    (negative indices, continued lines, a corner that is not an index) is read line by
    line, which also says what is wrong with it. ``as_assimp`` also refuses what Assimp
    reads wrong (:mod:`.mesh_obj_assimp`), looked for only where the vertex numbers are
    not written plainly.

    Raises:
        MeshFormatError: A vertex without three numbers, or a face naming a vertex that does
            not exist; with ``as_assimp``, a line Assimp reads wrong.
    """
    if data.startswith(b"\xef\xbb\xbf"):  # a UTF-8 byte order mark, as Assimp skips it
        data = data[3:]
    if b"\r" in data and b"\n" not in data:  # classic Mac OS line ends: CR only
        data = data.replace(b"\r", b"\n")
    if b"\\" in data and (b"\\\n" in data or b"\\\r" in data):  # continued lines
        _refuse_misread(data, as_assimp)
        return _read_obj_lines(data)
    found = _in_runs(data)
    if found is None:  # lines that start with blanks, and the like: the whole file is read
        _refuse_misread(data, as_assimp)
        found = _by_expression(data), False
    ((vertex_text, vertex_count), (face_text, face_count)), dotted_textures = found
    if dotted_textures:
        _refuse_misread(data, as_assimp)
    faces = face_corners(face_text, face_count)
    if faces is None:
        _refuse_misread(data, as_assimp)
        return _read_obj_lines(data)
    indices, counts = faces
    values = plain_numbers(vertex_text)
    if values is None:
        _refuse_misread(data, as_assimp)
        values = numbers(vertex_text)
    table = _obj_vertices(vertex_text, vertex_count, values)
    if len(counts) and counts.min() == 3 == counts.max():  # triangles only, as most are
        return table, checked(len(table), (indices - 1).reshape(-1, 3))
    polygons = counts >= 3  # a face of one or two corners has no area: left out
    return table, fan_counts(len(table), indices[np.repeat(polygons, counts)] - 1,
                              counts[polygons])


def _in_runs(data: bytes) -> tuple[tuple[Lines, Lines], bool] | None:
    """The vertex and face lines, cut out of ``data`` a run of neighbouring lines at a time.

    Also whether a texture coordinate (``vt``) line holds a blank before a point, which
    Assimp may read wrong (:mod:`.mesh_obj_assimp`). None where the regular expressions must
    find them: a line that starts with a blank, a carriage return inside a line, more runs
    than a line in eight.
    """
    chars = np.frombuffer(data + b"\n\n", dtype=np.uint8)
    newlines = np.flatnonzero(chars[:len(data)] == _NEWLINE)
    starts = np.empty(len(newlines) + 1, dtype=np.int64)
    starts[0], starts[1:] = 0, newlines + 1
    first, second = chars[starts], chars[starts + 1]
    if np.any((first == _SPACE) | (first == _TAB)):
        return None
    keyword = np.where((second == _SPACE) | (second == _TAB), first, 0)
    ends = np.append(newlines, len(data))
    vertices = _runs(data, keyword == _V, starts, ends, b"v")
    faces = _runs(data, keyword == _F, starts, ends, b"f")
    if vertices is None or faces is None:
        return None
    return (vertices, faces), _hold_dotted(data, (first == _V) & (second == _T), starts, ends)


def _hold_dotted(data: bytes, chosen: npt.NDArray[np.bool_], starts: IntArray,
                 ends: IntArray) -> bool:
    """Whether one of the ``chosen`` lines holds a blank before a point (``vt .5 0.5``)."""
    if not chosen.any():
        return False
    edges = np.flatnonzero(np.diff(np.concatenate(([False], chosen, [False]))))
    for first, after in zip(edges[0::2].tolist(), edges[1::2].tolist(), strict=True):
        run = data[starts[first]:ends[after - 1]]
        if b" ." in run or b"\t." in run:
            return True
    return False


def _runs(data: bytes, chosen: npt.NDArray[np.bool_], starts: IntArray, ends: IntArray,
          keyword: bytes) -> Lines | None:
    """The contents of the ``chosen`` lines (each after its keyword and one blank)."""
    edges = np.flatnonzero(np.diff(np.concatenate(([False], chosen, [False]))))
    if len(edges) > 2 * max(_FEW_RUNS, len(chosen) // 8):
        return None
    parts = []
    for first, after in zip(edges[0::2].tolist(), edges[1::2].tolist(), strict=True):
        run = data[starts[first] + 2:ends[after - 1]]  # from after the first line's keyword
        cut = run.replace(b"\n" + keyword + b" ", b"\n")
        keywords = 2 * (after - first - 1)  # each later line's keyword and blank
        if len(run) - len(cut) != keywords:
            cut = cut.replace(b"\n" + keyword + b"\t", b"\n")
            if len(run) - len(cut) != keywords:  # a keyword in a line's contents came first
                return None
        parts.append(cut)
    text = b"\n".join(parts)
    if b"\r" in text:  # CRLF line ends; a carriage return anywhere else ends the line there
        text = text.replace(b"\r\n", b"\n").removesuffix(b"\r")
        if b"\r" in text:
            return None
    return text, int(chosen.sum())


def _by_expression(data: bytes) -> tuple[Lines, Lines]:
    """The vertex and face lines, found by regular expression."""
    vertex_lines, face_lines = _OBJ_VERTEX.findall(data), _OBJ_FACE.findall(data)
    first = _OBJ_FIRST_LINE.match(data)
    if first:
        (vertex_lines if first[1] == b"v" else face_lines).insert(0, first[2])
    return (b"\n".join(vertex_lines), len(vertex_lines)), (b"\n".join(face_lines),
                                                          len(face_lines))


def _refuse_misread(data: bytes, as_assimp: bool) -> None:
    """With ``as_assimp``, raise MeshFormatError for a line of ``data`` Assimp reads wrong."""
    misread = assimp_misread(data) if as_assimp else None
    if misread is not None:
        raise MeshFormatError(misread)


def _obj_vertices(text: bytes, count: int, values: FloatArray) -> FloatArray:
    """``x y z`` of ``count`` ``v`` lines from their ``values`` (a weight, colours ignored)."""
    if len(values) == 3 * count:
        table: FloatArray = values.reshape(-1, 3)
        return table
    counts = np.array([len(line.split()) for line in text.split(b"\n")] if count else [],
                      dtype=np.int64)
    if np.any(counts < 3) or len(values) != int(counts.sum()):
        raise MeshFormatError("a vertex ('v' line) without three numbers")
    first = np.cumsum(counts) - counts
    table = values[first[:, None] + np.arange(3)]
    return table


def _read_obj_lines(data: bytes) -> tuple[FloatArray, IntArray]:
    """:func:`read_obj_indexed`, one line at a time."""
    vertices: list[list[float]] = []
    faces: list[list[int]] = []
    for raw in data.splitlines():
        parts = raw.split()
        if not parts:
            continue
        if parts[0] == b"v" and len(parts) >= 4:
            vertices.append([float(p) for p in parts[1:4]])
        elif parts[0] == b"f" and len(parts) >= 4:
            indices = [int(p.split(b"/")[0]) for p in parts[1:]]
            faces.append([i - 1 if i > 0 else len(vertices) + i for i in indices])
    table = np.array(vertices, dtype=np.float64).reshape(-1, 3)
    tris = [(p[0], p[i], p[i + 1]) for p in faces for i in range(1, len(p) - 1)]
    try:
        index = np.array(tris, dtype=np.int64).reshape(-1, 3)
    except OverflowError:  # an index beyond int64 names no vertex a file can hold
        raise MeshFormatError("a face refers to a vertex that does not exist") from None
    return table, checked(len(table), index)
