r"""Pixel noise keyed by (frame, pixel, channel), so any piece of a frame draws its own.

A camera frame's gaussian noise is not drawn in sequence from a generator: each frame takes
one 64-bit key from the run's camera generator, and the noise of pixel :math:`n`, channel
:math:`c` is a function of the key and :math:`n` alone. Rows can then be shaded in any
order, on any number of threads, in numba's loop or in numpy, with the same bytes.

The function: SplitMix64's finaliser of :math:`k + (n + 1) \varphi` (:math:`\varphi` the
64-bit golden ratio) gives 64 random bits per pixel; each channel takes 16 of them as an
index into a table of the standard normal's quantiles at :math:`(i + 1/2) / 2^{16}`, so a
draw is one of 65,536 equally likely values (within :math:`\pm 4.17\sigma`; the steps near
the mean are :math:`4 \times 10^{-5} \sigma`). Only integer arithmetic and a table lookup:
no libm function whose last bit could differ between numpy and numba.
"""

from __future__ import annotations

import functools
import statistics

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
UintArray = npt.NDArray[np.uint64]
TABLE_BITS = 16
GOLDEN = np.uint64(0x9E3779B97F4A7C15)
MIX_1 = np.uint64(0xBF58476D1CE4E5B9)
MIX_2 = np.uint64(0x94D049BB133111EB)


@functools.cache
def normal_table() -> FloatArray:
    """Quantiles of N(0, 1) at ``(i + 0.5) / 2**16``, shape (65536,), read-only."""
    size = 1 << TABLE_BITS
    half = [statistics.NormalDist().inv_cdf((i + 0.5) / size) for i in range(size // 2)]
    table = np.array([*half, *(-z for z in reversed(half))])
    table.flags.writeable = False
    return table


def frame_key(rng: np.random.Generator) -> np.uint64:
    """The next frame's key from the run's camera generator (one draw a frame)."""
    return np.uint64(rng.integers(0, 1 << 64, dtype=np.uint64, endpoint=False))


def pixel_bits(key: np.uint64, count: int) -> UintArray:
    """SplitMix64 bits of pixels ``0 .. count - 1`` for a frame's ``key``, shape (count,)."""
    z = key + (np.arange(1, count + 1, dtype=np.uint64) * GOLDEN)
    z = (z ^ (z >> np.uint64(30))) * MIX_1
    z = (z ^ (z >> np.uint64(27))) * MIX_2
    bits: UintArray = z ^ (z >> np.uint64(31))
    return bits


def standard_normal(key: np.uint64, count: int) -> FloatArray:
    """N(0, 1) draws of ``count`` pixels' three channels, shape (count, 3)."""
    bits = pixel_bits(key, count)
    mask = np.uint64((1 << TABLE_BITS) - 1)
    index = np.stack([(bits >> np.uint64(TABLE_BITS * c)) & mask for c in range(3)], axis=1)
    drawn: FloatArray = normal_table()[index.astype(np.intp)]
    return drawn
