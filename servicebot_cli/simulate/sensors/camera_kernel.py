r"""A camera frame's colours and distances in one compiled loop over the pixels.

The same surfaces, tests and shading as the numpy path of
:mod:`~servicebot_cli.simulate.sensors.camera_image` (floor, then boxes, cylinders and
spheres in closed form: the slab method, the cylinder's quadratic and caps, the sphere's
quadratic; a ray starting inside a primitive does not see it; surfaces outside the clip
planes are passed over), pixel by pixel, without the numpy path's temporaries. Meshes are
not drawn here: a scene with meshes takes the numpy path. Compiled by numba (cached on
disk after the first run). Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
BOX, CYLINDER, SPHERE = 0, 1, 2


@njit(cache=True, nogil=True, error_model="numpy")
def _box(o: FloatArray, d: FloatArray, half: FloatArray) -> float:
    near, far = -math.inf, math.inf
    for i in range(3):
        if d[i] == 0.0:
            if o[i] < -half[i] or o[i] > half[i]:
                return math.inf
            continue
        inv = 1.0 / d[i]  # as raycast.box_entry: the same rounding at edges
        t1, t2 = (-half[i] - o[i]) * inv, (half[i] - o[i]) * inv
        near, far = max(near, min(t1, t2)), min(far, max(t1, t2))
    return near if near <= far and near >= 0.0 else math.inf


@njit(cache=True, nogil=True, error_model="numpy")
def _cylinder(o: FloatArray, d: FloatArray, half: FloatArray) -> float:
    radius, half_length = half[0], half[2]
    c = o[0] * o[0] + o[1] * o[1] - radius * radius
    if c < 0.0 and abs(o[2]) < half_length:
        return math.inf  # from inside: no entry
    a = d[0] * d[0] + d[1] * d[1]
    b = o[0] * d[0] + o[1] * d[1]
    disc = b * b - a * c
    best = math.inf
    if disc >= 0.0 and a > 0.0:
        t = (-b - math.sqrt(disc)) / a
        if t >= 0.0 and abs(o[2] + t * d[2]) <= half_length:
            best = t
    if d[2] != 0.0:
        t = (-math.copysign(half_length, d[2]) - o[2]) / d[2]
        x, y = o[0] + t * d[0], o[1] + t * d[1]
        if t >= 0.0 and x * x + y * y <= radius * radius:
            best = min(best, t)
    return best


@njit(cache=True, nogil=True, error_model="numpy")
def _sphere(o: FloatArray, d: FloatArray, radius: float) -> float:
    b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2]
    c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - radius * radius
    disc = b * b - c
    if disc < 0.0 or c <= 0.0:
        return math.inf
    t = -b - math.sqrt(disc)
    return t if t >= 0.0 else math.inf


@njit(cache=True, nogil=True, error_model="numpy")
def _lit(kind: int, local: FloatArray, half: FloatArray, rotation: FloatArray,
         light: FloatArray, ambient: float) -> float:
    """The light on a primitive at a point ``local`` on it, from its outward unit normal."""
    n0 = n1 = n2 = 0.0
    if kind == BOX:
        axis, ratio = 0, -1.0
        for i in range(3):
            if abs(local[i]) / half[i] > ratio:
                axis, ratio = i, abs(local[i]) / half[i]
        sign = np.sign(local[axis])
        n0, n1, n2 = (sign if axis == 0 else 0.0), (sign if axis == 1 else 0.0), \
            (sign if axis == 2 else 0.0)
    elif kind == CYLINDER:
        radial = math.hypot(local[0], local[1])
        if abs(local[2]) / half[2] >= radial / half[0]:
            n2 = np.sign(local[2])
        elif radial > 0.0:
            n0, n1 = local[0] / radial, local[1] / radial
    else:
        length = math.sqrt(local[0] ** 2 + local[1] ** 2 + local[2] ** 2)
        if length > 0.0:
            n0, n1, n2 = local[0] / length, local[1] / length, local[2] / length
    dot = 0.0
    for r in range(3):
        dot += (rotation[r, 0] * n0 + rotation[r, 1] * n1 + rotation[r, 2] * n2) * light[r]
    return ambient + (1.0 - ambient) * abs(dot)


@njit(cache=True, nogil=True, error_model="numpy")
def shade(origin: FloatArray, directions: FloatArray, forward: FloatArray, near_m: float,
          far_m: float, kinds: IntArray, halves: FloatArray, rotations: FloatArray,
          centres: FloatArray, colours: FloatArray, floor: FloatArray, sky: FloatArray,
          light: FloatArray, ambient: float, colour: FloatArray, distance: FloatArray) -> None:
    """Fill ``colour`` (N, 3) and ``distance`` (N,) [m] (inf: nothing) for each ray.

    Primitives (S of them): ``kinds``, ``halves`` (S, 3), ``rotations`` (S, 3, 3, local
    axes as columns), ``centres`` (S, 3) in the world, base ``colours`` (S, 3); ``floor``
    holds the checker's two colours (2, 3).
    """
    count = len(kinds)
    local_origins = np.empty((count, 3))
    for s in range(count):
        for i in range(3):
            local_origins[s, i] = ((origin[0] - centres[s, 0]) * rotations[s, 0, i]
                                   + (origin[1] - centres[s, 1]) * rotations[s, 1, i]
                                   + (origin[2] - centres[s, 2]) * rotations[s, 2, i])
    d, local = np.empty(3), np.empty(3)
    for n in range(len(directions)):
        best, which = math.inf, -2  # -2: nothing, -1: the floor, s: a primitive
        if directions[n, 2] < 0.0:
            t = -origin[2] / directions[n, 2]
            if t >= 0.0 and near_m <= t * forward[n] <= far_m:
                best, which = t, -1
        for s in range(count):
            for i in range(3):
                d[i] = (directions[n, 0] * rotations[s, 0, i] + directions[n, 1]
                        * rotations[s, 1, i] + directions[n, 2] * rotations[s, 2, i])
            o = local_origins[s]
            if kinds[s] == BOX:
                t = _box(o, d, halves[s])
            elif kinds[s] == CYLINDER:
                t = _cylinder(o, d, halves[s])
            else:
                t = _sphere(o, d, halves[s, 0])
            if t < best and near_m <= t * forward[n] <= far_m:
                best, which = t, s
        distance[n] = best
        if which == -2:
            for i in range(3):
                colour[n, i] = sky[i]
        elif which == -1:
            x, y = origin[0] + best * directions[n, 0], origin[1] + best * directions[n, 1]
            square = int(math.floor(x) + math.floor(y)) % 2
            lit = ambient + (1.0 - ambient) * abs(light[2])
            for i in range(3):
                colour[n, i] = floor[square, i] * lit
        else:
            for i in range(3):
                local[i] = local_origins[which, i] + best * (
                    directions[n, 0] * rotations[which, 0, i] + directions[n, 1]
                    * rotations[which, 1, i] + directions[n, 2] * rotations[which, 2, i])
            lit = _lit(kinds[which], local, halves[which], rotations[which], light, ambient)
            for i in range(3):
                colour[n, i] = colours[which, i] * lit
