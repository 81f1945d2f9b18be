"""glibc's malloc told to keep the memory a run frees, for numpy's next temporaries.

A piece's numpy temporaries run to megabytes. By default glibc maps large blocks afresh
(from 128 kB, a threshold that then moves with what was freed) and gives memory freed at
the heap's top back to the system, so each piece's temporaries come back as fresh pages
that fault one by one: thousands of page faults a run. Served from the heap (blocks up to
32 MB) with a large trim threshold and a large top pad, they reuse the pages the piece
before touched, and the memory is given back when the process ends. The ``simulate``
command sets it for its own process; the library functions do not (a long-lived process
that calls them keeps its own malloc settings). Elsewhere than glibc this does nothing.
"""

from __future__ import annotations

import sys

_M_TRIM_THRESHOLD = -1  # mallopt's parameters, from glibc's malloc.h
_M_TOP_PAD = -2
_M_MMAP_THRESHOLD = -3
MMAP_THRESHOLD_BYTES = 32 << 20
"""Blocks from this size on are mapped on their own (glibc's largest threshold)."""
TRIM_THRESHOLD_BYTES = 512 << 20
"""Free memory at the heap's top kept rather than given back to the system."""
TOP_PAD_BYTES = 64 << 20
"""Extra address space the heap takes each time it grows (pages are only used when touched)."""


def keep_freed_memory() -> bool:
    """Tell glibc's malloc to keep freed memory for the process's next allocations.

    Process-wide, for the rest of the process. Returns whether glibc took every setting.
    """
    if not sys.platform.startswith("linux"):
        return False
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    return all([mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES),
                mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD_BYTES),
                mallopt(_M_TOP_PAD, TOP_PAD_BYTES)])
