"""Many targets in one compiled call: the answers :meth:`IkSolver.solve` gives, faster.

A batch solves target after target, each from the previous answer. Where a solve wants one
solution, checks no collision and has no deadline, :func:`solve_leading` hands a whole run
of targets (full poses or positions) to the compiled loop
(:func:`~servicebot_cli.kinematics.lm_series.solve_series`) instead of one call per target.
The random restarts come from the same generator in the same order: a buffer is drawn, and
afterwards the generator is put back where the per-target solves would have left it
(``PCG64.advance``), so a fixed ``--seed`` gives the same answers, bit for bit.

Every answer is then measured by Pinocchio's forward kinematics, as a single solve's is.
The run stops before the first target the loop failed or Pinocchio does not confirm: the
caller solves that one target the ordinary way (which settles the best try and says why it
failed), and goes on. Pure.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.inverse import IkResult, IkSolver, IkTarget

if TYPE_CHECKING:
    from servicebot_cli.kinematics.compiled_search import CompiledSearch

FloatArray = npt.NDArray[np.float64]

_BUFFER = 1 << 15  # uniform numbers drawn at a time (beyond one target's worst case)
_FIRST_RUN = 8  # as lm_series.FIRST_RUN, read without importing numba
_RUN = 16
_REFILL = 2  # lm_series.REFILL
_NEAR_M = 1e-9  # beyond the reach by less than this: tested again one target at a time


def series_search(solver: IkSolver, rng: np.random.Generator) -> CompiledSearch | None:
    """The compiled search when ``solver``'s solves can run as a series; None otherwise.

    That is: the compiled loop is there and the chain is plain (no continuous joint, whose
    angle would go through ``cos``/``sin`` between targets), one solution is asked for, no
    collision check, and the generator can be moved on (``PCG64``).
    """
    compiled = solver.compiled_search
    if compiled is None or not compiled.arrays.plain or solver.collisions is not None:
        return None
    if solver.settings.solutions != 1 or not hasattr(rng.bit_generator, "advance"):
        return None
    return compiled


def solve_leading(solver: IkSolver, compiled: CompiledSearch, targets: Sequence[IkTarget],
                  seed: FloatArray, rng: np.random.Generator) -> list[IkResult]:
    """The answers to the leading targets that the compiled series solves and FK confirms.

    Each target starts from the previous answer, the first from ``seed`` (full ``q``). The
    results are those :meth:`IkSolver.solve` gives for the same targets from the same
    generator; ``rng`` is left where those solves would leave it. The caller solves the next
    target (if any remain) with :meth:`IkSolver.solve`.
    """
    chain, arrays = solver.chain, compiled.arrays
    count = 0
    while count < len(targets) and solver.compiled_for(targets[count]):
        count += 1
    if not count:
        return []
    goals, rows, limits = _goals(solver, targets[:count])
    n = arrays.size
    out = np.empty((count, n))
    attempts, iterations, draws = (np.zeros(count, dtype=np.int64) for _ in range(3))
    theta = arrays.to_angles(chain.clamp(chain.to_chain(seed)))
    results: list[IkResult] = []
    while len(results) < count:
        done = len(results)
        size = _BUFFER + (_FIRST_RUN + _RUN * int(limits[done:].max())) * n
        state = rng.bit_generator.state
        unit = rng.random(size)
        solved, drawn, why = compiled.series(goals[done:], rows[done:], limits[done:], theta,
                                             unit, out[done:], attempts[done:],
                                             iterations[done:], draws[done:])
        confirmed = _confirm(solver, compiled, targets, done, done + solved, out, attempts,
                             iterations, seed if not results else results[-1].q, results)
        if confirmed < solved:  # back to the start of the target FK did not confirm
            drawn = int(draws[done + confirmed])
        rng.bit_generator.state = state
        rng.bit_generator.advance(drawn)  # type: ignore[attr-defined]
        if confirmed < solved or why != _REFILL or not solved:
            break
        theta = out[len(results) - 1]
    return results


def _goals(solver: IkSolver, targets: Sequence[IkTarget]) -> tuple[FloatArray, npt.NDArray[
        np.int64], npt.NDArray[np.int64]]:
    """Targets as ``[R | p]`` (m, 3, 4), rows per target (6 or 3), attempts allowed.

    A target beyond the reach sphere gets one attempt, as :meth:`IkSolver.out_of_reach`
    says; that test is made here for all at once, and again target by target only where the
    answer is within :data:`_NEAR_M` of changing.
    """
    count = len(targets)
    goals = np.zeros((count, 3, 4))
    rows = np.full(count, 3, dtype=np.int64)
    limits = np.full(count, solver.settings.max_attempts, dtype=np.int64)
    goals[:, :, 3] = [target.position_m for target in targets]
    posed = [k for k, target in enumerate(targets) if target.rotation is not None and
             target.axes]
    if posed:
        goals[posed, :, :3] = [targets[k].rotation for k in posed]
        rows[posed] = 6
    chain = solver.chain
    if chain.base_nq:
        return goals, rows, limits
    offset = goals[:, :, 3] - chain.reach.center_m
    beyond = np.sqrt((offset * offset).sum(axis=1)) - chain.reach.radius_m - \
        solver.settings.tolerance_m
    limits[beyond > _NEAR_M] = 1
    for k in np.flatnonzero(np.abs(beyond) <= _NEAR_M).tolist():
        limits[k] = 1 if solver.out_of_reach(targets[k]) else solver.settings.max_attempts
    return goals, rows, limits


def _confirm(solver: IkSolver, compiled: CompiledSearch, targets: Sequence[IkTarget],
             first: int, stop: int, out: FloatArray, attempts: npt.NDArray[np.int64],
             iterations: npt.NDArray[np.int64], seed: FloatArray,
             results: list[IkResult]) -> int:
    """Append results for targets ``first..stop-1`` that Pinocchio's FK confirms.

    In order, up to the first it does not; returns how many were appended. Each answer's
    full ``q`` is ``seed`` with the chain's entries replaced (the others never change along
    a series), made for the whole run at once.
    """
    full = solver.chain.to_full_rows(out[first:stop], seed)  # plain chain: q is the angles
    check = compiled.check
    for k in range(first, stop):
        errors = check(out[k], targets[k])
        if errors is None:
            return k - first
        results.append(IkResult(full[k - first], True, errors[0], errors[1],
                                int(iterations[k]), int(attempts[k]), 1))
    return stop - first
