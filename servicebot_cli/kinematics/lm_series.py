r"""A series of IK targets solved in one compiled call, each from the previous answer.

:func:`solve_series` runs, for target after target, the attempts that
:meth:`~servicebot_cli.kinematics.inverse.IkSolver.solve` runs for one target when it wants
one solution and checks no collision: a run from the start (the previous answer) and
:data:`FIRST_RUN` random restarts, then runs of :data:`RUN` restarts, each run stopping at
the first attempt that converges (:func:`~servicebot_cli.kinematics.lm_kernel.search`).
Random starts come from one flat buffer of uniform numbers, consumed run by run exactly as
that solve draws them from its generator (``rng.random((restarts, n))``), so the caller can
bring the generator to the same place afterwards and the answers are the same, bit for bit.

The call returns early, so the caller can take over: at a target whose attempts all fail
(the caller solves it the slow way, which settles the best try and explains the failure),
and before a target whose worst case could run past the end of the buffer. Pure; compiled
by numba and cached on disk, as the kernel.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from numba import njit  # type: ignore[import-untyped, import-not-found, unused-ignore]

from servicebot_cli.kinematics.lm_kernel import search

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

FIRST_RUN = 8
"""Random restarts after the start in a target's first run."""
RUN = 16
"""Random restarts in each later run."""
DONE, FAILED, REFILL = 0, 1, 2
"""Why :func:`solve_series` returned: all solved, a target failed, the buffer ran low."""


@njit(cache=True, nogil=True)
def worst_draws(limit: int, n: int) -> int:
    """The most uniform numbers one target with ``limit`` attempts can draw."""
    return (FIRST_RUN + RUN * limit) * n


@njit(cache=True, nogil=True)
def solve_series(frames: FloatArray, axes: FloatArray, kinds: IntArray, limits: FloatArray,
                 goals: FloatArray, rows: IntArray, attempt_limits: IntArray,
                 tolerances: FloatArray, max_iterations: int, start: FloatArray,
                 unit: FloatArray, drawn: int, out: FloatArray, attempts: IntArray,
                 iterations: IntArray, draws: IntArray) -> tuple[int, int, int]:
    """Solve ``goals`` in order, each from the previous answer (the first from ``start``).

    Args:
        frames: The chain's joint placements (see ``ChainArrays``).
        axes: Each joint's axis.
        kinds: Each joint's kind.
        limits: Limits and the range of random starts.
        goals: Shape (m, 3, 4): each target's ``[R | p]`` in the root frame.
        rows: Shape (m,): 6 for a full pose, 3 for a position.
        attempt_limits: Shape (m,): attempts allowed per target (1 beyond the reach).
        tolerances: Position [m] and orientation [rad] tolerances.
        max_iterations: Iterations per attempt.
        start: Shape (n,): joint values of the first target's start.
        unit: Uniform numbers in [0, 1), consumed from index ``drawn`` on.
        drawn: Numbers of ``unit`` already consumed.
        out: Shape (m, n): each solved target's answer.
        attempts: Shape (m,): each solved target's attempts.
        iterations: Shape (m,): each solved target's iterations.
        draws: Shape (m,): numbers of ``unit`` consumed before each target's search.

    Returns:
        Targets solved (``k``: targets ``0..k-1`` are in ``out``), the numbers of ``unit``
        consumed by then, and why it returned (:data:`DONE`, :data:`FAILED` at target ``k``,
        :data:`REFILL` before target ``k``).
    """
    n = kinds.shape[0]
    theta = start.copy()
    no_seed = np.empty(0)
    for i in range(goals.shape[0]):
        limit = attempt_limits[i]
        if drawn + worst_draws(limit, n) > unit.shape[0]:
            return i, drawn, REFILL
        draws[i] = drawn
        made = used = 0
        converged = False
        while made < limit and not converged:
            restarts = min(limit - 1, FIRST_RUN) if made == 0 else min(limit - made, RUN)
            seed = theta if made == 0 else no_seed
            block = unit[drawn:drawn + restarts * n].reshape((restarts, n))
            drawn += restarts * n
            run_made, converged, run_used, _ = search(
                frames, axes, kinds, limits, goals[i], rows[i], tolerances, max_iterations,
                seed, block, out[i])
            made += run_made
            used += run_used
        if not converged:
            return i, draws[i], FAILED
        attempts[i], iterations[i] = made, used
        theta[:] = out[i]
    return goals.shape[0], drawn, DONE
