"""One BLAS thread where numpy's products are too small to share (the default: one per core).

numpy's OpenBLAS starts a thread per core when numpy loads, and a large enough matrix product
then runs on all of them. Where the products are small, or the cores are already busy with
worker processes, those threads only cost: a tenth of a second of CPU per ``check`` of one
file on a busy two-core machine. The thread counts are read once, when numpy loads; a count
the user set is theirs and is left alone.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping

BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
"""Thread counts of numpy's BLAS (OpenBLAS, OpenMP, MKL), read when numpy loads."""


def one_thread_each(environ: Mapping[str, str]) -> dict[str, str]:
    """The BLAS thread counts to add to ``environ`` for one thread: those it does not set."""
    return {name: "1" for name in BLAS_THREADS if name not in environ}


def use_one_blas_thread() -> None:
    """Have numpy's BLAS run one thread in this process and its children, unless the user chose.

    Only before numpy loads: after, the counts are read already, and this does nothing.
    """
    if "numpy" not in sys.modules:
        os.environ.update(one_thread_each(os.environ))
