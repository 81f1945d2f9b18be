r"""One IK attempt in Pinocchio's arithmetic: damped least-squares steps on a residual.

Levenberg-Marquardt on the residual's Jacobian (see
:mod:`~servicebot_cli.kinematics.residuals`). Each iteration solves

.. math:: \Delta q = J^T (J J^T + \lambda I)^{-1} e, \quad \lambda = w \|e\|^2 + \bar w

(or the equivalent :math:`(J^T J + \lambda I)^{-1} J^T e` when J has more rows than
columns) with eigenpy's Cholesky factorisation, caps the step, and projects ``q`` into the
joint limits (integrating on the configuration space when the chain has continuous joints).
:meth:`Descent.descend` is one cheap attempt, stopped when it stalls;
:meth:`Descent.settle` accepts only steps that lower the error, to settle a failed solve's
best try. The attempts and restarts around them are
:class:`~servicebot_cli.kinematics.inverse.IkSolver`'s. Pure.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from servicebot_cli.kinematics.chain import Chain
    from servicebot_cli.kinematics.residuals import Residual

FloatArray = npt.NDArray[np.float64]

_DAMPING = 1e-2  # w: damping per squared error
_DAMPING_FLOOR = 1e-9  # w-bar: keeps the system positive definite at singularities
_MAX_STEP = 2.0  # largest step norm [rad or m]
_STALL_RATIO = 0.8  # an attempt stalls when ||e||^2 fell less than this in two iterations


class Descent:
    """Damped least-squares descents for one chain, at fixed tolerances and iterations."""

    def __init__(self, chain: Chain, tolerance_m: float, tolerance_rad: float,
                 max_iterations: int) -> None:
        """Factorisations for every system size ``chain`` can give, and its integrator.

        An answer is within tolerance at ``tolerance_m`` [m] of position error and
        ``tolerance_rad`` [rad] of orientation error; an attempt takes at most
        ``max_iterations`` iterations.
        """
        import eigenpy
        import pinocchio as pin

        self.chain = chain
        self._tolerance_m, self._tolerance_rad = tolerance_m, tolerance_rad
        self._max_iterations = max_iterations
        sizes = range(1, 10 + chain.model.nv)
        self._factor = {n: eigenpy.LLT(np.eye(n)) for n in sizes}
        self._eye = {n: np.eye(n) for n in sizes}
        self._integrate = None if chain.vector_space else pin.integrate
        self._gate2 = 1.5 * (tolerance_m ** 2 + tolerance_rad ** 2)

    def descend(self, residual: Residual, q: FloatArray,
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
        for iteration in range(1, self._max_iterations + 1):
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

    def settle(self, residual: Residual, q: FloatArray) -> tuple[FloatArray, int, bool]:
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
        for iteration in range(1, self._max_iterations + 1):
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
        """Both of the residual's errors are within tolerance."""
        position, orientation = residual.errors()
        return position <= self._tolerance_m and (
            orientation is None or orientation <= self._tolerance_rad)
