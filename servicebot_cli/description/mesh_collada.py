"""A fast reader of COLLADA meshes: triangles, or only their count and bounding box.

The scene's nodes place geometries (with ``<library_nodes>`` instances, as SketchUp
exports), each under its transform, and ``<unit meter>`` scales the result, as Assimp
(Gazebo's and RViz's reader) applies it. Pure.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np

from servicebot_cli.description.collada_xml import ColladaXmlError, parse_collada
from servicebot_cli.description.mesh_arrays import (
    FloatArray,
    IntArray,
    MeshFormatError,
    bounds,
    checked,
    fan_counts,
    numbers,
)

_IDENTITY = np.eye(4)
_MOST_NESTED_INSTANCES = 32  # <instance_node> within placed library nodes
_MOST_NODE_VISITS = 100_000  # nodes placed: library nodes can place each other many times


def _collada(data: bytes) -> tuple[list[tuple[ET.Element, FloatArray]], str, float]:
    """Each geometry instance of the scene with its transform, the namespace, and the unit."""
    try:
        root = parse_collada(data)
    except ColladaXmlError as exc:
        raise MeshFormatError(f"COLLADA file is not well-formed XML: {exc}") from None
    except LookupError as exc:  # an XML declaration naming an encoding nobody has
        raise MeshFormatError(f"its XML declaration names an {exc}") from None
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


def _elements(parent: ET.Element) -> list[ET.Element]:
    """The child elements of ``parent``, without comments (which lxml keeps in the tree)."""
    return [child for child in parent if isinstance(child.tag, str)]


def _primitive_triangles(prim: ET.Element, ns: str) -> int:
    """How many triangles a primitive says it has, without reading its index lists.

    Raises:
        MeshFormatError: More corners than its ``<p>`` text could hold (each index takes
            at least a digit and a blank): a count that is no count of this file.
    """
    kind = prim.tag[len(ns):]
    corners, triangles = 0, 0
    if kind == "triangles":
        triangles = int(prim.get("count", "0"))
        corners = 3 * triangles
    elif kind == "polylist":
        counts = numbers(prim.findtext(f"{ns}vcount"), np.int64)
        corners = int(counts.sum())
        triangles = int(np.maximum(counts - 2, 0).sum())
    elif kind == "polygons":
        triangles = int(prim.get("count", "0"))
    if corners:
        stride = max((int(i.get("offset", "0")) for i in prim.findall(f"{ns}input")),
                     default=0) + 1
        written = sum(len(p.text or "") for p in prim.findall(f"{ns}p"))
        if corners * stride * 2 - 1 > written:
            raise MeshFormatError("a polygon list shorter than its vertex counts")
    return triangles


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
    if source is None or array is None:
        raise MeshFormatError("COLLADA mesh without vertex positions")
    points = numbers(array.text)
    return _accessed(source, array, points, ns)


def _accessed(source: ET.Element, array: ET.Element, values: FloatArray, ns: str) -> FloatArray:
    """The points a position ``source``'s accessor reads from its ``values``, as Assimp does.

    Assimp (RViz, Gazebo and MoveIt read COLLADA through it) reads the ``count`` numbers a
    ``<float_array>`` says it holds (refusing it where it holds fewer), and refuses a
    source without an ``<accessor>`` and an accessor that reads past those numbers.

    Raises:
        MeshFormatError: Saying which, in Assimp's terms.
    """
    name = source.get("id") or "?"
    written = _integer(array.get("count"))
    if written is not None and written > len(values):
        raise MeshFormatError(
            f"COLLADA <float_array> of source '{name}' says count=\"{array.get('count')}\" and "
            f"holds {len(values)} numbers, which Assimp (RViz, Gazebo, MoveIt) refuses")
    held = len(values)
    if written is not None and written >= 0:
        values = values[:written]
    accessor = source.find(f"{ns}technique_common/{ns}accessor")
    if accessor is None:
        raise MeshFormatError(f"COLLADA source '{name}' has no <accessor>, without which Assimp "
                              "(RViz, Gazebo, MoveIt) reads no positions")
    count, stride = _integer(accessor.get("count")), _integer(accessor.get("stride")) or 1
    offset = _integer(accessor.get("offset")) or 0
    if count is None or count < 0 or stride < 3 or offset < 0:
        return values[: len(values) - len(values) % 3].reshape(-1, 3)
    if offset + count * stride > len(values):
        told = (f", though it holds {held}: Assimp reads the count it is told"
                if held > len(values) else "")
        raise MeshFormatError(
            f"COLLADA accessor of source '{name}' reads {count} points of {stride} numbers "
            f"({offset + count * stride}) where its <float_array> says count="
            f"\"{len(values)}\"{told}; Assimp 5.4 and later (RViz, Gazebo, MoveIt) refuse it "
            "('Not enough data for accessor'), older Assimp (Ubuntu 22.04 and 24.04) reads "
            "past the numbers it kept: vertices of garbage, or a crash")
    points: FloatArray = values[offset: offset + count * stride].reshape(count, stride)[:, :3]
    return points


def _integer(text: str | None) -> int | None:
    """An attribute's whole number; None where it is not written or is no integer."""
    try:
        return int(text) if text is not None else None
    except ValueError:
        return None


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
        parts = [numbers(p.text, np.int64)[offset::stride] for p in prim.findall(f"{ns}p")]
        counts = np.array([len(p) for p in parts], dtype=np.int64)
        flat = np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)
        return _take(points, fan_counts(len(points), flat, counts))
    indices = numbers(" ".join(p.text or "" for p in prim.findall(f"{ns}p")), np.int64)
    indices = indices[offset::stride]
    if kind == "triangles":
        return _take(points, checked(len(points), indices[: len(indices) - len(indices) % 3]
                                      .reshape(-1, 3)))
    counts = numbers(prim.findtext(f"{ns}vcount"), np.int64)
    return _take(points, fan_counts(len(points), indices, counts))


def _take(points: FloatArray, faces: IntArray) -> FloatArray:
    """The triangles (F, 3, 3) of ``faces``, checked rows of ``points``."""
    if not len(faces):
        return np.zeros((0, 3, 3))
    triangles: FloatArray = points[faces]
    return triangles
