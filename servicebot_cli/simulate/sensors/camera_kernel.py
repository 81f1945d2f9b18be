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


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _slab(o: float, d: float, half: float, near: float, far: float) -> tuple[float, float]:
    """One axis of the slab method: ``near`` and ``far`` narrowed (near > far: a miss)."""
    if d == 0.0:
        return (near, far) if -half <= o <= half else (math.inf, -math.inf)
    inv = 1.0 / d  # as raycast.box_entry: the same rounding at edges
    t1, t2 = (-half - o) * inv, (half - o) * inv
    return max(near, min(t1, t2)), min(far, max(t1, t2))


@njit(cache=True, nogil=True, error_model="numpy")
def _box(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float, h0: float,
         h1: float, h2: float) -> float:
    near, far = _slab(o0, d0, h0, -math.inf, math.inf)
    near, far = _slab(o1, d1, h1, near, far)
    near, far = _slab(o2, d2, h2, near, far)
    return near if near <= far and near >= 0.0 else math.inf


@njit(cache=True, nogil=True, error_model="numpy")
def _cylinder(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float,
              radius: float, half_length: float) -> float:
    c = o0 * o0 + o1 * o1 - radius * radius
    if c < 0.0 and abs(o2) < half_length:
        return math.inf  # from inside: no entry
    a = d0 * d0 + d1 * d1
    b = o0 * d0 + o1 * d1
    disc = b * b - a * c
    best = math.inf
    if disc >= 0.0 and a > 0.0:
        t = (-b - math.sqrt(disc)) / a
        if t >= 0.0 and abs(o2 + t * d2) <= half_length:
            best = t
    if d2 != 0.0:
        t = (-math.copysign(half_length, d2) - o2) / d2
        x, y = o0 + t * d0, o1 + t * d1
        if t >= 0.0 and x * x + y * y <= radius * radius:
            best = min(best, t)
    return best


@njit(cache=True, nogil=True, error_model="numpy")
def _sphere(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float,
            radius: float) -> float:
    b = o0 * d0 + o1 * d1 + o2 * d2
    c = o0 * o0 + o1 * o1 + o2 * o2 - radius * radius
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
    # each primitive's bounding sphere as seen from the camera: a ray further from its
    # centre's direction than its angular radius, or with a nearer hit already, misses it
    towards, reach_cos, nearest = np.empty((count, 3)), np.empty(count), np.empty(count)
    for s in range(count):
        offset = centres[s] - origin
        length = math.sqrt(offset[0] ** 2 + offset[1] ** 2 + offset[2] ** 2)
        radius = math.sqrt(halves[s, 0] ** 2 + halves[s, 1] ** 2 + halves[s, 2] ** 2)
        towards[s] = offset / length if length > 0.0 else offset
        inside = length <= radius * (1.0 + 1e-9)
        reach_cos[s] = -2.0 if inside else math.cos(math.asin(radius / length)) - 1e-9
        nearest[s] = 0.0 if inside else length - radius
    local = np.empty(3)
    for n in range(len(directions)):
        dx, dy, dz = directions[n, 0], directions[n, 1], directions[n, 2]
        best, which = math.inf, -2  # -2: nothing, -1: the floor, s: a primitive
        if dz < 0.0:
            t = -origin[2] / dz
            if t >= 0.0 and near_m <= t * forward[n] <= far_m:
                best, which = t, -1
        for s in range(count):
            if nearest[s] >= best or (dx * towards[s, 0] + dy * towards[s, 1]
                                      + dz * towards[s, 2]) < reach_cos[s]:
                continue
            r = rotations[s]
            d0 = dx * r[0, 0] + dy * r[1, 0] + dz * r[2, 0]
            d1 = dx * r[0, 1] + dy * r[1, 1] + dz * r[2, 1]
            d2 = dx * r[0, 2] + dy * r[1, 2] + dz * r[2, 2]
            o0, o1, o2 = local_origins[s, 0], local_origins[s, 1], local_origins[s, 2]
            if kinds[s] == BOX:
                t = _box(o0, o1, o2, d0, d1, d2, halves[s, 0], halves[s, 1], halves[s, 2])
            elif kinds[s] == CYLINDER:
                t = _cylinder(o0, o1, o2, d0, d1, d2, halves[s, 0], halves[s, 2])
            else:
                t = _sphere(o0, o1, o2, d0, d1, d2, halves[s, 0])
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
