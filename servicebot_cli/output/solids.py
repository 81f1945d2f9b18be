"""Visual shapes as flat polygons in the root frame, ready to draw.

Boxes are six quads, cylinders a ring of quads and two caps, spheres a latitude-longitude
grid, meshes their triangles (thinned past :data:`MAX_MESH_FACES`, so a dense scan stays
quick to draw). Colours come from the visual's material, inline or named at the top.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from servicebot_cli.inspect.geometry import FloatArray, MeshLibrary, PosedShape

MAX_MESH_FACES = 20_000
DEFAULT_RGBA = (0.6, 0.6, 0.62, 1.0)
_CYLINDER_SIDES = 32


@dataclass(frozen=True)
class Solid:
    """Polygons of one shape, each of shape (k, 3) in the root frame [m], and its colour."""

    link: str
    polygons: list[FloatArray]
    rgba: tuple[float, float, float, float]
    kind: str


def _box(size: FloatArray) -> list[FloatArray]:
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * size / 2
    faces = ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3))
    return [corners[list(face)] for face in faces]


def _cylinder(radius: float, length: float) -> list[FloatArray]:
    angles = np.linspace(0, 2 * np.pi, _CYLINDER_SIDES, endpoint=False)
    ring = np.column_stack([radius * np.cos(angles), radius * np.sin(angles),
                            np.zeros_like(angles)])
    bottom, top = ring - [0, 0, length / 2], ring + [0, 0, length / 2]
    sides = [np.array([bottom[i], bottom[i - 1], top[i - 1], top[i]])
             for i in range(_CYLINDER_SIDES)]
    return [*sides, bottom[::-1], top]


def _sphere(radius: float, rows: int = 10, columns: int = 20) -> list[FloatArray]:
    theta = np.linspace(0, np.pi, rows + 1)
    phi = np.linspace(0, 2 * np.pi, columns + 1)

    def point(i: int, j: int) -> FloatArray:
        return radius * np.array([np.sin(theta[i]) * np.cos(phi[j]),
                                  np.sin(theta[i]) * np.sin(phi[j]), np.cos(theta[i])])

    return [np.array([point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)])
            for i in range(rows) for j in range(columns)]


def local_polygons(posed: PosedShape, meshes: MeshLibrary) -> list[FloatArray]:
    """The shape's polygons in its own frame; empty when it has no usable geometry."""
    g = posed.shape.geometry
    if g.kind == "box" and g.size is not None and np.all(np.isfinite(g.size)):
        return _box(np.abs(np.array(g.size, dtype=float)))
    if g.kind == "cylinder" and g.radius and g.length and np.isfinite([g.radius, g.length]).all():
        return _cylinder(abs(g.radius), abs(g.length))
    if g.kind == "sphere" and g.radius and np.isfinite(g.radius):
        return _sphere(abs(g.radius))
    if g.kind == "mesh" and g.filename:
        mesh = meshes.get(g.filename)
        if mesh is None:
            return []
        stride = max(1, len(mesh.faces) // MAX_MESH_FACES)
        vertices = mesh.vertices * np.array(g.scale, dtype=float)
        return list(vertices[mesh.faces[::stride]])
    return []


def shape_rgba(posed: PosedShape,
               materials: Mapping[str, tuple[float, float, float, float] | None]
               ) -> tuple[float, float, float, float]:
    """The visual's colour: its inline ``<color>``, else its named material, else grey."""
    element = posed.shape.element
    colour = element.find("material/color") if element is not None else None
    if colour is not None:
        parts = (colour.get("rgba") or "").split()
        try:
            r, g, b, a = (min(1.0, max(0.0, float(p))) for p in parts)
            return (r, g, b, a)
        except ValueError:
            pass
    named = materials.get(posed.shape.material or "")
    return named if named is not None else DEFAULT_RGBA


def solids(shapes: list[PosedShape], meshes: MeshLibrary,
           materials: Mapping[str, tuple[float, float, float, float] | None]) -> list[Solid]:
    """Every shape as polygons in the root frame."""
    out = []
    for posed in shapes:
        local = local_polygons(posed, meshes)
        if not local:
            continue
        rotation, origin = posed.transform[:3, :3], posed.transform[:3, 3]
        placed = [poly @ rotation.T + origin for poly in local]
        out.append(Solid(posed.link, placed, shape_rgba(posed, materials),
                         posed.shape.geometry.kind))
    return out
