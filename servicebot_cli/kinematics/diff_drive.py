r"""Differential-drive kinematics: body twist to wheel speeds and back, and their limits.

With wheel radius :math:`r` and track :math:`b` (left-to-right wheel distance):

.. math::
    \omega_l = (v - \omega b / 2) / r, \quad \omega_r = (v + \omega b / 2) / r

    v = r (\omega_l + \omega_r) / 2, \quad \omega = r (\omega_r - \omega_l) / b

Pure functions of floats; shared by ``simulate`` and ``drive`` so both obey one law.
"""

from __future__ import annotations

import math


def wheel_speeds(
    linear_m_s: float, angular_rad_s: float, *, wheel_radius_m: float, track_m: float
) -> tuple[float, float]:
    """Left and right wheel speeds [rad/s] for a body twist (forward [m/s], yaw rate [rad/s])."""
    half = angular_rad_s * track_m / 2.0
    return (linear_m_s - half) / wheel_radius_m, (linear_m_s + half) / wheel_radius_m


def body_twist(
    left_rad_s: float, right_rad_s: float, *, wheel_radius_m: float, track_m: float
) -> tuple[float, float]:
    """Body twist ``(forward [m/s], yaw rate [rad/s])`` from left and right wheel speeds."""
    linear = wheel_radius_m * (left_rad_s + right_rad_s) / 2.0
    angular = wheel_radius_m * (right_rad_s - left_rad_s) / track_m
    return linear, angular


def rolled_twist(left_rad_s: float, right_rad_s: float, *, left_radius_m: float,
                 right_radius_m: float, track_m: float) -> tuple[float, float]:
    """:func:`body_twist` of wheels that roll on radii of their own (a base that curves).

    With equal radii, :func:`body_twist`'s arithmetic exactly.
    """
    if left_radius_m == right_radius_m:
        return body_twist(left_rad_s, right_rad_s, wheel_radius_m=left_radius_m,
                          track_m=track_m)
    left, right = left_rad_s * left_radius_m, right_rad_s * right_radius_m
    return (left + right) / 2.0, (right - left) / track_m


def saturate_keep_curvature(
    left_rad_s: float, right_rad_s: float, max_rad_s: float
) -> tuple[float, float]:
    """Scale both wheels by one factor so neither exceeds ``max_rad_s``.

    The ratio of the two speeds, hence the path's curvature, is unchanged.
    """
    peak = max(abs(left_rad_s), abs(right_rad_s))
    if peak <= max_rad_s or peak == 0.0:
        return left_rad_s, right_rad_s
    scale = max_rad_s / peak
    return left_rad_s * scale, right_rad_s * scale


def saturate_per_wheel(
    left_rad_s: float, right_rad_s: float, max_rad_s: float
) -> tuple[float, float]:
    """Clip each wheel to ``[-max_rad_s, max_rad_s]`` on its own (as Gazebo does)."""
    return (
        max(-max_rad_s, min(max_rad_s, left_rad_s)),
        max(-max_rad_s, min(max_rad_s, right_rad_s)),
    )


def rate_limit(previous: float, target: float, max_rate: float, dt_s: float) -> float:
    """Move from ``previous`` toward ``target`` by at most ``max_rate * dt_s``.

    ``max_rate`` is in the value's unit per second; ``inf`` disables the limit.
    """
    if math.isinf(max_rate):
        return target
    step = max_rate * dt_s
    return previous + max(-step, min(step, target - previous))
