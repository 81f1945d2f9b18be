"""Closed-form answers for the base: lines, circles, turns in place, the timeout ramp."""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.kinematics.link_poses import link_transforms
from tests.simulate.helpers import body, run

GEOMETRY = body().geometry
R, B = GEOMETRY.wheel_radius_m, GEOMETRY.track_m
V_MAX = GEOMETRY.max_wheel_speed_rad_s * R  # top speed the URDF's wheel limits allow


def test_straight_line_at_a_speed_under_the_limit():
    v = 0.5 * V_MAX
    result = run({"duration_s": 10, "cmd_vel": [{"duration_s": 10, "linear_m_s": v}]})
    assert result.truth.x_m[-1] == pytest.approx(v * 10, abs=1e-12)
    assert result.truth.y_m[-1] == pytest.approx(0, abs=1e-12)
    assert result.odometry.x_m[-1] == pytest.approx(v * 10, abs=1e-12)
    # the wheels turned by distance / radius
    assert result.wheel_angles_rad[-1] == pytest.approx([v * 10 / R] * 2, rel=1e-12)


def test_a_command_over_the_limit_is_scaled_and_keeps_its_curvature():
    radius = 0.8  # asked for: v / w = 0.8 m, at speeds far above what the wheels can do
    v, w = 1.0, 1.0 / radius
    result = run({"duration_s": 60, "cmd_vel": [{"duration_s": 60, "linear_m_s": v,
                                                 "angular_rad_s": w}]})
    x, y = result.truth.x_m, result.truth.y_m
    # a circle through the start, centred at (0, radius): every pose lies on it
    assert np.max(np.abs(np.hypot(x, y - radius) - radius)) < 1e-9
    # the outer wheel runs exactly at its limit
    outer = np.abs(result.plan.right_rad_s)
    assert outer.max() == pytest.approx(GEOMETRY.max_wheel_speed_rad_s, rel=1e-12)
    # and the yaw rate is the one that keeps v/w: w = v_outer / (radius + B/2)
    assert result.truth.angular_rad_s[0] == pytest.approx(V_MAX / (radius + B / 2), rel=1e-12)


def test_per_wheel_saturation_changes_the_curvature():
    radius = 0.8
    document = {"duration_s": 10, "controller": {"saturation": "per-wheel"},
                "cmd_vel": [{"duration_s": 10, "linear_m_s": 1.0, "angular_rad_s": 1.0 / radius}]}
    result = run(document)
    # both wheels clip to the limit: a straight line, not an arc
    assert result.truth.angular_rad_s[0] == pytest.approx(0.0, abs=1e-12)
    assert result.truth.x_m[-1] == pytest.approx(V_MAX * 10, rel=1e-12)


def test_turn_in_place():
    w = 0.5 * 2 * V_MAX / B
    result = run({"duration_s": 8, "cmd_vel": [{"duration_s": 8, "angular_rad_s": w}]})
    assert result.truth.yaw_rad[-1] == pytest.approx(w * 8, rel=1e-12)
    assert np.max(np.hypot(result.truth.x_m, result.truth.y_m)) < 1e-12
    left, right = result.plan.left_rad_s[0], result.plan.right_rad_s[0]
    assert left == pytest.approx(-right) and right == pytest.approx(w * B / 2 / R)


def test_timeout_ramps_to_zero_at_the_acceleration_limit():
    v, accel, timeout = 0.5 * V_MAX, 0.01, 0.5
    result = run({"duration_s": 10, "controller": {"max_linear_acceleration_m_s2": accel,
                                                   "cmd_vel_timeout_s": timeout},
                  "cmd_vel": [{"duration_s": 4, "linear_m_s": v}]})
    plan, dt = result.plan, result.plan.dt_s
    t = np.arange(plan.ticks) * dt
    expected = np.clip(np.minimum(accel * (t + dt), v), 0, None)  # ramp up from rest
    ramp_down = t >= 4 + timeout - 1e-9
    expected[ramp_down] = np.maximum(v - accel * (t[ramp_down] - (4 + timeout) + dt), 0)
    np.testing.assert_allclose(plan.linear_m_s, expected, atol=1e-12)
    assert plan.linear_m_s[-1] == 0.0


