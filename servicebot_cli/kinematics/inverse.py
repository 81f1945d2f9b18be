r"""Inverse kinematics: joint values that put a frame at a target.

Levenberg-Marquardt (damped least squares) on the frame Jacobian, with the error-dependent
damping of Sugihara (2011): large steps far away, Gauss-Newton close in (one attempt:
:class:`~servicebot_cli.kinematics.pin_descent.Descent`). Steps are capped, and joint limits
are enforced after every step by projection, so no iterate, and no result, ever leaves them;
continuous joints turn freely and wrap.

An answer is checked for collisions when the solver has a check (see
:mod:`~servicebot_cli.kinematics.collisions`); a colliding one does not count, and the search
goes on. Attempts at a full pose or a position on a chain of single-axis joints run in a
compiled loop (:mod:`~servicebot_cli.kinematics.lm_kernel`, when numba is installed), and
Pinocchio's forward kinematics check each answer it finds. An attempt that stops improving
ends early, and the next starts from a random
configuration within the limits (drawn from the caller's generator, so a fixed seed gives
the same answer). The first attempt starts from the seed; with a mobile base, the first
keeps the base still and the second lets it move. Of the converged solutions, the one
nearest the seed is returned. Pure: no clock, no global randomness.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.compiled_search import CompiledSearch
from servicebot_cli.kinematics.pin_descent import Descent
from servicebot_cli.kinematics.residuals import Residual, residual_for

if TYPE_CHECKING:
    from servicebot_cli.kinematics.chain import Chain
    from servicebot_cli.kinematics.collisions import CollisionCheck, Contact

FloatArray = npt.NDArray[np.float64]
Errors = tuple[float, float | None]
"""Position error [m] and orientation error [rad] (None: position only)."""


@dataclass(frozen=True)
class IkTarget:
    """Where the frame should go, in the root frame.

    Attributes:
        position_m: Target position [m], shape (3,).
        rotation: Target orientation, shape (3, 3); None for position only.
        axes: Orientation angles that matter, a subset of ``("roll", "pitch", "yaw")``;
            empty means position only.
    """

    position_m: FloatArray
    rotation: FloatArray | None = None
    axes: tuple[str, ...] = ()


@dataclass(frozen=True)
class IkSettings:
    """How hard and how precisely to search.

    Attributes:
        tolerance_m: Largest accepted position error [m].
        tolerance_rad: Largest accepted orientation error [rad].
        max_attempts: Attempts in all (the seed, then random restarts).
        max_iterations: Iterations per attempt.
        solutions: Converged solutions to compare before returning the nearest to the seed.
    """

    tolerance_m: float = 1e-6
    tolerance_rad: float = 1e-6
    max_attempts: int = 100
    max_iterations: int = 100
    solutions: int = 1


@dataclass(frozen=True)
class IkResult:
    """The answer, or the best try.

    Attributes:
        q: Full configuration; joints outside the chain keep the seed's values.
        success: Both errors within tolerance.
        position_error_m: Distance from the frame to the target [m].
        orientation_error_rad: Angle to the target orientation [rad] (for some axes: the
            norm of their angle differences); None for position only.
        iterations: Iterations over all attempts.
        attempts: Attempts made.
        solutions: Converged solutions found (the nearest to the seed was returned).
        contact: When the target was reached only with links in collision: the first such
            pair (``q`` is that configuration); None otherwise.
        stopped: The caller's ``stop`` ended the search before its attempts were made.
    """

    q: FloatArray = field(repr=False)
    success: bool
    position_error_m: float
    orientation_error_rad: float | None
    iterations: int
    attempts: int
    solutions: int
    contact: Contact | None = None
    stopped: bool = False


@dataclass
class _Tally:
    """What a solve's attempts found so far.

    The best try that did not converge (chain ``q``, squared error), converged answers free
    of collisions (``q``, errors), the first in collision (and the pair), iterations,
    attempts, and whether ``stop`` ended the search.
    """

    best_q: FloatArray
    best_err2: float = math.inf
    found: list[tuple[FloatArray, Errors]] = field(default_factory=list)
    blocked: tuple[FloatArray, Errors, Contact] | None = None
    iterations: int = 0
    attempts: int = 0
    stopped: bool = False


class IkSolver:
    """Solves IK for one chain; reuse it for many targets (batch mode warm-starts)."""

    def __init__(self, chain: Chain, settings: IkSettings | None = None,
                 collisions: CollisionCheck | None = None, *, compiled: bool = True,
                 on_compiled: Callable[[float], None] | None = None) -> None:
        """Prepare the solver for ``chain`` with ``settings`` (defaults otherwise).

        With ``collisions``, an answer whose links touch each other or the floor is not
        one: the search goes on from other restarts. Its model is the one ``chain`` was
        reduced from. With ``compiled`` (and numba installed), attempts at a full pose or a
        position run in the compiled loop, and Pinocchio checks each converged answer; the
        loop is readied (compiled the first time on a machine) by the first solve that needs
        it, and ``on_compiled`` hears how many seconds that took.
        """
        self.chain = chain
        self.collisions = collisions
        self.settings = settings or IkSettings()
        self._descent = Descent(chain, self.settings.tolerance_m, self.settings.tolerance_rad,
                                self.settings.max_iterations)
        self._compiled = CompiledSearch.build(chain, self.settings.tolerance_m,
                                              self.settings.tolerance_rad,
                                              self.settings.max_iterations,
                                              on_compiled) if compiled else None

    @property
    def compiled(self) -> bool:
        """Whether attempts at a full pose or a position run in the compiled loop."""
        return self._compiled is not None

    @property
    def compiled_search(self) -> CompiledSearch | None:
        """The compiled loop's search for this chain; None when attempts run in Pinocchio."""
        return self._compiled

    def compiled_for(self, target: IkTarget) -> bool:
        """Whether the compiled loop runs the attempts at ``target``.

        It does for full poses and positions; some orientation axes keep to Pinocchio.
        """
        return self._compiled is not None and (target.rotation is None or not target.axes
                                               or len(target.axes) == 3)

    def prepare(self) -> None:
        """Ready the compiled loop now, so that later solve times measure solving alone."""
        if self._compiled is not None:
            self._compiled.ready()

    def solve(self, target: IkTarget, seed: FloatArray, rng: np.random.Generator,
              stop: Callable[[], bool] | None = None) -> IkResult:
        """Joint values that put the chain's frame at ``target``.

        Args:
            target: The target, in the root frame.
            seed: Full configuration to start from (within limits); shape (full nq,).
            rng: Source of the random restarts.
            stop: Asked between attempts (after the first): True ends the search, which
                then returns its best try (a deadline: see ``IkProblem.timeout_s``).
        """
        chain = self.chain
        residual = None if self.compiled_for(target) else residual_for(
            chain, target.position_m, target.rotation, target.axes)
        start = chain.clamp(chain.to_chain(seed))  # a fresh array: results stay in limits
        tally = _Tally(start)
        self._search(tally, residual, start, target, seed, rng, stop)
        if not tally.found and tally.blocked is None:  # settle the best try into its minimum
            failed = self._settle_best(tally, residual, target, seed)
            if failed is not None:
                return failed
        return self._answer(tally, start, seed)

    def _search(self, tally: _Tally, residual: Residual | None, start: FloatArray,
                target: IkTarget, seed: FloatArray, rng: np.random.Generator,
                stop: Callable[[], bool] | None) -> None:
        """Attempts into ``tally`` until enough solutions, the last attempt, or ``stop``."""
        settings = self.settings
        # beyond the reach sphere no restart can help: one attempt gives the best try
        limit = 1 if self.out_of_reach(target) else settings.max_attempts
        while tally.attempts < limit and len(tally.found) < settings.solutions:
            if tally.attempts and stop is not None and stop():
                tally.stopped = True
                break
            q, err2, made, used, errors = self._attempts(residual, start, tally.attempts,
                                                         limit, target, rng)
            tally.attempts, tally.iterations = tally.attempts + made, tally.iterations + used
            if errors is not None:
                contact = self._contact(q, seed)
                if contact is None:
                    tally.found.append((q, errors))
                elif tally.blocked is None:
                    tally.blocked = (q, errors, contact)
            elif err2 < tally.best_err2:
                tally.best_q, tally.best_err2 = q, err2

    def _settle_best(self, tally: _Tally, residual: Residual | None, target: IkTarget,
                     seed: FloatArray) -> IkResult | None:
        """Settle the best try into its local minimum; the failed result, or None.

        None: it converged there after all (a slow descent cut short as a stall), free.
        """
        chain = self.chain
        residual = residual or residual_for(chain, target.position_m, target.rotation,
                                            target.axes)
        best_q, used, settled = self._descent.settle(residual, tally.best_q.copy())
        tally.iterations += used
        if residual.last_q is not best_q:
            residual.reset(best_q)
            residual.evaluate(best_q)
        errors = residual.errors()
        contact = None
        if settled:
            contact = self._contact(best_q, seed)
            if contact is None:
                tally.found.append((best_q, errors))
                return None
        return IkResult(chain.to_full(best_q, seed), False, *errors, tally.iterations,
                        tally.attempts, 0, contact, tally.stopped)

    def _answer(self, tally: _Tally, start: FloatArray, seed: FloatArray) -> IkResult:
        """The answer nearest ``start`` of those found; else the best try, in collision."""
        found, contact = tally.found, None
        if found:
            best_q, (position_error, orientation_error) = found[0] if len(found) == 1 else min(
                found, key=lambda item: self._distance(start, item[0]))
        elif tally.blocked is not None:  # reached, but only through a collision: the best try
            best_q, (position_error, orientation_error), contact = tally.blocked
        return IkResult(self.chain.to_full(best_q, seed), bool(found), position_error,
                        orientation_error, tally.iterations, tally.attempts, len(found),
                        contact, tally.stopped and not found)

    def _attempts(self, residual: Residual | None, start: FloatArray, made: int, limit: int,
                  target: IkTarget, rng: np.random.Generator
                  ) -> tuple[FloatArray, float, int, int, Errors | None]:
        """The next attempts after ``made``: a run in the compiled loop, or one in Pinocchio.

        The compiled loop runs them when there is no ``residual``; an answer it finds counts
        only once Pinocchio's forward kinematics agree.

        Returns:
            The attempt's best ``q``, its squared error, attempts and iterations used, and
            the answer's errors when it converged (None otherwise).
        """
        chain = self.chain
        if residual is None:
            compiled = self._compiled
            assert compiled is not None  # no residual: the compiled loop does the attempts
            run = compiled.run(target, start if made == 0 else None, rng, limit - made)
            errors = compiled.check(run.q, target) if run.converged else None
            return run.q, run.err2, run.attempts, run.iterations, errors
        hold_base = chain.base_nq > 0 and made == 0
        q0 = start if made < (2 if chain.base_nq else 1) else chain.random_q(
            rng, target.position_m)
        q, err2, used, converged = self._descent.descend(residual, q0.copy(), hold_base)
        # the residual still holds this q's state (and free angles)
        return q, err2, 1, used, residual.errors() if converged else None

    def out_of_reach(self, target: IkTarget) -> bool:
        """True when ``target`` lies beyond the chain's reach sphere (no base to move)."""
        if self.chain.base_nq:
            return False
        return self.chain.reach.beyond_m(target.position_m) > self.settings.tolerance_m

    def _contact(self, q: FloatArray, seed: FloatArray) -> Contact | None:
        """The collision at chain ``q`` (other joints as in ``seed``); None: free, or unchecked."""
        if self.collisions is None:
            return None
        return self.collisions.contact(self.chain.to_full(q, seed))

    def _distance(self, start: FloatArray, q: FloatArray) -> float:
        """How far ``q`` is from ``start`` (continuous joints the short way round)."""
        import pinocchio as pin

        return float(np.linalg.norm(pin.difference(self.chain.model, start, q)))
