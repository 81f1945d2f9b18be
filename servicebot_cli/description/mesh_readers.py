"""Fast readers for the common mesh formats: STL (binary and ASCII), OBJ and COLLADA.

Each returns the triangles as an ``(n, 3, 3)`` float array (an OBJ also as its vertex
table and faces) in the file's own length unit times COLLADA's ``<unit meter>``, as Assimp
(Gazebo's and RViz's reader) applies it. Loading trimesh costs most of a second, so these
cover the formats robot descriptions use, for ``check`` and for the simulator's link
shapes; anything else goes through trimesh. A test compares them with trimesh on every
mesh of the example-robot-data corpus.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import numpy as np
import numpy.typing as npt

from servicebot_cli.description import number_text
from servicebot_cli.description.collada_xml import ColladaXmlError, parse_collada

FloatArray = npt.NDArray[np.float64]
_IDENTITY = np.eye(4)
_MOST_NESTED_INSTANCES = 32  # <instance_node> within placed library nodes
_MOST_NODE_VISITS = 100_000  # nodes placed: library nodes can place each other many times
IntArray = npt.NDArray[np.int64]


class MeshFormatError(ValueError):
    """The file is not a readable mesh of its format."""


SUFFIXES = (".stl", ".obj", ".dae")
"""The formats these readers read (any case); others are left to trimesh."""


def read_indexed(suffix: str, data: bytes) -> tuple[FloatArray, IntArray]:
    """A mesh's vertices (V, 3) and its triangles as rows of them (F, 3), by file suffix.

    An OBJ gives its vertex table; STL and COLLADA a vertex per triangle corner.

    Raises:
        MeshFormatError: Not a readable mesh of its format.
        ValueError: ``suffix`` is none of :data:`SUFFIXES`.
    """
    kind = suffix.lower()
    if kind == ".obj":
        return read_obj_indexed(data)
    if kind not in (".stl", ".dae"):
        raise ValueError(f"no fast reader for '{suffix}' files")
    triangles = read_stl(data) if kind == ".stl" else read_dae(data)
    return triangles.reshape(-1, 3), np.arange(3 * len(triangles), dtype=np.int64).reshape(-1, 3)


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
    return table, _fan_counts(len(table), indices[np.repeat(polygons, counts)] - 1,
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
        indices = _numbers(chars.tobytes(), np.int64)
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
    values = _numbers(b" ".join(lines))
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
    return table, _checked(len(table), np.array(tris, dtype=np.int64).reshape(-1, 3))


def _checked(vertex_count: int, index: IntArray) -> IntArray:
    """``index`` (F, 3), once every row it names is one of ``vertex_count`` vertices."""
    if len(index) and (index.min() < 0 or index.max() >= vertex_count):
        raise MeshFormatError("a face refers to a vertex that does not exist")
    return index


def _fan_counts(vertex_count: int, indices: IntArray, counts: IntArray) -> IntArray:
    """Fan-triangulate polygons given as flat ``indices`` with ``counts`` corners each."""
    counts = counts[counts >= 3]
    if not len(counts):
        return np.zeros((0, 3), dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    per = counts - 2
    first = np.repeat(starts, per)
    step = np.arange(per.sum()) - np.repeat(np.cumsum(per) - per, per) + 1
    corners = np.stack([first, first + step, first + step + 1], axis=1)
    if corners.max() >= len(indices):
        raise MeshFormatError("a polygon list shorter than its vertex counts")
    return _checked(vertex_count, indices[corners])


def _numbers(text: str | bytes | None, dtype: type = np.float64) -> np.ndarray:
    """Whitespace-separated numbers (see :mod:`number_text`)."""
    try:
        return number_text.numbers(text, dtype)
    except number_text.NumberListError as exc:
        raise MeshFormatError(str(exc)) from None


def _collada(data: bytes) -> tuple[list[tuple[ET.Element, FloatArray]], str, float]:
    """Each geometry instance of the scene with its transform, the namespace, and the unit."""
    try:
        root = parse_collada(data)
    except ColladaXmlError as exc:
        raise MeshFormatError(f"COLLADA file is not well-formed XML: {exc}") from None
    ns = root.tag[: root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    unit = root.find(f"{ns}asset/{ns}unit")
    meter = float(unit.get("meter", "1")) if unit is not None else 1.0
    geometries = {g.get("id"): g for g in root.iter(f"{ns}geometry")}
    scene = root.find(f"{ns}library_visual_scenes/{ns}visual_scene")
    if scene is None:
        return [(g, np.eye(4)) for g in geometries.values()], ns, meter
    library = {n.get("id"): n for n in root.iterfind(f"{ns}library_nodes/{ns}node")}
    return _instances(scene, ns, geometries, library), ns, meter


def read_dae(data: bytes) -> FloatArray:
    """Triangles of a COLLADA file: scene nodes' transforms and ``<unit meter>`` applied."""
    instances, ns, meter = _collada(data)
    parts = []
    for geometry, transform in instances:
        tris = _geometry_triangles(geometry, ns)
        if len(tris):
            parts.append(_placed(tris.reshape(-1, 3), transform).reshape(-1, 3, 3))
    if not parts:
        return np.zeros((0, 3, 3))
    triangles: FloatArray = np.concatenate(parts)
    return triangles * meter if meter != 1.0 else triangles


