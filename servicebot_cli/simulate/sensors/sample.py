"""When a stream publishes: every ``1 / rate`` seconds, the first message one period in.

A run is simulated a stretch of control ticks at a time; :class:`SampleClock` hands each
stretch the sample times that fall in it, the same numbers :func:`sample_times` gives for the
whole run.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]


def sample_times(rate_hz: float, duration_s: float) -> FloatArray:
    """``k / rate_hz`` for k = 1 .. floor(duration_s * rate_hz) [s]."""
    return np.arange(1, sample_count(rate_hz, duration_s) + 1) / rate_hz


def sample_count(rate_hz: float, duration_s: float) -> int:
    """How many samples a stream at ``rate_hz`` has in a run of ``duration_s``."""
    return int(np.floor(duration_s * rate_hz + 1e-9))


class SampleClock:
    """A stream's sample times, handed out a stretch of control ticks at a time.

    A sample belongs to the tick that holds it, ``floor(t / dt)`` (to 1e-9 of a tick); those
    past the run's last tick belong to it.

    Args:
        rate_hz: The stream's rate.
        duration_s: The run's length.
        dt_s: The control period.
    """

    def __init__(self, rate_hz: float, duration_s: float, dt_s: float) -> None:
        self.rate_hz, self.dt_s = rate_hz, dt_s
        self.count = sample_count(rate_hz, duration_s)
        self.taken = 0

    @property
    def period_s(self) -> float:
        """Time between the run's first two samples [s] (0 for a run of fewer)."""
        return float(np.diff(np.arange(1, 3) / self.rate_hz)[0]) if self.count > 1 else 0.0

    def take(self, stop_tick: int | None) -> FloatArray:
        """The next samples: those that belong to ticks before ``stop_tick`` (None: all)."""
        end = self.count
        if stop_tick is not None:
            # k / rate for k up to here covers every tick before stop_tick, and a few more
            end = min(end, math.ceil((stop_tick + 1) * self.dt_s * self.rate_hz) + 1)
        times = np.arange(self.taken + 1, end + 1) / self.rate_hz
        if stop_tick is not None:
            ticks = np.floor(times / self.dt_s + 1e-9).astype(np.int64)
            times = times[:int(np.searchsorted(ticks, stop_tick))]
        self.taken += len(times)
        return times
