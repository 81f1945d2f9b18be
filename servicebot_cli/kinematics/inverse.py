r"""Inverse kinematics: joint values that put a frame at a target.

Levenberg-Marquardt (damped least squares) on the frame Jacobian. Each iteration solves

.. math:: \Delta q = J^T (J J^T + \lambda I)^{-1} e, \quad \lambda = w \|e\|^2 + \bar w

(or the equivalent :math:`(J^T J + \lambda I)^{-1} J^T e` when J has more rows than
columns), the error-dependent damping of Sugihara (2011): large steps far away, Gauss-Newton
close in. Steps are capped, and joint limits are enforced after every step by projection,
so no iterate, and no result, ever leaves them; continuous joints turn freely and wrap.

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
from servicebot_cli.kinematics.residuals import Residual, residual_for

if TYPE_CHECKING:
    from servicebot_cli.kinematics.chain import Chain
    from servicebot_cli.kinematics.collisions import CollisionCheck, Contact

FloatArray = npt.NDArray[np.float64]
Errors = tuple[float, float | None]
"""Position error [m] and orientation error [rad] (None: position only)."""

_DAMPING = 1e-2  # w: damping per squared error
_DAMPING_FLOOR = 1e-9  # w-bar: keeps the system positive definite at singularities
_MAX_STEP = 2.0  # largest step norm [rad or m]
_STALL_RATIO = 0.8  # an attempt stalls when ||e||^2 fell less than this in two iterations


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
        import eigenpy
        import pinocchio as pin

        self.chain = chain
        self.collisions = collisions
        self.settings = settings or IkSettings()
        sizes = range(1, 10 + chain.model.nv)
        self._factor = {n: eigenpy.LLT(np.eye(n)) for n in sizes}
        self._eye = {n: np.eye(n) for n in sizes}
        self._integrate = None if chain.vector_space else pin.integrate
        self._gate2 = 1.5 * (self.settings.tolerance_m ** 2 + self.settings.tolerance_rad ** 2)
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
        chain, settings = self.chain, self.settings
        fast = self.compiled_for(target)
        residual = None if fast else residual_for(chain, target.position_m, target.rotation,
                                                  target.axes)
        start = chain.clamp(chain.to_chain(seed))  # a fresh array: results stay in limits
        found: list[tuple[FloatArray, Errors]] = []  # q, its errors
        blocked: tuple[FloatArray, Errors, Contact] | None = None
        best_q, best_err2 = start, math.inf
        iterations = attempts = 0
        # beyond the reach sphere no restart can help: one attempt gives the best try
        limit = 1 if self.out_of_reach(target) else settings.max_attempts
        stopped = False
        while attempts < limit and len(found) < settings.solutions:
            if attempts and stop is not None and stop():
                stopped = True
                break
            q, err2, made, used, errors = self._attempts(residual, start, attempts, limit,
                                                         target, rng)
            attempts, iterations = attempts + made, iterations + used
            if errors is not None:
                contact = self._contact(q, seed)
                if contact is None:
                    found.append((q, errors))
                elif blocked is None:
                    blocked = (q, errors, contact)
            elif err2 < best_err2:
                best_q, best_err2 = q, err2
        contact = None
        if not found and blocked is None:  # settle the best try into its local minimum
            residual = residual or residual_for(chain, target.position_m, target.rotation,
                                                target.axes)
            best_q, used, settled = self._settle(residual, best_q.copy())
            iterations += used
            if residual.last_q is not best_q:
                residual.reset(best_q)
                residual.evaluate(best_q)
            errors = residual.errors()
            if settled:  # a slow descent, cut short as a stall, that does converge
                contact = self._contact(best_q, seed)
                if contact is None:
                    found.append((best_q, errors))
            if not found:
                return IkResult(chain.to_full(best_q, seed), False, *errors, iterations,
                                attempts, 0, contact, stopped)
        if found:
            best_q, (position_error, orientation_error) = found[0] if len(found) == 1 else min(
                found, key=lambda item: self._distance(start, item[0]))
        elif blocked is not None:  # reached, but only through a collision: the best try
            best_q, (position_error, orientation_error), contact = blocked
        return IkResult(chain.to_full(best_q, seed), bool(found), position_error,
                        orientation_error, iterations, attempts, len(found), contact,
                        stopped and not found)

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
        q, err2, used, converged = self._descend(residual, q0.copy(), hold_base)
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

    def _descend(self, residual: Residual, q: FloatArray,
                 hold_base: bool) -> tuple[FloatArray, float, int, bool]:
        """One attempt: damped least-squares steps from ``q`` until converged or stalled.

        It stalls when the squared error fell by less than :data:`_STALL_RATIO` in two
        iterations. Steps are not checked for progress: that is what makes an attempt cheap.

        Returns:
            The best ``q`` of the attempt, its squared error, iterations used, and success.
        """
        evaluate, within = residual.evaluate, self._within
        step_of, move = self._step, self._move
        residual.reset(q)
        gate2 = self._gate2
        earlier = previous = math.inf
        best_q, best_err2 = q, math.inf
        for iteration in range(1, self.settings.max_iterations + 1):
            error, jacobian = evaluate(q)
            if hold_base:
                jacobian[:, :3] = 0.0  # planar base: x, y, yaw stay where they are
            err2 = error.dot(error)
            if err2 < best_err2:
                best_q, best_err2 = q, err2
                if err2 <= gate2 and within(residual):
                    return q, err2, iteration, True
            if err2 > _STALL_RATIO * earlier:
                break
            earlier, previous = previous, err2
            q = move(q, step_of(jacobian, error, _DAMPING * err2 + _DAMPING_FLOOR), residual)
        return best_q, float(best_err2), iteration, False

    def _settle(self, residual: Residual, q: FloatArray) -> tuple[FloatArray, int, bool]:
        """Levenberg-Marquardt with step acceptance from ``q`` into the nearest minimum.

        Only for solves that failed: a step that does not lower the error is undone and the
        damping raised, so the error never grows and the best residual is a true one.

        Returns:
            The settled ``q``, iterations used, and whether it met the tolerance after all.
        """
        residual.reset(q)
        error, jacobian = residual.evaluate(q)
        err2 = error.dot(error)
        damping = _DAMPING * err2 + _DAMPING_FLOOR
        for iteration in range(1, self.settings.max_iterations + 1):
            step = self._step(jacobian, error, damping)
            candidate = self._move(q, step, residual)
            new_error, new_jacobian = residual.evaluate(candidate)
            new2 = new_error.dot(new_error)
            if new2 < err2:
                if new2 <= self._gate2 and self._within(residual):
                    return candidate, iteration, True
                done = err2 - new2 <= 1e-12 * err2
                q, error, jacobian, err2 = candidate, new_error, new_jacobian, new2
                damping = max(damping / 3, _DAMPING_FLOOR)
                if done:
                    break
            else:
                extra = residual.extra
                if extra:
                    residual.shift(-step[-extra:])
                damping *= 4
                if damping > 1e9:
                    break
        return q, iteration, False

    def _step(self, jacobian: FloatArray, error: FloatArray, damping: float) -> FloatArray:
        """The damped least-squares step, capped at :data:`_MAX_STEP`."""
        rows, cols = jacobian.shape
        step: FloatArray
        if rows <= cols:
            factor = self._factor[rows]
            factor.compute(np.dot(jacobian, jacobian.T) + damping * self._eye[rows])
            step = jacobian.T.dot(factor.solve(error))
        else:
            factor = self._factor[cols]
            factor.compute(np.dot(jacobian.T, jacobian) + damping * self._eye[cols])
            step = factor.solve(jacobian.T.dot(error)).reshape(cols)  # (1, 1) for one joint
        size2 = step.dot(step)
        if size2 > _MAX_STEP * _MAX_STEP:
            step *= _MAX_STEP / math.sqrt(size2)
        return step

    def _move(self, q: FloatArray, step: FloatArray, residual: Residual) -> FloatArray:
        """``q`` moved by the joints' part of ``step``, projected into the limits.

        The rest of ``step`` moves the residual's own unknowns (free angles).
        """
        extra = residual.extra
        if extra:
            residual.shift(step[-extra:])
            step = step[:-extra]
        q = q + step if self._integrate is None else self._integrate(self.chain.model, q, step)
        np.maximum(q, self.chain.lower, out=q)
        np.minimum(q, self.chain.upper, out=q)
        return q

    def _within(self, residual: Residual) -> bool:
        position, orientation = residual.errors()
        return position <= self.settings.tolerance_m and (
            orientation is None or orientation <= self.settings.tolerance_rad)
