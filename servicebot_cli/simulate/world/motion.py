r"""Planar motion along exact arcs.

A body moving at constant forward speed :math:`v` and yaw rate :math:`\omega` for
:math:`\Delta t` follows an arc; in the body frame at the start of the step it moves

.. math:: \Delta x = \frac{v}{\omega}\sin(\omega\Delta t), \quad
          \Delta y = \frac{v}{\omega}(1 - \cos(\omega\Delta t)), \quad
          \Delta\theta = \omega\Delta t

(the straight line :math:`\Delta x = v\Delta t` when :math:`\omega = 0`). Steps are composed
for many ticks at once with cumulative sums, so a stretch of a run is a handful of numpy calls.
A run is integrated a stretch at a time (:class:`Integrator`; :mod:`.blocking` stops it at
obstacles): the sums run on from one stretch to the next, so the poses have the same bits as
one sum over the whole run.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_STRAIGHT = 1e-9  # |omega dt| below this is a straight step (sin x / x = 1 to 1e-18)


@dataclass(frozen=True)
class Path2D:
    """Poses at tick boundaries: ``x_m[i], y_m[i], yaw_rad[i]`` at time ``(first_tick + i) dt``.

    ``linear_m_s`` and ``angular_rad_s`` (length n, for n + 1 poses) are the twists actually
    followed. A whole run starts at tick 0; a stretch of it at ``first_tick``.
    """

    dt_s: float
    x_m: FloatArray
    y_m: FloatArray
    yaw_rad: FloatArray
    linear_m_s: FloatArray
    angular_rad_s: FloatArray
    first_tick: int = 0

    def tick_index(self, times_s: FloatArray, *, boundaries: bool = False) -> IntArray:
        """Index into this stretch of the tick holding each time (clamped to the stretch).

        With ``boundaries``, of the tick boundary at or before each time.
        """
        last = len(self.linear_m_s) - (0 if boundaries else 1)
        k = np.floor(np.asarray(times_s) / self.dt_s + 1e-9).astype(np.int64) - self.first_tick
        return np.clip(k, 0, last)


@dataclass(frozen=True)
class Contact:
    """A link touched an obstacle: a step of the base or the arm was refused.

    The step began at ``time_s``, with the base at ``x_m, y_m, yaw_rad``.
    """

    time_s: float
    obstacle: str
    link: str
    x_m: float
    y_m: float
    yaw_rad: float


def arc_step(linear_m_s: FloatArray, angular_rad_s: FloatArray,
             dt_s: FloatArray | float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Body-frame displacement ``(dx [m], dy [m], dyaw [rad])`` of arcs of duration ``dt_s``."""
    dyaw = angular_rad_s * dt_s
    straight = np.abs(dyaw) < _STRAIGHT
    safe = np.where(straight, 1.0, dyaw)
    # v/omega * sin(omega dt) written as v dt * sin(dyaw)/dyaw keeps it finite and exact.
    dx = np.where(straight, linear_m_s * dt_s, linear_m_s * dt_s * np.sin(safe) / safe)
    dy = np.where(straight, 0.5 * linear_m_s * dt_s * dyaw,
                  linear_m_s * dt_s * (1.0 - np.cos(safe)) / safe)
    return dx, dy, dyaw


class Integrator:
    """Arc steps composed from an origin, a stretch of ticks at a time.

    The three cumulative sums (x, y, yaw) run on from one stretch to the next, so the poses
    have the same bits as one cumulative sum from the origin. A sum starts at -0.0: the one
    float z with ``z + v == v`` for every v.
    """

    def __init__(self, origin: tuple[float, float, float]) -> None:
        self.restart(origin)

    def restart(self, origin: tuple[float, float, float]) -> None:
        """Compose the next steps from ``origin`` (x [m], y [m], yaw [rad])."""
        self.origin = origin
        self.sums = (-0.0, -0.0, -0.0)

    def trial(self, linear_m_s: FloatArray, angular_rad_s: FloatArray,
              dt_s: float) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """Poses after each step, shape (n,) each, and the running sums, shape (n + 1, 3).

        The sums are those before the first step and after each; nothing is kept until
        :meth:`keep`.
        """
        dx, dy, dyaw = arc_step(linear_m_s, angular_rad_s, dt_s)
        sum_yaw = np.cumsum(np.concatenate(([self.sums[2]], dyaw)))
        yaw = self.origin[2] + sum_yaw
        cos, sin = np.cos(yaw[:-1]), np.sin(yaw[:-1])
        sum_x = np.cumsum(np.concatenate(([self.sums[0]], cos * dx - sin * dy)))
        sum_y = np.cumsum(np.concatenate(([self.sums[1]], sin * dx + cos * dy)))
        return (self.origin[0] + sum_x[1:], self.origin[1] + sum_y[1:], yaw[1:],
                np.column_stack((sum_x, sum_y, sum_yaw)))

    def keep(self, sums: FloatArray, steps: int) -> None:
        """Keep the first ``steps`` steps of a trial whose sums are ``sums``."""
        self.sums = (float(sums[steps, 0]), float(sums[steps, 1]), float(sums[steps, 2]))


def pose_at(path: Path2D, times_s: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Poses at arbitrary times, exact along each tick's arc (clamped to the path)."""
    k = path.tick_index(times_s)
    tau = np.clip(times_s - (k + path.first_tick) * path.dt_s, 0.0, path.dt_s)
    dx, dy, dyaw = arc_step(path.linear_m_s[k], path.angular_rad_s[k], tau)
    c, s = np.cos(path.yaw_rad[k]), np.sin(path.yaw_rad[k])
    return path.x_m[k] + c * dx - s * dy, path.y_m[k] + s * dx + c * dy, path.yaw_rad[k] + dyaw
