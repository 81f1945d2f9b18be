r"""The compiled IK loop's damped least-squares step, solved by Cholesky without BLAS.

.. math:: \Delta q = J^T (J J^T + \lambda I)^{-1} e

or the equivalent :math:`(J^T J + \lambda I)^{-1} J^T e` when J has more rows than columns,
capped at 2 (rad or m). Compiled by numba (cached on disk after the first run), for
:mod:`~servicebot_cli.kinematics.lm_kernel`. Pure.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

FloatArray = npt.NDArray[np.float64]

_MAX_STEP = 2.0  # largest step norm [rad or m]


@njit(cache=True, nogil=True)
def _solve_spd(a: FloatArray, b: FloatArray) -> None:
    """Solve ``a x = b`` in place (``b`` becomes ``x``) by Cholesky; ``a`` is overwritten."""
    n = b.shape[0]
    for j in range(n):
        d = a[j, j]
        for k in range(j):
            d -= a[j, k] * a[j, k]
        d = math.sqrt(d)
        a[j, j] = d
        for i in range(j + 1, n):
            s = a[i, j]
            for k in range(j):
                s -= a[i, k] * a[j, k]
            a[i, j] = s / d
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= a[i, k] * b[k]
        b[i] = s / a[i, i]
    for i in range(n - 1, -1, -1):
        s = b[i]
        for k in range(i + 1, n):
            s -= a[k, i] * b[k]
        b[i] = s / a[i, i]


@njit(cache=True, nogil=True)
def _gram(matrix: FloatArray, damping: float, out: FloatArray) -> None:
    """``out = M M^T + damping I`` for a small ``M`` (``out`` is (rows, rows))."""
    rows, cols = matrix.shape
    for i in range(rows):
        for j in range(i + 1):
            s = 0.0
            for k in range(cols):
                s += matrix[i, k] * matrix[j, k]
            out[i, j] = out[j, i] = s
        out[i, i] += damping


@njit(cache=True, nogil=True)
def damped_step(jacobian: FloatArray, error: FloatArray, damping: float, step: FloatArray,
                gram: FloatArray, solved: FloatArray) -> None:
    """The damped least-squares step, capped at :data:`_MAX_STEP`, into ``step``.

    ``gram`` (k, k) and ``solved`` (k,), k the smaller side of the Jacobian, are scratch.
    """
    rows, cols = jacobian.shape
    if rows <= cols:  # J^T (J J^T + lambda I)^-1 e
        _gram(jacobian, damping, gram)
        solved[:] = error
        _solve_spd(gram, solved)
        for c in range(cols):
            step[c] = 0.0
            for r in range(rows):
                step[c] += jacobian[r, c] * solved[r]
    else:  # (J^T J + lambda I)^-1 J^T e
        _gram(jacobian.T, damping, gram)
        for c in range(cols):
            step[c] = 0.0
            for r in range(rows):
                step[c] += jacobian[r, c] * error[r]
        _solve_spd(gram, step)
    size2 = 0.0
    for i in range(cols):
        size2 += step[i] * step[i]
    if size2 > _MAX_STEP * _MAX_STEP:
        scale = _MAX_STEP / math.sqrt(size2)
        for i in range(cols):
            step[i] *= scale
