r"""Planar motion along exact arcs, and the same motion stopped by obstacles.

A body moving at constant forward speed :math:`v` and yaw rate :math:`\omega` for
:math:`\Delta t` follows an arc; in the body frame at the start of the step it moves

.. math:: \Delta x = \frac{v}{\omega}\sin(\omega\Delta t), \quad
          \Delta y = \frac{v}{\omega}(1 - \cos(\omega\Delta t)), \quad
          \Delta\theta = \omega\Delta t

(the straight line :math:`\Delta x = v\Delta t` when :math:`\omega = 0`). Steps are composed
for all ticks at once with cumulative sums, so a whole run is a handful of numpy calls.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_STRAIGHT = 1e-9  # |omega dt| below this is a straight step (sin x / x = 1 to 1e-18)


@dataclass(frozen=True)
class Path2D:
    """Poses at tick boundaries: ``x_m[k], y_m[k], yaw_rad[k]`` at time ``k dt``, k = 0..n.

    ``linear_m_s`` and ``angular_rad_s`` (length n) are the twists actually followed.
    """

    dt_s: float
    x_m: FloatArray
    y_m: FloatArray
    yaw_rad: FloatArray
    linear_m_s: FloatArray
    angular_rad_s: FloatArray


@dataclass(frozen=True)
class Contact:
    """A link touched an obstacle: the base's step starting at ``time_s`` was refused."""

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


def integrate(start: tuple[float, float, float], linear_m_s: FloatArray,
              angular_rad_s: FloatArray, dt_s: float) -> Path2D:
    """Compose arc steps from ``start = (x [m], y [m], yaw [rad])``, all ticks at once."""
    dx, dy, dyaw = arc_step(linear_m_s, angular_rad_s, dt_s)
    yaw = start[2] + np.concatenate(([0.0], np.cumsum(dyaw)))
    cos, sin = np.cos(yaw[:-1]), np.sin(yaw[:-1])
    x = start[0] + np.concatenate(([0.0], np.cumsum(cos * dx - sin * dy)))
    y = start[1] + np.concatenate(([0.0], np.cumsum(sin * dx + cos * dy)))
    return Path2D(dt_s, x, y, yaw, np.asarray(linear_m_s, float), np.asarray(angular_rad_s, float))


Collides = Callable[[IntArray, FloatArray, FloatArray, FloatArray], tuple[IntArray, IntArray]]
"""Given ticks and the base poses at them: per pose, the obstacle touched and the link touching
it (indices into the names), -1 where free. The tick says where the arm is."""


def integrate_blocked(start: tuple[float, float, float], linear_m_s: FloatArray,
                      angular_rad_s: FloatArray, dt_s: float, collides: Collides,
                      names: list[str], links: Sequence[str]) -> tuple[Path2D, list[Contact]]:
    """Like :func:`integrate`, but steps into obstacles are refused.

    A step that would put any link into an obstacle leaves the base where it was (its
    wheels still turn) and logs a contact naming the obstacle and the link.

    While blocked, each later step is tried from the resting pose; the first one that is free
    (turning or backing away) resumes the motion.
    """
    n = len(linear_m_s)
    lin, ang = np.array(linear_m_s, float), np.array(angular_rad_s, float)
    x, y, yaw = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    x[0], y[0], yaw[0] = start
    contacts: list[Contact] = []
    k = 0
    while k < n:
        path = integrate((x[k], y[k], yaw[k]), lin[k:], ang[k:], dt_s)
        ticks = np.arange(k + 1, n + 1)
        hit, link = collides(ticks, path.x_m[1:], path.y_m[1:], path.yaw_rad[1:])
        blocked = np.flatnonzero(hit >= 0)
        stop = n if not len(blocked) else k + int(blocked[0])
        x[k + 1:stop + 1] = path.x_m[1:stop - k + 1]
        y[k + 1:stop + 1] = path.y_m[1:stop - k + 1]
        yaw[k + 1:stop + 1] = path.yaw_rad[1:stop - k + 1]
        if stop == n:
            break
        contacts.append(Contact(stop * dt_s, names[int(hit[blocked[0]])],
                                links[int(link[blocked[0]])],
                                float(x[stop]), float(y[stop]), float(yaw[stop])))
        k = _wait_until_free(stop, x, y, yaw, lin, ang, dt_s, collides)
    moved_lin, moved_ang = _followed_twist(x, y, yaw, lin, ang)
    return Path2D(dt_s, x, y, yaw, moved_lin, moved_ang), contacts


def _wait_until_free(k: int, x: FloatArray, y: FloatArray, yaw: FloatArray, lin: FloatArray,
                     ang: FloatArray, dt_s: float, collides: Collides) -> int:
    """Hold the pose at tick ``k`` until a step from it is free; return that step's tick."""
    n = len(lin)
    dx, dy, dyaw = arc_step(lin[k:], ang[k:], dt_s)
    c, s = np.cos(yaw[k]), np.sin(yaw[k])
    hit, _ = collides(np.arange(k + 1, n + 1), x[k] + c * dx - s * dy, y[k] + s * dx + c * dy,
                      yaw[k] + dyaw)
    free = hit < 0
    moving = (lin[k:] != 0) | (ang[k:] != 0)
    ok = np.flatnonzero(free & moving)
    resume = n if not len(ok) else k + int(ok[0])
    x[k + 1:resume + 1], y[k + 1:resume + 1], yaw[k + 1:resume + 1] = x[k], y[k], yaw[k]
    return resume


def _followed_twist(x: FloatArray, y: FloatArray, yaw: FloatArray, lin: FloatArray,
                    ang: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The commanded twist where the base moved, zero where it was held."""
    held = (np.diff(x) == 0) & (np.diff(y) == 0) & (np.diff(yaw) == 0)
    return np.where(held, 0.0, lin), np.where(held, 0.0, ang)


def pose_at(path: Path2D, times_s: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Poses at arbitrary times, exact along each tick's arc (clamped to the run)."""
    n = len(path.linear_m_s)
    k = np.clip(np.floor(times_s / path.dt_s + 1e-9).astype(np.int64), 0, n - 1)
    tau = np.clip(times_s - k * path.dt_s, 0.0, path.dt_s)
    dx, dy, dyaw = arc_step(path.linear_m_s[k], path.angular_rad_s[k], tau)
    c, s = np.cos(path.yaw_rad[k]), np.sin(path.yaw_rad[k])
    return path.x_m[k] + c * dx - s * dy, path.y_m[k] + s * dx + c * dy, path.yaw_rad[k] + dyaw
