r"""A ray against triangles through their bounding volume hierarchy, compiled by numba.

The hierarchy is :mod:`~servicebot_cli.simulate.sensors.camera_mesh`'s: boxes met by the slab
method, triangles by the Moller-Trumbore test. With :math:`e_1, e_2` a triangle's edges from
its corner :math:`c`, :math:`p = d \times e_2`, :math:`\delta = e_1 \cdot p`,
:math:`s = o - c`, :math:`q = s \times e_1`, the ray meets it at
:math:`t = e_2 \cdot q / \delta` where :math:`u = s \cdot p / \delta \ge 0`,
:math:`v = d \cdot q / \delta \ge 0` and :math:`u + v \le 1`; :math:`\delta > 0` where the
triangle faces the ray (counter-clockwise seen from outside). Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_SLACK = 1e-9  # boxes up to this share further than the bound are still opened (rounding)


@njit(cache=True, nogil=True, error_model="numpy")
def box_near(o: FloatArray, inverse: tuple[float, float, float], low: FloatArray,
             high: FloatArray) -> float:
    """Where a ray enters an axis-aligned box (inf: never)."""
    near, far = 0.0, math.inf
    for i in range(3):
        t1, t2 = (low[i] - o[i]) * inverse[i], (high[i] - o[i]) * inverse[i]
        near, far = max(near, min(t1, t2)), min(far, max(t1, t2))
    return near if near <= far else math.inf


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def triangle_hit(o: FloatArray, d: FloatArray, corner: FloatArray, e1: FloatArray,
                 e2: FloatArray) -> tuple[float, float]:
    """Where a ray meets one triangle (the module's Moller-Trumbore test), and its delta.

    Returns:
        ``t`` (NaN: it misses, so every comparison with it is false) and :math:`\\delta`
        (> 0: the triangle faces the ray).
    """
    p0, p1, p2 = d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], \
        d[0] * e2[1] - d[1] * e2[0]
    det = e1[0] * p0 + e1[1] * p1 + e1[2] * p2
    if abs(det) < 1e-15:
        return math.nan, det
    s0, s1, s2 = o[0] - corner[0], o[1] - corner[1], o[2] - corner[2]
    u = (s0 * p0 + s1 * p1 + s2 * p2) / det
    if u < 0.0 or u > 1.0:
        return math.nan, det
    q0, q1, q2 = s1 * e1[2] - s2 * e1[1], s2 * e1[0] - s0 * e1[2], s0 * e1[1] - s1 * e1[0]
    v = (d[0] * q0 + d[1] * q1 + d[2] * q2) / det
    if not (v >= 0.0 and u + v <= 1.0):
        return math.nan, det
    return (e2[0] * q0 + e2[1] * q1 + e2[2] * q2) / det, det


@njit(cache=True, nogil=True, error_model="numpy")
def mesh_entry(o: FloatArray, d: FloatArray, bound: float, root: int,
               mesh: tuple, stack: IntArray) -> tuple[float, int]:  # type: ignore[type-arg]
    """Where a ray enters the mesh under node ``root``, if no further than ``bound``.

    The nearest triangle the ray meets at :math:`0 \\le t \\le` ``bound`` (ties: the lowest
    numbered) is the entry if it faces the ray; if it faces away, the ray starts inside
    and enters nothing (as a primitive seen from inside, and the LIDAR's meshes). The
    numpy path (:func:`~servicebot_cli.simulate.sensors.camera_mesh_rays.mesh_part_hits`)
    computes the same numbers in the same order.

    Args:
        o: The ray's origin in the mesh's frame, (3,).
        d: Its unit direction in that frame, (3,).
        bound: No further than this [m] (inf: anywhere).
        root: The mesh's root node.
        mesh: :class:`~servicebot_cli.simulate.sensors.camera_mesh.Triangles`' arrays.
        stack: Room for the walk, (64,).

    Returns:
        Distance (inf: none) and triangle (-1: none).
    """
    corner, edge_1, edge_2, _, _, low, high, first, count = mesh
    inverse = ray_inverse(d)
    best, found, facing, top = math.inf, -1, False, 0
    stack[0] = root
    while top >= 0:
        node = stack[top]
        top -= 1
        limit = min(best, bound)
        near = box_near(o, inverse, low[node], high[node])
        if near == math.inf or near > limit + _SLACK * (1.0 + limit):
            continue
        if count[node] == 0:
            stack[top + 1], stack[top + 2] = first[node], first[node] + 1
            top += 2
            continue
        for k in range(first[node], first[node] + count[node]):
            t, det = triangle_hit(o, d, corner[k], edge_1[k], edge_2[k])
            if 0.0 <= t <= bound and (t < best or (t == best and k < found)):
                best, found, facing = t, k, det > 0.0
    if not facing:
        return math.inf, -1
    return best, found


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def ray_inverse(d: FloatArray) -> tuple[float, float, float]:
    """1 / each component of ``d``, kept finite (a ray along a box's face stays in its slab).

    A tuple, as :func:`box_near` takes it: nothing is allocated per ray.
    """
    return _inverse(d[0]), _inverse(d[1]), _inverse(d[2])


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _inverse(component: float) -> float:
    return 1.0 / (component if abs(component) > 1e-300 else 1e-300)


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def lit_normal(normal: FloatArray, rotation: FloatArray, light: FloatArray,
               ambient: float) -> float:
    """The light on a surface whose unit normal is ``normal`` in a frame turned by ``rotation``."""
    dot = 0.0
    for r in range(3):
        dot += (rotation[r, 0] * normal[0] + rotation[r, 1] * normal[1]
                + rotation[r, 2] * normal[2]) * light[r]
    return ambient + (1.0 - ambient) * abs(dot)
