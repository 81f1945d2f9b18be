"""Gazebo's gaussian sensor noise, repeatable from one seed, drawn a piece of the run at a time.

Gazebo draws a bias once per run from ``N(bias_mean, bias_stddev)``, flips its sign with
probability one half, and adds it with fresh ``N(mean, stddev)`` noise to every sample. Each
stream draws from its own generator derived from the run's seed and the stream's name, so
turning one sensor off leaves the noise of the others unchanged.

A run is simulated a piece at a time; numpy's generators give the same numbers whether a
block of samples is drawn in one call or in several, so the pieces add up to the same bits.
Where one generator serves several quantities, each drawn for the whole run before the next
(the IMU's six axes), :func:`one_after_another` positions a generator at each block.
"""

from __future__ import annotations

import copy
import zlib
from collections.abc import Sequence

import numpy as np
import numpy.random  # on import, not on the run's first draw (numpy imports it lazily)
import numpy.typing as npt

from servicebot_cli.description.sensors import NoiseSpec

FloatArray = npt.NDArray[np.float64]
_SKIP_BATCH = 1 << 18  # numbers drawn per call while moving a generator past a block


def stream_rng(seed: int, stream: str) -> np.random.Generator:
    """The generator of ``stream`` for a run seeded with ``seed``."""
    return np.random.default_rng([seed, zlib.crc32(stream.encode())])


class Noise:
    """The noise of one quantity: its bias drawn on creation, fresh noise for each batch.

    A negative standard deviation draws as its magnitude: Gazebo's ``std::normal_distribution``
    computes ``mean + stddev * z`` for a symmetric ``z``, the same spread either way.
    """

    def __init__(self, spec: NoiseSpec | None, rng: np.random.Generator) -> None:
        self.spec = spec if spec is not None and spec.type != "none" else None
        self.rng, self.bias = rng, 0.0
        if self.spec is not None and (self.spec.bias_mean or self.spec.bias_stddev):
            self.bias = rng.normal(self.spec.bias_mean, abs(self.spec.bias_stddev))
            if rng.uniform() < 0.5:
                self.bias = -self.bias

    def add(self, values: FloatArray) -> FloatArray:
        """``values`` with the noise; unchanged when there is none (or type ``none``)."""
        if self.spec is None:
            return values
        return values + self.rng.normal(self.spec.mean, abs(self.spec.stddev),
                                        size=np.shape(values)) + self.bias

    def skip(self, count: int) -> None:
        """Draw past ``count`` samples, as :meth:`add` would, without keeping them."""
        if self.spec is None:
            return
        for start in range(0, count, _SKIP_BATCH):
            self.rng.normal(self.spec.mean, abs(self.spec.stddev),
                            size=min(_SKIP_BATCH, count - start))


def apply(values: FloatArray, spec: NoiseSpec | None, rng: np.random.Generator) -> FloatArray:
    """``values`` with ``spec``'s noise; unchanged when there is none (or type ``none``)."""
    return Noise(spec, rng).add(values)


def one_after_another(specs: Sequence[NoiseSpec | None], rng: np.random.Generator,
                      count: int) -> list[Noise]:
    """Noise for quantities that one generator serves in turn, ``count`` samples each.

    Drawn whole, quantity ``i`` takes its bias and its ``count`` samples from ``rng`` after
    quantity ``i - 1`` took all of its own. Each returned :class:`Noise` holds a copy of the
    generator at its block's start, so the blocks can be drawn a piece at a time, side by
    side, and still give those numbers.
    """
    out = []
    for spec in specs:
        noise = Noise(spec, rng)  # the bias, drawn in turn from the shared generator
        start = copy.deepcopy(rng)  # where this quantity's samples begin
        noise.skip(count)  # the shared generator moves past them, to the next quantity
        noise.rng = start
        out.append(noise)
    return out


def variance(spec: NoiseSpec | None) -> float:
    """The noise variance a ROS message reports as covariance [unit^2]."""
    return 0.0 if spec is None or spec.type == "none" else spec.stddev**2
