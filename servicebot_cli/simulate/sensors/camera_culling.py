r"""Which primitives each tile of a camera frame can show, and how near each can be.

A primitive (box, cylinder, sphere) lies within its box: centre :math:`c`, unit axes
:math:`a_i`, half sizes :math:`h_i` (a cylinder's are ``(r, r, half length)``). In the
optical frame (x right, y down, z forward) the rays of pixel columns :math:`u_0 .. u_1` and
rows :math:`v_0 .. v_1` lie within the planes :math:`x \ge \alpha_0 z`, :math:`x \le
\alpha_1 z`, :math:`y \ge \beta_0 z`, :math:`y \le \beta_1 z` (:math:`\alpha = (u + 1 - c_x)
/ f_x`, :math:`\beta = (v + 1 - c_y) / f_y`), and what is drawn within
:math:`z_{near} \le z \le z_{far}`. A box is wholly outside the plane
:math:`n \cdot p + o \ge 0` when

.. math:: n \cdot c + o + \sum_i h_i |n \cdot a_i| < 0,

so no ray of the tile can meet it. Rays meet a primitive no nearer than the distance from
the camera to its box, by which the survivors are sorted: a ray stops once its nearest hit
is nearer than the next one's box. Compiled by numba. Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_MARGIN_M = 1e-6  # boxes this near a plane stay: rays are normalised, planes are not


@njit(cache=True, nogil=True, error_model="numpy")
def boxes(rotation: FloatArray, origin: FloatArray, halves: FloatArray, rotations: FloatArray,
          centres: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Each primitive's box in the optical frame, and its distance from the camera.

    Returns:
        Centres (S, 3), half-size axes (S, 3, 3: ``[s, i]`` is :math:`h_i a_i`), and the
        distance from the camera to the box [m] (0 inside it), (S,).
    """
    count = len(halves)
    centre, axes, distance = np.empty((count, 3)), np.empty((count, 3, 3)), np.empty(count)
    for s in range(count):
        link = np.empty(3)
        for j in range(3):  # into the camera link's frame (x forward, y left, z up)
            link[j] = ((centres[s, 0] - origin[0]) * rotation[0, j]
                       + (centres[s, 1] - origin[1]) * rotation[1, j]
                       + (centres[s, 2] - origin[2]) * rotation[2, j])
        centre[s, 0], centre[s, 1], centre[s, 2] = -link[1], -link[2], link[0]
        outside = 0.0
        for i in range(3):
            for j in range(3):
                link[j] = (rotation[0, j] * rotations[s, 0, i] + rotation[1, j]
                           * rotations[s, 1, i] + rotation[2, j] * rotations[s, 2, i])
            axes[s, i, 0], axes[s, i, 1], axes[s, i, 2] = -link[1] * halves[s, i], \
                -link[2] * halves[s, i], link[0] * halves[s, i]
            # the camera's offset along the primitive's axis i, beyond the box's face
            along = -(centre[s, 0] * axes[s, i, 0] + centre[s, 1] * axes[s, i, 1]
                      + centre[s, 2] * axes[s, i, 2]) / max(halves[s, i], 1e-300)
            outside += max(0.0, abs(along) - halves[s, i]) ** 2
        distance[s] = math.sqrt(outside)
    return centre, axes, distance


@njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _outside(centre: FloatArray, axes: FloatArray, n0: float, n1: float, n2: float,
             offset: float) -> bool:
    """Whether a box is wholly on the negative side of ``n . p + offset >= 0``."""
    reach = 0.0
    for i in range(3):
        reach += abs(n0 * axes[i, 0] + n1 * axes[i, 1] + n2 * axes[i, 2])
    value = float(n0 * centre[0] + n1 * centre[1] + n2 * centre[2] + offset + reach)
    return value < -_MARGIN_M


@njit(cache=True, nogil=True, error_model="numpy")
def visible(centre: FloatArray, axes: FloatArray, cone: FloatArray, near_m: float,
            far_m: float) -> bool:
    """Whether a box can meet a ray within ``cone`` (alpha 0, alpha 1, beta 0, beta 1)."""
    a0, a1, b0, b1 = cone[0], cone[1], cone[2], cone[3]
    return not (_outside(centre, axes, 1.0, 0.0, -a0, 0.0)
                or _outside(centre, axes, -1.0, 0.0, a1, 0.0)
                or _outside(centre, axes, 0.0, 1.0, -b0, 0.0)
                or _outside(centre, axes, 0.0, -1.0, b1, 0.0)
                or _outside(centre, axes, 0.0, 0.0, 1.0, -near_m)
                or (far_m < math.inf and _outside(centre, axes, 0.0, 0.0, -1.0, far_m)))


@njit(cache=True, nogil=True, error_model="numpy")
def cone(intrinsics: FloatArray, first_column: int, last_column: int, first_row: int,
         last_row: int) -> FloatArray:
    """(alpha 0, alpha 1, beta 0, beta 1) of the pixels' centres in the given span.

    ``intrinsics`` holds fx, cx, fy, cy (one-based principal point, as ``camera_info``).
    """
    fx, cx, fy, cy = intrinsics[0], intrinsics[1], intrinsics[2], intrinsics[3]
    out = np.empty(4)
    out[0], out[1] = (first_column + 1 - cx) / fx, (last_column + 1 - cx) / fx
    out[2], out[3] = (first_row + 1 - cy) / fy, (last_row + 1 - cy) / fy
    return out


@njit(cache=True, nogil=True, error_model="numpy")
def survivors(candidates: IntArray, centre: FloatArray, axes: FloatArray, cone: FloatArray,
              near_m: float, far_m: float, out: IntArray) -> int:
    """Write the ``candidates`` visible within ``cone`` to ``out`` in order; their count."""
    count = 0
    for s in candidates:
        if visible(centre[s], axes[s], cone, near_m, far_m):
            out[count] = s
            count += 1
    return count
