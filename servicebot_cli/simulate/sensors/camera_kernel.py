r"""A camera frame in one compiled loop: rays, nearest surface, shading, noise, bytes.

The same surfaces, tests, shading and noise as the numpy path of
:mod:`~servicebot_cli.simulate.sensors.camera_image`, pixel by pixel and rows in parallel
(numba's ``prange``; a pixel depends on nothing but its own ray, so the bytes do not depend
on the thread count). Per frame, before the pixels: each primitive (box, cylinder, sphere)
outside the view's cone is dropped and the rest are sorted by the distance to their bounding
sphere, so a ray stops testing them once the nearest hit so far is closer. Mesh triangles
are found through their bounding volume hierarchy
(:mod:`~servicebot_cli.simulate.sensors.camera_mesh`) and met by the Moller-Trumbore test
(:mod:`~servicebot_cli.simulate.sensors.camera_bvh`). A robot's mesh part is culled and
sorted as a box (its bounding box), and a ray that reaches it is moved into its frame to walk
its own hierarchy; the normal it meets is turned back to the world to shade it.
Colour goes straight to rgb8 and depth to float32. Compiled by numba (cached on disk after
the first run). Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit, prange  # type: ignore[import-untyped, import-not-found, unused-ignore]

from servicebot_cli.simulate.sensors import camera_culling as culling
from servicebot_cli.simulate.sensors.camera_bvh import (
    box_near,
    lit_normal,
    mesh_entry,
    ray_inverse,
    triangle_hit,
)
from servicebot_cli.simulate.sensors.camera_noise import GOLDEN, MIX_1, MIX_2
from servicebot_cli.simulate.sensors.camera_primitives import MESH, entry, lit

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_STACK = 64  # deepest hierarchy walked: 2**64 triangles
TILE = 8
"""Tiles of TILE x TILE pixels share one list of what they can show."""
_MASK = np.uint64(0xFFFF)


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _triangles(o: FloatArray, d: FloatArray, best: float, lowest: float, highest: float,
               mesh: tuple, stack: IntArray) -> tuple[float, int]:  # type: ignore[type-arg]
    """Nearest triangle a ray meets at a distance in [lowest, highest] before ``best``.

    Returns:
        Distance and triangle (-1: none before ``best``).
    """
    corner, edge_1, edge_2, _, _, low, high, first, count = mesh
    inverse = ray_inverse(d)
    found, top = -1, 0
    stack[0] = 0
    while top >= 0:
        node = stack[top]
        top -= 1
        if box_near(o, inverse, low[node], high[node]) >= min(best, highest):
            continue
        if count[node] == 0:
            stack[top + 1], stack[top + 2] = first[node], first[node] + 1
            top += 2
            continue
        for k in range(first[node], first[node] + count[node]):
            t, _ = triangle_hit(o, d, corner[k], edge_1[k], edge_2[k])
            if lowest <= t <= highest and t < best:
                best, found = t, k
    return best, found


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _noisy(colour: FloatArray, n: int, key: np.uint64, scale: float, table: FloatArray,
           rgb: npt.NDArray[np.uint8]) -> None:
    """``colour`` plus pixel ``n``'s noise (:mod:`.camera_noise`), rounded into ``rgb[n]``."""
    bits = np.uint64(0)
    if scale > 0.0:
        z = key + np.uint64(n + 1) * GOLDEN
        z = (z ^ (z >> np.uint64(30))) * MIX_1
        z = (z ^ (z >> np.uint64(27))) * MIX_2
        bits = z ^ (z >> np.uint64(31))
    for i in range(3):
        value = colour[i]
        if scale > 0.0:
            value = value + table[np.int64((bits >> np.uint64(16 * i)) & _MASK)] * scale
        rgb[n, i] = np.uint8(min(255.0, max(0.0, np.rint(value))))


