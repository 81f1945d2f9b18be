"""IK attempts run by the compiled loop, and Pinocchio's check of every answer it finds.

:class:`CompiledSearch` runs attempts (the seed, then random restarts) in
:func:`~servicebot_cli.kinematics.lm_kernel.search` and hands back the first converged
answer, or the best try, as the chain's ``q``. :meth:`CompiledSearch.check` measures an
answer with Pinocchio's forward kinematics: the solver counts it only when those errors are
within the tolerances. Built only when numba can be imported and the chain is a plain serial
chain of revolute and prismatic joints
(:func:`~servicebot_cli.kinematics.chain_arrays.chain_arrays`); otherwise the solver keeps
to its Pinocchio loop. Pure.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.numba_start import without_blas_probe

if TYPE_CHECKING:
    from servicebot_cli.kinematics.chain import Chain
    from servicebot_cli.kinematics.chain_arrays import ChainArrays
    from servicebot_cli.kinematics.inverse import IkTarget

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

_FIRST_RUN = 8  # random restarts after the seed in the first run
_RUN = 16  # restarts in each later run
_NO_SEED = np.empty(0)


@dataclass(frozen=True)
class Attempts:
    """A run of attempts.

    Attributes:
        q: The chain's ``q``: the converged answer, or the run's best try.
        converged: The last attempt met the tolerances (by the loop's own arithmetic).
        err2: Its squared error (mixed [m^2] and [rad^2]).
        attempts: Attempts made.
        iterations: Iterations over those attempts.
    """

    q: FloatArray
    converged: bool
    err2: float
    attempts: int
    iterations: int


class CompiledSearch:
    """Runs of attempts for one chain, with fixed tolerances and iterations per attempt."""

    def __init__(self, chain: Chain, arrays: ChainArrays, tolerance_m: float,
                 tolerance_rad: float, max_iterations: int,
                 on_ready: Callable[[float], None] | None = None) -> None:
        """Prepare the search; the loop itself is readied by the first run (see :meth:`ready`).

        ``on_ready`` hears how many seconds that took, when the loop was compiled (not
        loaded from numba's cache).
        """
        import pinocchio as pin

        from servicebot_cli.kinematics import lm_kernel, lm_series

        self._search = lm_kernel.search
        self._series = lm_series.solve_series
        self._pin = pin
        self._chain = chain
        self._arrays = arrays
        self._tolerances = np.array([tolerance_m, tolerance_rad])
        self._max_iterations = max_iterations
        self._target = np.zeros((3, 4))
        self._out = np.empty(arrays.size)
        self._on_ready = on_ready
        self.ready_s: float | None = None
        """Seconds the loops took to be ready (to compile, the first time on a machine)."""
        self._series_ready = self._search_ready = False

    @property
    def arrays(self) -> ChainArrays:
        """The chain, flat."""
        return self._arrays

    def ready(self, *, series: bool = False) -> float:
        """Compile the loop, or load it from numba's cache, unless done; the seconds it took.

        A call with no attempt, so that solve times after it measure solving. With
        ``series``, the loop over a series of targets (:meth:`series`) is readied instead
        (it holds its own copy of the attempts' loop).
        """
        if (self._series_ready if series else self._search_ready):
            return self.ready_s or 0.0
        loop = self._series if series else self._search
        missed = _cache_misses(loop)
        begin = time.perf_counter()
        with without_blas_probe():
            self._ready(series)
        took_s = time.perf_counter() - begin
        self.ready_s = (self.ready_s or 0.0) + took_s
        # a load from numba's cache on a busy machine may take as long as a compile: only a
        # miss of the cache (or no cache) is a compile
        if self._on_ready is not None and _cache_misses(loop) > missed:
            self._on_ready(took_s)
        return self.ready_s

    def _ready(self, series: bool) -> None:
        if series:
            none, empty = np.empty(0, dtype=np.int64), np.empty((0, self._arrays.size))
            self._run_series(np.empty((0, 3, 4)), none, none, self._out, _NO_SEED, empty,
                             none, none, none)
            self._series_ready = True
        else:
            arrays = self._arrays
            self._search(arrays.frames, arrays.axes, arrays.kinds, arrays.limits, self._target,
                         6, self._tolerances, 1, _NO_SEED, np.empty((0, arrays.size)),
                         self._out)
            self._search_ready = True

    def series(self, goals: FloatArray, rows: IntArray, attempt_limits: IntArray,
               start: FloatArray, unit: FloatArray, out: FloatArray, attempts: IntArray,
               iterations: IntArray, draws: IntArray) -> tuple[int, int, int]:
        """Targets solved in one compiled call, each from the last answer.

        See :func:`~servicebot_cli.kinematics.lm_series.solve_series` (same arguments).
        """
        self.ready(series=True)
        return self._run_series(goals, rows, attempt_limits, start, unit, out, attempts,
                                iterations, draws)

    def _run_series(self, goals: FloatArray, rows: IntArray, attempt_limits: IntArray,
                    start: FloatArray, unit: FloatArray, out: FloatArray, attempts: IntArray,
                    iterations: IntArray, draws: IntArray) -> tuple[int, int, int]:
        arrays = self._arrays
        done, drawn, why = self._series(
            arrays.frames, arrays.axes, arrays.kinds, arrays.limits, goals, rows,
            attempt_limits, self._tolerances, self._max_iterations, start, unit, 0, out,
            attempts, iterations, draws)
        return int(done), int(drawn), int(why)

    @classmethod
    def build(cls, chain: Chain, tolerance_m: float, tolerance_rad: float,
              max_iterations: int,
              on_ready: Callable[[float], None] | None = None) -> CompiledSearch | None:
        """The search for ``chain``; None without numba, or for a chain the loop cannot do."""
        try:
            from servicebot_cli.kinematics.chain_arrays import chain_arrays
        except ModuleNotFoundError as exc:
            if exc.name != "numba":
                raise
            return None
        arrays = chain_arrays(chain)
        if arrays is None:
            return None
        return cls(chain, arrays, tolerance_m, tolerance_rad, max_iterations, on_ready)

    def run(self, target: IkTarget, start: FloatArray | None, rng: np.random.Generator,
            most: int) -> Attempts:
        """Up to ``most`` attempts at a full pose or a position (``target.rotation`` None).

        The first from ``start`` (a chain ``q``) if given, the others from random
        configurations within the limits; stops at the first attempt that converges.
        """
        self.ready()
        arrays, goal = self._arrays, self._target
        goal[:, 3] = target.position_m
        rows = 3
        if target.rotation is not None and target.axes:
            goal[:, :3], rows = target.rotation, 6
        seed = _NO_SEED if start is None else arrays.to_angles(start)
        randoms = min(most, _RUN) if start is None else min(most - 1, _FIRST_RUN)
        unit = rng.random((randoms, arrays.size))
        made, converged, iterations, err2 = self._search(
            arrays.frames, arrays.axes, arrays.kinds, arrays.limits, goal, rows,
            self._tolerances, self._max_iterations, seed, unit, self._out)
        return Attempts(arrays.to_q(self._out, self._chain.model.nq), bool(converged),
                        float(err2), int(made), int(iterations))

    def check(self, q: FloatArray, target: IkTarget) -> tuple[float, float | None] | None:
        """Errors of chain ``q`` by Pinocchio's forward kinematics; None: not within tolerance.

        Returns:
            Position error [m] and orientation error [rad] (None for position only).
        """
        pin, chain = self._pin, self._chain
        pin.forwardKinematics(chain.model, chain.data, q)
        pose = pin.updateFramePlacement(chain.model, chain.data, chain.frame)
        offset = target.position_m - pose.translation
        position_m = math.sqrt(offset.dot(offset))
        if position_m > self._tolerances[0]:
            return None
        if target.rotation is None or not target.axes:
            return position_m, None
        angle = pin.log3(pose.rotation.T.dot(target.rotation))
        angle_rad = math.sqrt(angle.dot(angle))
        return (position_m, angle_rad) if angle_rad <= self._tolerances[1] else None


def _cache_misses(loop: object) -> int:
    """How many times numba compiled ``loop`` (a dispatcher) for want of a cached copy."""
    misses = getattr(getattr(loop, "stats", None), "cache_misses", None)
    return 0 if misses is None else int(sum(misses.values()))
