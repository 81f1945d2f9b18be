"""Gazebo's gaussian sensor noise, repeatable from one seed.

Gazebo draws a bias once per run from ``N(bias_mean, bias_stddev)``, flips its sign with
probability one half, and adds it with fresh ``N(mean, stddev)`` noise to every sample. Each
stream draws from its own generator derived from the run's seed and the stream's name, so
turning one sensor off leaves the noise of the others unchanged.
"""

from __future__ import annotations

import zlib

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.sensors import NoiseSpec

FloatArray = npt.NDArray[np.float64]


def stream_rng(seed: int, stream: str) -> np.random.Generator:
    """The generator of ``stream`` for a run seeded with ``seed``."""
    return np.random.default_rng([seed, zlib.crc32(stream.encode())])


def apply(values: FloatArray, spec: NoiseSpec | None, rng: np.random.Generator) -> FloatArray:
    """``values`` with ``spec``'s noise; unchanged when there is none (or type ``none``)."""
    if spec is None or spec.type == "none":
        return values
    bias = 0.0
    if spec.bias_mean or spec.bias_stddev:
        bias = rng.normal(spec.bias_mean, spec.bias_stddev)
        if rng.uniform() < 0.5:
            bias = -bias
    return values + rng.normal(spec.mean, spec.stddev, size=np.shape(values)) + bias


def variance(spec: NoiseSpec | None) -> float:
    """The noise variance a ROS message reports as covariance [unit^2]."""
    return 0.0 if spec is None or spec.type == "none" else spec.stddev**2