@njit(cache=True, nogil=True, error_model="numpy")
def _tile(pixels: tuple, rotation: FloatArray, origin: FloatArray,  # type: ignore[type-arg]
          view: tuple, solids: tuple, frame: tuple, chosen: IntArray,  # type: ignore[type-arg]
          mesh: tuple, part_mesh: tuple, look: tuple,  # type: ignore[type-arg]
          noise: tuple, rgb: npt.NDArray[np.uint8],  # type: ignore[type-arg]
          depth: npt.NDArray[np.float32]) -> None:
    """Shade the pixels of one tile from the ``chosen`` primitives (and the meshes)."""
    top, bottom, left, right = pixels
    directions, forward, width, near_m, far_m, _ = view
    kinds, halves, rotations, _, colours = solids
    local_origins, lower, meshes_seen = frame
    floor, sky, light, ambient = look
    key, scale, table = noise
    part_triangles, roots = part_mesh
    part_normals = part_triangles[3]
    stack, d, local, colour = np.empty(_STACK, np.int64), np.empty(3), np.empty(3), np.empty(3)
    floor_shade = ambient + (1.0 - ambient) * abs(light[2])
    for row in range(top, bottom):
        for n in range(row * width + left, row * width + right):
            for i in range(3):
                d[i] = (directions[n, 0] * rotation[i, 0] + directions[n, 1] * rotation[i, 1]
                        + directions[n, 2] * rotation[i, 2])
            best, which = math.inf, -2  # -2: nothing, -1: the floor, s: a primitive
            part_triangle = -1  # the triangle of a mesh part ``which``
            if d[2] < 0.0:
                t = -origin[2] / d[2]
                if t >= 0.0 and near_m <= t * forward[n] <= far_m:
                    best, which = t, -1
            for s in chosen:
                if lower[s] > best:
                    break
                k = -1
                if kinds[s] == MESH:
                    for i in range(3):
                        local[i] = (d[0] * rotations[s, 0, i] + d[1] * rotations[s, 1, i]
                                    + d[2] * rotations[s, 2, i])
                    t, k = mesh_entry(local_origins[s], local, best, roots[s],
                                      part_triangles, stack)
                else:
                    t = entry(kinds[s], local_origins[s, 0], local_origins[s, 1],
                              local_origins[s, 2], d[0] * rotations[s, 0, 0]
                              + d[1] * rotations[s, 1, 0] + d[2] * rotations[s, 2, 0],
                              d[0] * rotations[s, 0, 1] + d[1] * rotations[s, 1, 1]
                              + d[2] * rotations[s, 2, 1], d[0] * rotations[s, 0, 2]
                              + d[1] * rotations[s, 1, 2] + d[2] * rotations[s, 2, 2],
                              halves[s, 0], halves[s, 1], halves[s, 2])
                nearer = t < best or (t == best and s < which)  # a tie: the numpy path's first
                if nearer and t < math.inf and near_m <= t * forward[n] <= far_m:
                    best, which, part_triangle = t, s, k
            triangle = -1
            if meshes_seen:
                best, triangle = _triangles(origin, d, best, near_m / forward[n],
                                            far_m / forward[n], mesh, stack)
            if depth.size:
                depth[n] = np.float32(best * forward[n]) if best < math.inf else np.inf
            if triangle >= 0:
                normal = mesh[3][triangle]
                shade = ambient + (1.0 - ambient) * abs(
                    normal[0] * light[0] + normal[1] * light[1] + normal[2] * light[2])
                for i in range(3):
                    colour[i] = mesh[4][triangle, i] * shade
            elif which == -2:
                colour[:] = sky
            elif which == -1:
                x, y = origin[0] + best * d[0], origin[1] + best * d[1]
                square = int(math.floor(x) + math.floor(y)) % 2
                for i in range(3):
                    colour[i] = floor[square, i] * floor_shade
            elif part_triangle >= 0:
                shade = lit_normal(part_normals[part_triangle], rotations[which], light, ambient)
                for i in range(3):
                    colour[i] = colours[which, i] * shade
            else:
                for i in range(3):
                    local[i] = local_origins[which, i] + best * (
                        d[0] * rotations[which, 0, i] + d[1] * rotations[which, 1, i]
                        + d[2] * rotations[which, 2, i])
                shade = lit(kinds[which], local, halves[which], rotations[which], light,
                            ambient)
                for i in range(3):
                    colour[i] = colours[which, i] * shade
            _noisy(colour, n, key, scale, table, rgb)


@njit(cache=True, nogil=True, error_model="numpy")
def _local_origins(origin: FloatArray, rotations: FloatArray, centres: FloatArray) -> FloatArray:
    """The camera in each primitive's frame, :math:`R^T (o - c)`, (S, 3)."""
    out = np.empty((len(centres), 3))
    for s in range(len(centres)):
        for i in range(3):
            out[s, i] = ((origin[0] - centres[s, 0]) * rotations[s, 0, i]
                         + (origin[1] - centres[s, 1]) * rotations[s, 1, i]
                         + (origin[2] - centres[s, 2]) * rotations[s, 2, i])
    return out


