"""When a stream publishes: every ``1 / rate`` seconds, the first message one period in."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt


def sample_times(rate_hz: float, duration_s: float) -> npt.NDArray[np.float64]:
    """``k / rate_hz`` for k = 1 .. floor(duration_s * rate_hz) [s]."""
    count = int(np.floor(duration_s * rate_hz + 1e-9))
    return np.arange(1, count + 1) / rate_hz
