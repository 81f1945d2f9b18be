"""Rows of bytes placed end to end where the MCAP records go: the bytes a plain loop writes."""

from __future__ import annotations

import numpy as np
import pytest

from servicebot_cli.simulate.bag.byte_rows import place_rows


@pytest.mark.parametrize(("width", "count", "gap"), [(330, 500, 7), (1, 300, 0), (0, 10, 3),
                                                     (1500, 40, 1), (64, 0, 2)])
def test_rows_land_where_a_loop_puts_them(width, count, gap):
    rng = np.random.default_rng(width + count)
    rows = rng.integers(0, 256, (2 * count, width), dtype=np.uint8)[::2]  # not contiguous
    starts = np.arange(count, dtype=np.int64) * (width + gap) + gap
    flat = rng.integers(0, 256, int(count * (width + gap) + gap + 5), dtype=np.uint8)
    expected = flat.copy()
    for start, row in zip(starts.tolist(), rows, strict=True):
        expected[start:start + width] = row
    place_rows(flat, starts, rows)
    assert flat.tobytes() == expected.tobytes()
