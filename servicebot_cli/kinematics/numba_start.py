"""Readying numba's compiled loops without importing scipy.linalg (0.17 s of a start).

The first compiled function a process loads makes numba set up its compiler, which imports
``numba.np.arraymath``; that module imports ``scipy.linalg.cython_blas`` once, only to
learn whether a BLAS is there (``_HAVE_BLAS``), and scipy.linalg's package pulls in much of
scipy. The flag only picks how one helper of numba's own ``np.correlate``/``np.convolve``
sums; ``np.dot`` and ``np.linalg`` check for BLAS themselves when a function using them is
compiled, and still find it. Our loops use neither, so :func:`without_blas_probe` makes that
one import fail while the compiler is set up. Pure (it touches only ``sys.modules``, and
puts it back).
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterator

_PROBED = "scipy.linalg.cython_blas"
_PROBER = "numba.np.arraymath"


@contextlib.contextmanager
def without_blas_probe() -> Iterator[None]:
    """Within the block, numba's first set-up does not import scipy.linalg."""
    if _PROBER in sys.modules or _PROBED in sys.modules:
        yield
        return
    sys.modules[_PROBED] = None  # type: ignore[assignment]  # import fails: ImportError
    try:
        yield
    finally:
        if _PROBED in sys.modules and sys.modules[_PROBED] is None:
            del sys.modules[_PROBED]
