"""Intermediate trajectory points are reached, late when asked for faster than the arm can go."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from servicebot_cli.simulate.controllers.arm_trajectory import ArmLimits, ArmMotion
from servicebot_cli.simulate.scenario.definition import ArmTrajectory, TrajectoryPoint
from tests.simulate.helpers import run

V_RAD_S = 1.0  # every arm joint's URDF velocity limit


def _times_s(result) -> np.ndarray:
    return np.arange(len(result.arm_positions_rad)) * result.plan.dt_s


def test_a_point_asked_too_soon_is_reached_late_and_not_cut_short():
    result = run({"duration_s": 5, "arm": {"joint_names": ["arm_base_to_link1"], "points": [
        {"time_from_start_s": 0.5, "positions": [1.5]},    # needs 1.5 s at 1 rad/s
        {"time_from_start_s": 2.0, "positions": [0.0]}]}})  # 1.5 s asked, 1.5 s needed
    q, t = result.arm_positions_rad[:, 0], _times_s(result)
    assert q.max() == pytest.approx(1.5, abs=1e-12)
    assert t[np.argmax(q >= 1.5 - 1e-12)] == pytest.approx(1.5, abs=1e-9)
    assert t[np.argmax((t > 1.5) & (q <= 1e-12))] == pytest.approx(3.0, abs=1e-9)
    np.testing.assert_allclose(q, np.interp(t, [0, 1.5, 3.0], [0, 1.5, 0]), atol=1e-12)
    assert np.abs(np.diff(q)).max() / result.plan.dt_s <= V_RAD_S * (1 + 1e-9)


def test_joints_of_a_stretched_segment_arrive_together():
    result = run({"duration_s": 4, "arm": {
        "joint_names": ["arm_base_to_link1", "arm_link1_to_link2"], "points": [
            {"time_from_start_s": 0.25, "positions": [1.0, 0.5]},   # the first joint needs 1 s
            {"time_from_start_s": 2.25, "positions": [1.0, -0.5]}]}})  # 2 s asked, 1 s needed
    t = _times_s(result)
    first, second = result.arm_positions_rad[:, 0], result.arm_positions_rad[:, 1]
    np.testing.assert_allclose(first, np.interp(t, [0, 1], [0, 1]), atol=1e-12)
    np.testing.assert_allclose(second, np.interp(t, [0, 1, 3], [0, 0.5, -0.5]), atol=1e-12)



def test_a_joint_whose_velocity_limit_is_zero_holds_and_the_others_keep_their_times():
    trajectory = ArmTrajectory(("a", "b"), (TrajectoryPoint(1.0, (0.5, 0.5)),
                                            TrajectoryPoint(2.0, (0.5, -0.5))))
    limits = ArmLimits(np.array([-1.0, -1.0]), np.array([1.0, 1.0]), np.array([0.0, 1.0]))
    motion = ArmMotion(trajectory, [0, 1], np.zeros(2), limits, 0.01)
    t = np.arange(301) * 0.01
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no division by the zero limit
        q = motion.follow(motion.references(t), motion.start())
    assert np.all(q[:, 0] == 0.0)  # URDF velocity="0": the joint cannot move
    np.testing.assert_allclose(q[:, 1], np.interp(t, [0, 1, 2], [0, 0.5, -0.5]), atol=1e-12)
