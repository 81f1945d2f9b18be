"""Roll-pitch-yaw and quaternions: conventions, round trips, gimbal lock, rate rows."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from servicebot_cli.kinematics import rotations
from servicebot_cli.kinematics.transforms import rpy_matrix

angle = st.floats(-math.pi, math.pi, allow_nan=False)
half = st.floats(-math.pi / 2, math.pi / 2, allow_nan=False)


@given(angle, half, angle)
def test_matrix_from_rpy_is_urdfs_convention(roll, pitch, yaw):
    matrix = rotations.matrix_from_rpy(np.array([roll, pitch, yaw]))
    assert matrix.tobytes() == rpy_matrix(roll, pitch, yaw).tobytes()  # bit for bit
    assert matrix == pytest.approx(pin.rpy.rpyToMatrix(roll, pitch, yaw), abs=1e-12)


@given(angle, half, angle)
def test_rpy_round_trips_through_the_matrix(roll, pitch, yaw):
    matrix = rotations.matrix_from_rpy(np.array([roll, pitch, yaw]))
    again = rotations.matrix_from_rpy(rotations.rpy_from_matrix(matrix))
    assert again == pytest.approx(matrix, abs=1e-9)


@pytest.mark.parametrize("pitch", [math.pi / 2, -math.pi / 2])
def test_gimbal_lock_reports_yaw_zero_and_keeps_the_rotation(pitch):
    matrix = rotations.matrix_from_rpy(np.array([0.3, pitch, 1.1]))
    rpy = rotations.rpy_from_matrix(matrix)
    assert rpy[1] == pytest.approx(pitch) and rpy[2] == 0.0
    assert rotations.matrix_from_rpy(rpy) == pytest.approx(matrix, abs=1e-12)


def test_stacks_convert_in_one_call():
    rng = np.random.default_rng(0)
    rpy = rng.uniform(-1.5, 1.5, size=(5, 7, 3))
    matrices = rotations.matrix_from_rpy(rpy)
    assert matrices.shape == (5, 7, 3, 3)
    assert rotations.rpy_from_matrix(matrices) == pytest.approx(rpy)
    assert rotations.quaternion_from_matrix(matrices).shape == (5, 7, 4)


@settings(max_examples=200)
@given(st.lists(st.floats(-1, 1, allow_nan=False), min_size=4, max_size=4)
       .filter(lambda v: np.linalg.norm(v) > 1e-3))
def test_quaternion_round_trip_with_w_not_negative(xyzw):
    matrix = rotations.matrix_from_quaternion(np.array(xyzw))
    assert matrix @ matrix.T == pytest.approx(np.eye(3), abs=1e-12)
    q = rotations.quaternion_from_matrix(matrix)
    assert q[3] >= 0 and np.linalg.norm(q) == pytest.approx(1.0)
    expected = np.array(xyzw) / np.linalg.norm(xyzw)
    expected = expected if expected[3] >= 0 else -expected
    assert q == pytest.approx(expected, abs=1e-9) or abs(q[3]) < 1e-9


def test_quaternion_agrees_with_pinocchio_including_half_turns():
    for matrix in [np.diag([1.0, -1.0, -1.0]), np.diag([-1.0, 1.0, -1.0]),
                   np.diag([-1.0, -1.0, 1.0]), pin.SE3.Random().rotation]:
        ours = rotations.quaternion_from_matrix(matrix)
        theirs = pin.Quaternion(matrix).coeffs()  # x y z w
        assert abs(ours @ theirs) == pytest.approx(1.0)


def test_zero_quaternion_is_refused():
    with pytest.raises(rotations.BadRotation, match="length 0"):
        rotations.matrix_from_quaternion(np.zeros(4))


def test_rpy_rate_rows_match_finite_differences():
    rng = np.random.default_rng(1)
    for _ in range(20):
        rpy = rng.uniform([-3, -1.4, -3], [3, 1.4, 3])
        omega = rng.normal(size=3) * 1e-6  # small world-frame rotation
        turned = pin.exp3(omega) @ rotations.matrix_from_rpy(rpy)
        rates = rotations.wrap_angle(rotations.rpy_from_matrix(turned) - rpy)
        assert rates == pytest.approx(rotations.rpy_rate_rows(rpy) @ omega, abs=1e-10)
