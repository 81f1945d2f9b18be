"""A fast reader of Wavefront OBJ meshes: the vertex table and triangles as rows of it.

Vertices and faces are found by regular expression and parsed by numpy in one pass; a file
that pass cannot read is read line by line. Pure.
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

# an OBJ's vertex and face lines after a newline; the first line is matched on its own
_OBJ_VERTEX = re.compile(rb"\n[ \t]*v[ \t]([^\r\n]*)")
_OBJ_FACE = re.compile(rb"\n[ \t]*f[ \t]([^\r\n]*)")
_OBJ_FIRST_LINE = re.compile(rb"[ \t]*([vf])[ \t]([^\r\n]*)")


def read_obj_indexed(data: bytes) -> tuple[FloatArray, IntArray]:
    """A Wavefront OBJ's vertex table (V, 3) and triangles as rows of it (F, 3), from 0.

    Polygons are fan-triangulated. Vertices and faces are found by regular expression and
    parsed by numpy; a file this cannot read in one pass (negative indices, continued lines,
    a corner that is not an index) is read line by line, which also says what is wrong with
    it.

    Raises:
        MeshFormatError: A vertex without three numbers, or a face naming a vertex that does
            not exist.
    """
    if data.startswith(b"\xef\xbb\xbf"):  # a UTF-8 byte order mark, as Assimp skips it
        data = data[3:]
    if b"\r" in data and b"\n" not in data:  # classic Mac OS line ends: CR only
        data = data.replace(b"\r", b"\n")
    if b"\\\n" in data or b"\\\r" in data:
        return _read_obj_lines(data)
    vertex_lines, face_lines = _OBJ_VERTEX.findall(data), _OBJ_FACE.findall(data)
    first = _OBJ_FIRST_LINE.match(data)
    if first:
        (vertex_lines if first[1] == b"v" else face_lines).insert(0, first[2])
    faces = _obj_faces(face_lines)
    if faces is None:
        return _read_obj_lines(data)
    indices, counts = faces
    table = _obj_vertices(vertex_lines)
    polygons = counts >= 3  # a face of one or two corners has no area: left out
    return table, fan_counts(len(table), indices[np.repeat(polygons, counts)] - 1,
                              counts[polygons])


def _obj_faces(faces: list[bytes]) -> tuple[IntArray, IntArray] | None:
    """Every corner's vertex index (from 1) and each face's corner count.

    None when a corner is not a positive index (a negative one counts from the vertices
    read so far, which only the line-by-line reader knows).
    """
    chars = np.frombuffer(b"\n".join(faces), np.uint8)
    blank = (chars == ord(" ")) | (chars == ord("\t")) | (chars == ord("\n"))
    if (chars == ord("/")).any():
        chars = _corner_vertices(chars, blank | (chars == ord("\r")) | (chars == ord("\f"))
                                 | (chars == ord("\v")))
        blank = (chars == ord(" ")) | (chars == ord("\t")) | (chars == ord("\n"))
    starts = ~blank & np.concatenate(([True], blank[:-1]))
    counts = np.bincount(np.cumsum(chars == ord("\n"))[starts], minlength=len(faces))
    try:
        indices = numbers(chars.tobytes(), np.int64)
    except MeshFormatError:
        return None
    if len(indices) != int(counts.sum()) or (len(indices) and indices.min() < 1):
        return None
    return indices, counts.astype(np.int64)


def _corner_vertices(chars: npt.NDArray[np.uint8], blank: npt.NDArray[np.bool_]
                     ) -> npt.NDArray[np.uint8]:
    """Face text without each corner's texture and normal indices: "7/2/5 8//6" -> "7 8".

    A character stays when it is blank or no slash stands between it and its corner's start.
    """
    slash = chars == ord("/")
    slashes = np.cumsum(slash, dtype=np.int64 if len(chars) >= 2**31 else np.int32)
    starts = np.flatnonzero(~blank & np.concatenate(([True], blank[:-1])))
    at_start = np.zeros(len(chars), slashes.dtype)  # the count before each corner's start
    if len(starts):
        at_start[starts[0]:] = np.repeat(slashes[starts] - slash[starts],
                                         np.diff(np.append(starts, len(chars))))
    kept: npt.NDArray[np.uint8] = chars[(slashes == at_start) | blank]
    return kept


def _obj_vertices(lines: list[bytes]) -> FloatArray:
    """``x y z`` of each ``v`` line (a fourth weight or vertex colours after them ignored)."""
    values = numbers(b" ".join(lines))
    if len(values) == 3 * len(lines):
        table: FloatArray = values.reshape(-1, 3)
        return table
    counts = np.array([len(line.split()) for line in lines], dtype=np.int64)
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
