r"""Rays from a camera against one box, cylinder or sphere, in the primitive's own frame.

Compiled by numba for :mod:`~servicebot_cli.simulate.sensors.camera_kernel`, with the numpy
path's tests and rounding (:mod:`~servicebot_cli.simulate.world.raycast`): the slab method,
the cylinder's quadratic and caps, the sphere's quadratic; a ray that starts inside a
primitive does not see it. Each returns the entry distance [m], inf for none. Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]
BOX, CYLINDER, SPHERE, MESH = 0, 1, 2, 3
"""Kind numbers: ``camera_image.PART_KINDS``' order; a mesh part is not a primitive."""


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _slab(o: float, d: float, half: float, near: float, far: float) -> tuple[float, float]:
    """One axis of the slab method: ``near`` and ``far`` narrowed (near > far: a miss)."""
    if d == 0.0:
        return (near, far) if -half <= o <= half else (math.inf, -math.inf)
    inv = 1.0 / d  # as raycast.box_entry: the same rounding at edges
    t1, t2 = (-half - o) * inv, (half - o) * inv
    return max(near, min(t1, t2)), min(far, max(t1, t2))


@njit(cache=True, nogil=True, error_model="numpy")
def box(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float, h0: float,
         h1: float, h2: float) -> float:
    """Slab method: entry into the box of half sizes ``h0, h1, h2`` about the origin."""
    near, far = _slab(o0, d0, h0, -math.inf, math.inf)
    near, far = _slab(o1, d1, h1, near, far)
    near, far = _slab(o2, d2, h2, near, far)
    return near if near <= far and near >= 0.0 else math.inf


@njit(cache=True, nogil=True, error_model="numpy")
def cylinder(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float,
              radius: float, half_length: float) -> float:
    """Entry into the cylinder about the local z axis: its side's quadratic, then its caps."""
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
def sphere(o0: float, o1: float, o2: float, d0: float, d1: float, d2: float,
            radius: float) -> float:
    """Entry into the sphere of ``radius`` about the origin."""
    b = o0 * d0 + o1 * d1 + o2 * d2
    c = o0 * o0 + o1 * o1 + o2 * o2 - radius * radius
    disc = b * b - c
    if disc < 0.0 or c <= 0.0:
        return math.inf
    t = -b - math.sqrt(disc)
    return t if t >= 0.0 else math.inf


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def lit(kind: int, local: FloatArray, half: FloatArray, rotation: FloatArray,
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


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def entry(kind: int, o0: float, o1: float, o2: float, d0: float, d1: float, d2: float,
          h0: float, h1: float, h2: float) -> float:
    """Entry distance into a primitive of ``kind`` with half sizes ``h0, h1, h2`` [m]."""
    if kind == BOX:
        return box(o0, o1, o2, d0, d1, d2, h0, h1, h2)
    if kind == CYLINDER:
        return cylinder(o0, o1, o2, d0, d1, d2, h0, h2)
    return sphere(o0, o1, o2, d0, d1, d2, h0)
