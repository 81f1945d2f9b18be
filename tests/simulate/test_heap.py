"""glibc's malloc keeps the memory a run frees (fewer page faults for numpy's temporaries)."""

from __future__ import annotations

import platform
import subprocess
import sys

import pytest

from servicebot_cli.simulate.heap import keep_freed_memory

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux") or platform.libc_ver()[0] != "glibc",
    reason="glibc's mallopt")

_TEMPORARIES = """
import resource, sys
import numpy as np
from servicebot_cli.simulate.heap import keep_freed_memory
if sys.argv[1] == "keep":
    assert keep_freed_memory()
def faults():
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for size in (1 << 22, 1 << 20, 1 << 23, 1 << 21, 3 << 21, 1 << 22):  # bytes
        a, b, c = np.ones(size // 8), np.ones(size // 16), np.ones(size // 4)
        del a
        d = np.ones(size // 8)
        del b, c, d
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before
faults()  # the heap grows to what the temporaries need
print(faults())
"""


def _faults(mode: str) -> int:
    done = subprocess.run([sys.executable, "-c", _TEMPORARIES, mode], capture_output=True,
                          text=True, check=True)
    return int(done.stdout)


def test_every_setting_is_taken():
    assert keep_freed_memory()
    assert keep_freed_memory()  # again: harmless


def test_temporaries_of_changing_sizes_come_back_without_page_faults():
    kept = _faults("keep")
    assert kept < 50
    assert kept < _faults("default")