def read_dae_bounds(data: bytes) -> tuple[int, FloatArray, FloatArray]:
    """Triangle count and bounding box of a COLLADA file, without building the triangles.

    Reads the vertex positions and the primitives' counts only (the index lists are most of
    a COLLADA file), for the checks that need no more than the size.
    """
    instances, ns, meter = _collada(data)
    count, points = 0, []
    for geometry, transform in instances:
        mesh = geometry.find(f"{ns}mesh")
        if mesh is None:
            continue
        n = sum(_primitive_triangles(prim, ns) for prim in _elements(mesh))
        if n:
            count += n
            points.append(_placed(_positions(mesh, ns), transform))
    if not count:
        return 0, np.zeros(3), np.zeros(3)
    # each part's corners, scaled by the unit, bound what the scaled points would
    corners = [np.vstack(bounds(part)) for part in points if len(part)]
    lower, upper = bounds(np.concatenate(corners or [np.zeros((0, 3))]) * meter)
    return count, lower, upper


def _placed(points: FloatArray, transform: FloatArray) -> FloatArray:
    """``(n, 3)`` points moved by a scene node's 4x4 ``transform`` (most are the identity)."""
    if np.array_equal(transform, _IDENTITY):
        return points
    placed: FloatArray = points @ transform[:3, :3].T + transform[:3, 3]
    return placed


