"""A bounded reader of PLY meshes (ASCII and binary): the vertex table and its triangles.

The fast readers of :mod:`~servicebot_cli.description.mesh_readers` cover STL, OBJ and
COLLADA; a PLY collision mesh would otherwise go to Assimp (through coal) unread, which
crashes on a face naming a vertex that does not exist and allocates whatever a header
claims. Here the header's element counts are first held against the file's size (every
element takes at least so many bytes), then the elements are read and the faces checked
against the vertex table. Pure.
"""

from __future__ import annotations

import numpy as np

from servicebot_cli.description.mesh_arrays import (
    FloatArray,
    IntArray,
    MeshFormatError,
    fan_counts,
    numbers,
)
from servicebot_cli.kinematics.ply_header import PlyElement, check_sizes, ply_header

_FACE_LISTS = ("vertex_indices", "vertex_index")


def read_ply(data: bytes) -> tuple[FloatArray, IntArray]:
    """A PLY's vertices (V, 3) and its faces as triangles of them (F, 3), fan-triangulated.

    Raises:
        MeshFormatError: Not a PLY file, a header whose counts the file cannot hold, or a
            face naming a vertex that does not exist.
    """
    fmt, elements, body = ply_header(data)
    check_sizes(fmt, elements, len(body))
    if fmt:
        rows = _binary(body, fmt, elements)
    else:
        rows = _ascii(body, elements)
    vertices = np.zeros((0, 3))
    faces = np.zeros((0, 3), dtype=np.int64)
    for element, (scalars, _) in zip(elements, rows, strict=True):
        if element.name == "vertex":
            vertices = _xyz(element, scalars)
    for element, (_, lists) in zip(elements, rows, strict=True):
        if element.name == "face":
            faces = _faces(element, lists, len(vertices))
    return vertices, faces


_Rows = tuple[np.ndarray, list[np.ndarray]]
"""An element's scalar columns (count, scalars) and each list property's rows."""


def _ascii(body: bytes, elements: list[PlyElement]) -> list[_Rows]:
    values = numbers(body)
    at = 0
    rows: list[_Rows] = []
    for element in elements:
        props = element.properties
        if all(p.count_kind is None for p in props):
            width = len(props)
            block = values[at:at + element.count * width]
            if len(block) < element.count * width:
                raise MeshFormatError(f"a PLY file that ends inside its '{element.name}' list")
            rows.append((block.reshape(element.count, width), []))
            at += element.count * width
            continue
        width = _ascii_width(values, element, at)
        uniform = _ascii_uniform(values, element, at, width)
        if uniform is not None:
            rows.append(uniform)
            at += width * element.count
            continue
        scalars = np.zeros((element.count, sum(p.count_kind is None for p in props)))
        lists: list[list[np.ndarray]] = [[] for p in props if p.count_kind is not None]
        for row in range(element.count):
            column = 0
            which = 0
            for prop in props:
                if at >= len(values):
                    raise MeshFormatError(f"a PLY file that ends inside its '{element.name}' "
                                          "list")
                if prop.count_kind is None:
                    scalars[row, column] = values[at]
                    column, at = column + 1, at + 1
                    continue
                n = values[at]
                if not (0 <= n <= len(values) - at - 1) or n != int(n):
                    raise MeshFormatError(f"a PLY '{element.name}' list with a bad length")
                lists[which].append(values[at + 1:at + 1 + int(n)])
                which, at = which + 1, at + 1 + int(n)
        rows.append((scalars, _flat(lists)))
    return rows


def _ascii_width(values: FloatArray, element: PlyElement, at: int) -> int:
    """How many numbers the element's first row holds, its lists as long as they say."""
    width = 0
    for prop in element.properties:
        width += 1
        if prop.count_kind is not None:
            n = values[at + width - 1] if at + width - 1 < len(values) else -1.0
            if not (0 <= n <= len(values)) or n != int(n):
                return -1
            width += int(n)
    return width


def _ascii_uniform(values: FloatArray, element: PlyElement, at: int, width: int
                   ) -> _Rows | None:
    """The element read in one pass when every row is ``width`` long (as the first); or None."""
    if element.count == 0 or width <= 0 or at + width * element.count > len(values):
        return None
    block = values[at:at + width * element.count].reshape(element.count, width)
    columns, lists, column = [], [], 0
    for prop in element.properties:
        if prop.count_kind is None:
            columns.append(block[:, column])
            column += 1
            continue
        n = int(block[0, column])
        if not np.all(block[:, column] == n):
            return None
        lists.append(block[:, column + 1:column + 1 + n])
        column += 1 + n
    scalars = np.stack(columns, axis=1) if columns else np.zeros((element.count, 0))
    return scalars, lists


def _flat(lists: list[list[np.ndarray]]) -> list[np.ndarray]:
    """Each list property's rows as one object array of arrays."""
    out = []
    for rows in lists:
        holder = np.empty(len(rows), dtype=object)
        holder[:] = rows
        out.append(holder)
    return out


