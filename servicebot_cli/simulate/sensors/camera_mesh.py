"""Mesh obstacles for the camera's compiled loop: one triangle soup and its bounding volumes.

Every mesh of a scene goes into one list of triangles (corner, two edges, unit normal, base
colour), ordered so that each leaf of a bounding volume hierarchy holds a contiguous run of
them. The hierarchy is built once per run by median splits along the longest axis of the
triangles' centres; a ray visits only the boxes it enters before its nearest hit so far, so
a frame costs about the logarithm of the triangle count per ray, and a mesh outside the view
costs one box test per ray. The robot's mesh parts get a hierarchy each, built once in the
part's own frame (:func:`part_triangles`): a ray is moved into that frame, as for a box. Pure.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world.raycast import Mesh

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
LEAF_TRIANGLES = 4
"""At most this many triangles in a leaf of the hierarchy."""


@dataclass(frozen=True)
class Triangles:
    """Triangles and their bounding volume hierarchy, as the compiled loop reads them.

    Attributes:
        corner: First corner of each triangle [m], (T, 3).
        edge_1, edge_2: Second and third corners minus the first [m], (T, 3) each.
        normal: Unit normal (the edges' cross product), (T, 3).
        colour: Base colour rgb 0-255, (T, 3).
        low, high: Corners of each node's box [m], (M, 3) each; node 0 is the root.
        first, count: A leaf's triangles are ``first .. first + count - 1``; an inner node
            (``count`` 0) has its children at ``first`` and ``first + 1``, (M,) each.
    """

    corner: FloatArray = field(repr=False)
    edge_1: FloatArray = field(repr=False)
    edge_2: FloatArray = field(repr=False)
    normal: FloatArray = field(repr=False)
    colour: FloatArray = field(repr=False)
    low: FloatArray = field(repr=False)
    high: FloatArray = field(repr=False)
    first: IntArray = field(repr=False)
    count: IntArray = field(repr=False)


@dataclass(frozen=True)
class PartTriangles:
    """The robot's mesh parts for the compiled loop: one hierarchy per part, in its frame.

    Attributes:
        triangles: Every mesh part's triangles, part after part, in its part's frame; node
            and triangle numbers (``first``) count from the start of these arrays.
        root: The root node of each part's hierarchy, -1 for a primitive, (P,).
        start, stop: Each part's triangles are ``start .. stop - 1`` (empty for a primitive).
    """

    triangles: Triangles
    root: IntArray = field(repr=False)
    start: IntArray = field(repr=False)
    stop: IntArray = field(repr=False)


def triangles(meshes: Sequence[Mesh], colours: Sequence[tuple[int, int, int]]) -> Triangles:
    """The triangles of ``meshes`` (placed in the world), each with its mesh's colour."""
    corners = [np.asarray(m.vertices, dtype=np.float64)[np.asarray(m.faces)] for m in meshes]
    soup = np.concatenate(corners) if corners else np.zeros((0, 3, 3))
    colour = np.concatenate([np.tile(np.array(c, dtype=np.float64), (len(k), 1))
                             for c, k in zip(colours, corners, strict=True)]) \
        if corners else np.zeros((0, 3))
    return _ordered(soup, colour)


def part_triangles(parts: Sequence[Part]) -> PartTriangles:
    """The triangles of the mesh ``parts``, each in its part's frame under its own root."""
    root, start, stop = (np.full(len(parts), -1, np.int64), np.zeros(len(parts), np.int64),
                         np.zeros(len(parts), np.int64))
    pieces, nodes, before = [], 0, 0
    for i, part in enumerate(parts):
        if part.vertices_m is None or part.faces is None:
            continue
        piece = _ordered(part.vertices_m[part.faces], np.zeros((len(part.faces), 3)))
        inner = piece.count == 0
        piece.first[inner] += nodes  # an inner node's first is a node, a leaf's a triangle
        piece.first[~inner] += before
        root[i], start[i], stop[i] = nodes, before, before + len(piece.corner)
        nodes, before = nodes + len(piece.count), before + len(piece.corner)
        pieces.append(piece)
    if not pieces:
        pieces.append(_ordered(np.zeros((0, 3, 3)), np.zeros((0, 3))))
    joined = [np.concatenate([getattr(p, f.name) for p in pieces])
              for f in dataclasses.fields(Triangles)]
    return PartTriangles(Triangles(*joined), root, start, stop)


def _ordered(soup: FloatArray, colour: FloatArray) -> Triangles:
    """Triangles (T, 3 corners, 3) in the order of their hierarchy, with its nodes."""
    order, low, high, first, count = _hierarchy(soup)
    soup, colour = soup[order], colour[order]
    edge_1, edge_2 = soup[:, 1] - soup[:, 0], soup[:, 2] - soup[:, 0]
    normal = np.cross(edge_1, edge_2)
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    return Triangles(np.ascontiguousarray(soup[:, 0]), np.ascontiguousarray(edge_1),
                     np.ascontiguousarray(edge_2), normal, np.ascontiguousarray(colour),
                     low, high, first, count)


def _hierarchy(soup: FloatArray) -> tuple[IntArray, FloatArray, FloatArray, IntArray, IntArray]:
    """Triangle order and nodes (low, high, first, count) of the hierarchy over ``soup``."""
    order = np.arange(len(soup))
    if not len(soup):
        return order, np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0, np.int64), \
            np.zeros(0, np.int64)
    lows, highs, centres = soup.min(axis=1), soup.max(axis=1), soup.mean(axis=1)
    nodes: list[list[int]] = [[0, len(soup)]]  # per node: start, end (triangles of order)
    boxes: list[tuple[FloatArray, FloatArray]] = []
    first, count = [0], [0]
    index = 0
    while index < len(nodes):
        start, end = nodes[index]
        chosen = order[start:end]
        boxes.append((lows[chosen].min(axis=0), highs[chosen].max(axis=0)))
        if end - start <= LEAF_TRIANGLES:
            first[index], count[index] = start, end - start
        else:
            spread = centres[chosen].max(axis=0) - centres[chosen].min(axis=0)
            axis = int(np.argmax(spread))
            order[start:end] = chosen[np.argsort(centres[chosen, axis], kind="stable")]
            middle = (start + end) // 2
            first[index] = len(nodes)
            nodes += [[start, middle], [middle, end]]
            first += [0, 0]
            count += [0, 0]
        index += 1
    low = np.array([b[0] for b in boxes])
    high = np.array([b[1] for b in boxes])
    return order, low, high, np.array(first, np.int64), np.array(count, np.int64)
