"""Where random joint values are drawn: within the limits, and never far beyond any robot.

Limits of +-1e308 bound nothing a sample can use (numpy refuses their span, and a start
there overflows): a joint is drawn within :data:`SPAN` of zero where its limits allow more.
Within that, the draws are the limits' own. Pure.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

SPAN = 100.0
"""rad or m: the furthest from zero a random joint value is drawn (no robot moves further)."""


def sampling_bounds(lower: npt.ArrayLike, upper: npt.ArrayLike
                    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``lower`` and ``upper`` (arrays or numbers) cut to within :data:`SPAN` of zero.

    Limits that lie wholly beyond the span are kept as they are.
    """
    low, high = np.maximum(lower, -SPAN), np.minimum(upper, SPAN)
    inside = low <= high
    return np.where(inside, low, lower), np.where(inside, high, upper)