def _binary(body: bytes, fmt: str, elements: list[PlyElement]) -> list[_Rows]:
    at = 0
    rows: list[_Rows] = []
    for element in elements:
        props = element.properties
        if all(p.count_kind is None for p in props):
            record = np.dtype([(f"p{k}", fmt + p.kind) for k, p in enumerate(props)])
            table = _frombuffer(body, record, element, at)
            at += record.itemsize * element.count
            columns = [table[f"p{k}"].astype(np.float64) for k in range(len(props))]
            scalars = np.stack(columns, axis=1) if columns else np.zeros((element.count, 0))
            rows.append((scalars, []))
            continue
        uniform = _uniform_lists(body, fmt, element, at)
        if uniform is not None:
            (scalars, lists), at = uniform
            rows.append((scalars, lists))
            continue
        scalar_rows: list[list[float]] = []
        list_rows: list[list[np.ndarray]] = [[] for p in props if p.count_kind is not None]
        for _ in range(element.count):
            row: list[float] = []
            which = 0
            for prop in props:
                kind = np.dtype(fmt + (prop.count_kind or prop.kind))
                value = _frombuffer(body, kind, element, at, 1)[0]
                at += kind.itemsize
                if prop.count_kind is None:
                    row.append(float(value))
                    continue
                item = np.dtype(fmt + prop.kind)
                items = _frombuffer(body, item, element, at, int(value))
                at += item.itemsize * int(value)
                list_rows[which].append(items.astype(np.float64))
                which += 1
            scalar_rows.append(row)
        scalars = np.array(scalar_rows, dtype=np.float64).reshape(element.count, -1)
        rows.append((scalars, _flat(list_rows)))
    return rows


def _uniform_lists(body: bytes, fmt: str, element: PlyElement, at: int
                   ) -> tuple[_Rows, int] | None:
    """The element read in one pass when every row's lists are as long as the first row's.

    None when they are not (or the element is empty): read row by row.
    """
    if element.count == 0:
        return None
    props, offset = element.properties, at
    fields: list[tuple[str, str] | tuple[str, str, tuple[int]]] = []
    for k, prop in enumerate(props):
        if prop.count_kind is None:
            fields.append((f"p{k}", fmt + prop.kind))
            offset += np.dtype(prop.kind).itemsize
            continue
        count_type = np.dtype(fmt + prop.count_kind)
        n = int(_frombuffer(body, count_type, element, offset, 1)[0])
        if n < 0:
            return None
        fields.append((f"n{k}", count_type.str))
        fields.append((f"p{k}", fmt + prop.kind, (n,)))
        offset += count_type.itemsize + np.dtype(prop.kind).itemsize * n
    record = np.dtype(fields)
    if at + record.itemsize * element.count > len(body):
        return None
    table = np.frombuffer(body, record, element.count, at)
    columns, lists = [], []
    for k, prop in enumerate(props):
        if prop.count_kind is None:
            columns.append(table[f"p{k}"].astype(np.float64))
            continue
        if not np.all(table[f"n{k}"] == table[f"n{k}"][0]):
            return None
        lists.append(table[f"p{k}"].astype(np.float64).reshape(element.count, -1))
    scalars = np.stack(columns, axis=1) if columns else np.zeros((element.count, 0))
    return (scalars, lists), at + record.itemsize * element.count


def _frombuffer(body: bytes, kind: np.dtype, element: PlyElement, at: int,
                count: int | None = None) -> np.ndarray:
    n = element.count if count is None else count
    if n < 0 or at + kind.itemsize * n > len(body):
        raise MeshFormatError(f"a PLY file that ends inside its '{element.name}' list")
    return np.frombuffer(body, kind, n, at)


def _xyz(element: PlyElement, scalars: np.ndarray) -> FloatArray:
    names = [p.name for p in element.properties if p.count_kind is None]
    if not all(axis in names for axis in "xyz"):
        raise MeshFormatError("PLY vertices without x, y and z")
    vertices: FloatArray = scalars[:, [names.index(axis) for axis in "xyz"]]
    return vertices


def _faces(element: PlyElement, lists: list[np.ndarray], vertex_count: int) -> IntArray:
    names = [p.name for p in element.properties if p.count_kind is not None]
    found = [n for n in _FACE_LISTS if n in names]
    if not found:
        raise MeshFormatError("PLY faces without a vertex_indices list")
    rows = lists[names.index(found[0])]
    if rows.dtype != object:  # every face the same length: (F, n)
        counts = np.full(len(rows), rows.shape[1] if rows.ndim == 2 else 0, dtype=np.int64)
        flat = rows.reshape(-1)
    else:
        counts = np.array([len(r) for r in rows], dtype=np.int64)
        flat = np.concatenate(list(rows)) if len(rows) else np.zeros(0)
    if not np.all(flat == np.round(flat)):
        raise MeshFormatError("a PLY face with an index that is not a whole number")
    if len(flat) and not (flat.min() >= 0 and flat.max() < vertex_count):
        raise MeshFormatError("a face refers to a vertex that does not exist")
    polygons = counts >= 3  # points and edges are no triangles (fan_counts wants none)
    flat = flat[np.repeat(polygons, counts)]
    return fan_counts(vertex_count, flat.astype(np.int64), counts[polygons])