@njit(cache=True, nogil=True, error_model="numpy")
def _frame(rotation: FloatArray, origin: FloatArray, view: tuple,  # type: ignore[type-arg]
           solids: tuple, mesh: tuple, part_mesh: tuple,  # type: ignore[type-arg]
           look: tuple, noise: tuple, rgb: npt.NDArray[np.uint8],  # type: ignore[type-arg]
           depth: npt.NDArray[np.float32]) -> None:
    """One frame, tile by tile: ``render``'s arguments for one camera pose and one key."""
    directions, _, width, near_m, far_m, intrinsics = view
    kinds, halves, rotations, centres, _ = solids
    count = len(kinds)
    # the meshes' root box joins the primitives' boxes, as index ``count``
    box_halves, box_rotations, box_centres = np.zeros((count + 1, 3)), \
        np.zeros((count + 1, 3, 3)), np.zeros((count + 1, 3))
    box_halves[:count], box_rotations[:count], box_centres[:count] = halves, rotations, centres
    box_rotations[count] = np.eye(3)
    low, high = mesh[5], mesh[6]
    if len(low):
        box_halves[count] = np.maximum((high[0] - low[0]) / 2.0, 1e-9)
        box_centres[count] = (high[0] + low[0]) / 2.0
    centre, axes, lower = culling.boxes(rotation, origin, box_halves, box_rotations, box_centres)
    local_origins = _local_origins(origin, rotations, centres)
    rows = len(directions) // width
    everything = np.arange(count + (1 if len(low) else 0))
    in_view = np.empty(len(everything), np.int64)
    whole = culling.cone(intrinsics, 0, width - 1, 0, rows - 1)
    found = culling.survivors(everything, centre, axes, whole, near_m, far_m, in_view)
    ordered = in_view[:found][np.argsort(lower[in_view[:found]], kind="mergesort")]
    chosen = np.empty(len(ordered), np.int64)
    for top in range(0, rows, TILE):
        bottom = min(rows, top + TILE)
        for left in range(0, width, TILE):
            right = min(width, left + TILE)
            cone = culling.cone(intrinsics, left, right - 1, top, bottom - 1)
            tile = culling.survivors(ordered, centre, axes, cone, near_m, far_m, chosen)
            meshes_seen, kept = False, 0
            for j in range(tile):  # the meshes' box out of the primitives' list
                if chosen[j] == count:
                    meshes_seen = True
                else:
                    chosen[kept] = chosen[j]
                    kept += 1
            _tile((top, bottom, left, right), rotation, origin, view, solids,
                  (local_origins, lower, meshes_seen), chosen[:kept], mesh, part_mesh, look,
                  noise, rgb, depth)


@njit(cache=True, nogil=True, error_model="numpy", parallel=True)
def render(rotations: FloatArray, origins: FloatArray, view: tuple,  # type: ignore[type-arg]
           solids: tuple, parts: tuple, mesh: tuple,  # type: ignore[type-arg]
           part_mesh: tuple, look: tuple, noise: tuple,  # type: ignore[type-arg]
           rgb: npt.NDArray[np.uint8], depth: npt.NDArray[np.float32]) -> None:
    """Fill ``rgb`` (F, N, 3) and, unless it is empty, ``depth`` (F, N) [m] (inf: nothing).

    Frames are shared out between threads (a frame to each, as it finishes the last); each
    frame's bytes depend on its own inputs alone.

    Args:
        rotations: ``transform_camera_to_world``'s rotation of each frame, (F, 3, 3).
        origins: Its origin, (F, 3).
        view: Link-frame unit rays (N, 3), their cosines to the axis (N,), the image width,
            the near and far clip planes [m], and fx, cx, fy, cy (4,).
        solids: The world's primitives: kinds (S,), half sizes (S, 3), rotations (S, 3, 3,
            local axes as columns), centres (S, 3) and base colours (S, 3).
        parts: The robot's: kinds (P,), half sizes (P, 3), colours (P, 3), and per frame
            rotations (F, P, 3, 3) and centres (F, P, 3).
        mesh: :class:`~servicebot_cli.simulate.sensors.camera_mesh.Triangles`' arrays.
        part_mesh: The mesh parts' triangles' arrays (:class:`~.camera_mesh.PartTriangles`,
            in their parts' frames), and each solid's and part's root node (-1: not a mesh),
            (S + P,).
        look: The floor's two colours (2, 3), the sky's (3,), the unit light (3,), ambient.
        noise: Each frame's key (F,), the noise's stddev in pixel values (0: none), the table.
        rgb: Out: each frame's rgb8 pixels, row by row, (F, N, 3).
        depth: Out: each frame's depth [m], (F, N), or (F, 0) for none.
    """
    kinds, halves, rotations_s, centres_s, colours = solids
    part_kinds, part_halves, part_colours, part_rotations, part_centres = parts
    keys, scale, table = noise
    all_kinds = np.concatenate((kinds, part_kinds))
    all_halves = np.concatenate((halves, part_halves))
    all_colours = np.concatenate((colours, part_colours))
    # a tuple inside a tuple cannot reach prange's body: its arrays one by one
    (corner, edge_1, edge_2, normal, colour, low, high, first, count), roots = part_mesh
    for f in prange(len(origins)):
        frame_solids = (all_kinds, all_halves, np.concatenate((rotations_s, part_rotations[f])),
                        np.concatenate((centres_s, part_centres[f])), all_colours)
        _frame(rotations[f], origins[f], view, frame_solids, mesh,
               ((corner, edge_1, edge_2, normal, colour, low, high, first, count), roots), look,
               (keys[f], scale, table), rgb[f], depth[f])