def bounds(points: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Lower and upper corners of ``(n, 3)`` points, shape (3,) each (NaN if a point has one).

    One column at a time: numpy reduces ``axis=0`` of an ``(n, 3)`` array twenty times
    slower than it reduces a strided column.
    """
    lower = np.array([points[:, axis].min() for axis in range(3)])
    upper = np.array([points[:, axis].max() for axis in range(3)])
    return lower, upper


def _elements(parent: ET.Element) -> list[ET.Element]:
    """The child elements of ``parent``, without comments (which lxml keeps in the tree)."""
    return [child for child in parent if isinstance(child.tag, str)]


def _primitive_triangles(prim: ET.Element, ns: str) -> int:
    kind = prim.tag[len(ns):]
    if kind == "triangles":
        return int(prim.get("count", "0"))
    if kind == "polylist":
        counts = _numbers(prim.findtext(f"{ns}vcount"), np.int64)
        return int(np.maximum(counts - 2, 0).sum())
    if kind == "polygons":
        return int(prim.get("count", "0"))
    return 0


def _instances(scene: ET.Element, ns: str, geometries: dict[str | None, ET.Element],
               library: dict[str | None, ET.Element]) -> list[tuple[ET.Element, FloatArray]]:
    """Every geometry the scene places, with its transform.

    A node places its ``<instance_geometry>`` and its child nodes, and the
    ``<library_nodes>`` nodes its ``<instance_node>`` names (SketchUp's exports place every
    part so), each under its own transform.

    Raises:
        MeshFormatError: Library nodes that place each other in a loop, or over
            :data:`_MOST_NODE_VISITS` nodes placed in all.
    """
    found: list[tuple[ET.Element, FloatArray]] = []
    stack = [(node, np.eye(4), 0) for node in scene.findall(f"{ns}node")]
    visits = 0
    while stack:
        node, parent, depth = stack.pop()
        visits += 1
        if visits > _MOST_NODE_VISITS:
            raise MeshFormatError(f"COLLADA scene placing over {_MOST_NODE_VISITS} nodes")
        transform = parent @ _node_transform(node, ns)
        for inst in node.findall(f"{ns}instance_geometry"):
            geometry = geometries.get((inst.get("url") or "").lstrip("#"))
            if geometry is not None:
                found.append((geometry, transform))
        stack.extend((child, transform, depth) for child in node.findall(f"{ns}node"))
        for inst in node.findall(f"{ns}instance_node"):
            placed = library.get((inst.get("url") or "").lstrip("#"))
            if placed is None:
                continue
            if depth >= _MOST_NESTED_INSTANCES:
                raise MeshFormatError("COLLADA library nodes that place each other in a loop "
                                      f"(or nested over {_MOST_NESTED_INSTANCES} deep)")
            stack.append((placed, transform, depth + 1))
    return found


def _node_transform(node: ET.Element, ns: str) -> FloatArray:
    transform = np.eye(4)
    for step in _elements(node):
        tag = step.tag[len(ns):]
        values = [float(v) for v in (step.text or "").split()]
        local = np.eye(4)
        if tag == "matrix" and len(values) == 16:
            local = np.array(values).reshape(4, 4)
        elif tag == "translate" and len(values) == 3:
            local[:3, 3] = values
        elif tag == "scale" and len(values) == 3:
            local[:3, :3] = np.diag(values)
        elif tag == "rotate" and len(values) == 4:
            local[:3, :3] = _axis_angle(np.array(values[:3]), np.radians(values[3]))
        else:
            continue
        transform = transform @ local
    return transform


def _axis_angle(axis: FloatArray, angle: float) -> FloatArray:
    norm = np.linalg.norm(axis)
    if norm == 0:
        return np.eye(3)
    x, y, z = axis / norm
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    rotation: FloatArray = np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * (k @ k)
    return rotation


def _positions(mesh: ET.Element, ns: str) -> FloatArray:
    sources = {src.get("id"): src for src in mesh.findall(f"{ns}source")}
    vertices = mesh.find(f"{ns}vertices")
    inputs = vertices.findall(f"{ns}input") if vertices is not None else []
    position = next((i for i in inputs if i.get("semantic") == "POSITION"), None)
    source_id = (position.get("source") or "").lstrip("#") if position is not None else ""
    source = sources.get(source_id)
    array = source.find(f"{ns}float_array") if source is not None else None
    if array is None:
        raise MeshFormatError("COLLADA mesh without vertex positions")
    points = _numbers(array.text)
    return points[: len(points) - len(points) % 3].reshape(-1, 3)


def _geometry_triangles(geometry: ET.Element, ns: str) -> FloatArray:
    mesh = geometry.find(f"{ns}mesh")
    if mesh is None or mesh.find(f"{ns}vertices") is None:
        return np.zeros((0, 3, 3))
    points = _positions(mesh, ns)
    tris = []
    for prim in _elements(mesh):
        kind = prim.tag[len(ns):]
        if kind in ("triangles", "polylist", "polygons"):
            tris.append(_primitive(prim, ns, kind, points))
    return np.concatenate(tris) if tris else np.zeros((0, 3, 3))


def _primitive(prim: ET.Element, ns: str, kind: str, points: FloatArray) -> FloatArray:
    inputs = prim.findall(f"{ns}input")
    stride = max((int(i.get("offset", "0")) for i in inputs), default=0) + 1
    offset = next((int(i.get("offset", "0")) for i in inputs if i.get("semantic") == "VERTEX"), 0)
    if kind == "polygons":
        parts = [_numbers(p.text, np.int64)[offset::stride] for p in prim.findall(f"{ns}p")]
        counts = np.array([len(p) for p in parts], dtype=np.int64)
        flat = np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)
        return _take(points, _fan_counts(len(points), flat, counts))
    indices = _numbers(" ".join(p.text or "" for p in prim.findall(f"{ns}p")), np.int64)
    indices = indices[offset::stride]
    if kind == "triangles":
        return _take(points, _checked(len(points), indices[: len(indices) - len(indices) % 3]
                                      .reshape(-1, 3)))
    counts = _numbers(prim.findtext(f"{ns}vcount"), np.int64)
    return _take(points, _fan_counts(len(points), indices, counts))


def _take(points: FloatArray, faces: IntArray) -> FloatArray:
    """The triangles (F, 3, 3) of ``faces``, checked rows of ``points``."""
    if not len(faces):
        return np.zeros((0, 3, 3))
    triangles: FloatArray = points[faces]
    return triangles
