"""Benchmark scripts run as ``python bench/NAME.py``: their directory comes first on sys.path."""

from __future__ import annotations

import sys

from tests.conftest import REPO


def test_no_bench_script_shadows_a_standard_module():
    # bench/inspect.py once hid the stdlib's inspect from every other benchmark.
    clashes = [p.name for p in (REPO / "bench").glob("*.py") if p.stem in sys.stdlib_module_names]
    assert clashes == []