def test_without_acceleration_limits_the_timeout_stops_at_once():
    result = run({"duration_s": 3, "cmd_vel": [{"duration_s": 1, "linear_m_s": 0.01}]})
    t = np.arange(result.plan.ticks) * result.plan.dt_s
    assert np.all(result.plan.linear_m_s[t < 1.5 - 1e-9] == 0.01)
    assert np.all(result.plan.linear_m_s[t >= 1.5 - 1e-9] == 0.0)


def test_separation_multiplier_makes_odometry_drift_and_slip_too():
    w = 0.5 * 2 * V_MAX / B
    cmd = [{"duration_s": 10, "angular_rad_s": w}]
    exact = run({"duration_s": 10, "cmd_vel": cmd})
    assert exact.odometry.yaw_rad[-1] == pytest.approx(exact.truth.yaw_rad[-1], abs=1e-12)
    slipping = run({"duration_s": 10, "slip": {"track_factor": 1.25}, "cmd_vel": cmd})
    assert slipping.truth.yaw_rad[-1] == pytest.approx(w * 10 / 1.25, rel=1e-9)
    assert slipping.odometry.yaw_rad[-1] == pytest.approx(w * 10, rel=1e-9)
    calibrated = run({"duration_s": 10, "slip": {"track_factor": 1.25},
                      "controller": {"wheel_separation_multiplier": 1.25}, "cmd_vel": cmd})
    assert calibrated.odometry.yaw_rad[-1] == pytest.approx(calibrated.truth.yaw_rad[-1],
                                                            rel=1e-9)
    assert calibrated.truth.yaw_rad[-1] == pytest.approx(w * 10, rel=1e-9)


def test_the_base_stops_at_a_wall_and_logs_the_contact():
    v = V_MAX
    wall_x = 1.0
    result = run({"duration_s": 60, "cmd_vel": [{"duration_s": 60, "linear_m_s": v}],
                  "world": {"walls": [{"from_m": [wall_x, -2], "to_m": [wall_x, 2],
                                       "thickness_m": 0.1}]}})
    # the arm, stretched out ahead at rest, reaches the 1 m wall first: the front of
    # arm_link4 (0.3 m long along x) as the URDF tree places it
    front = link_transforms(body().robot)["arm_link4"][0, 3] + 0.3
    assert front == pytest.approx(0.8)
    assert len(result.contacts) == 1 and result.contacts[0].obstacle == "wall 1"
    assert result.contacts[0].link == "arm_link4"
    gap = (wall_x - 0.05) - (result.truth.x_m[-1] + front)
    assert 0 <= gap <= v * result.plan.dt_s  # stopped within one step of the wall
    assert result.contacts[0].time_s == pytest.approx((wall_x - 0.05 - front) / v, abs=0.011)
    # the wheels kept turning against the wall, so odometry ran ahead
    assert result.odometry.x_m[-1] == pytest.approx(v * 60, rel=1e-9)


def test_arm_follows_points_within_velocity_limits():
    result = run({"duration_s": 6, "arm": {"joint_names": ["arm_base_to_link1"], "points": [
        {"time_from_start_s": 1.0, "positions": [0.5]},      # 0.5 rad/s: tracked exactly
        {"time_from_start_s": 1.5, "positions": [1.5]}]}})   # 2 rad/s asked: limited to 1
    q = result.arm_positions_rad[:, 0]
    t = np.arange(len(q)) * result.plan.dt_s
    np.testing.assert_allclose(q[t <= 1.0 + 1e-9], 0.5 * t[t <= 1.0 + 1e-9], atol=1e-12)
    speed = np.abs(np.diff(q)) / result.plan.dt_s
    assert speed.max() <= 1.0 + 1e-9
    assert q[-1] == pytest.approx(1.5)
    assert math.isclose(t[np.argmax(q >= 1.5 - 1e-12)], 2.0, abs_tol=0.011)  # 1 s for 1 rad
