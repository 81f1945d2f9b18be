"""Sensors against known answers: LIDAR ranges to a wall, IMU at rest, camera intrinsics."""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.description.sensors import LidarSpec, NoiseSpec
from servicebot_cli.simulate.bag.msgdefs import MESSAGE_DEFINITIONS
from servicebot_cli.simulate.sensors.lidar import readings
from servicebot_cli.simulate.sensors.noise import Noise
from tests.simulate.helpers import body, run

BODY = body()
LIDAR = BODY.ray_sensors[0].spec
LIDAR_X = BODY.ray_sensors[0].transform_sensor_to_base[0, 3]


def test_lidar_ranges_against_a_wall_match_the_geometry():
    wall = 2.0  # the wall's face is at x = wall - 0.05
    result = run({"duration_s": 1, "world": {"walls": [
        {"from_m": [wall, -20], "to_m": [wall, 20], "thickness_m": 0.1, "height_m": 1}]}},
        seed=3)
    [scans] = result.scans
    assert scans.ranges_m.shape == (LIDAR.update_rate_hz * 1, LIDAR.samples)
    facing = np.abs(scans.angles_rad - math.pi) > math.pi / 2 + 0.01  # rays toward +x
    expected = (wall - 0.05 - LIDAR_X) / np.cos(scans.angles_rad[facing])
    expected = np.where(expected > LIDAR.max_range_m, np.inf, expected)
    measured = scans.ranges_m[:, facing]
    finite = np.isfinite(expected)
    error = measured[:, finite] - expected[finite]
    # gaussian noise (stddev from the URDF), never rounded to the range resolution
    assert abs(error.mean()) < 0.003
    assert error.std() == pytest.approx(LIDAR.noise.stddev, rel=0.1)
    quanta = measured[:, finite] / LIDAR.range_resolution_m
    assert np.mean(np.abs(quanta - np.round(quanta)) > 1e-3) > 0.9
    assert np.all(np.isinf(measured[:, ~finite]))
    behind = scans.ranges_m[:, ~facing]
    # nothing behind but the robot's own arm_base_link, 0.23 m back, 24 rays wide
    assert np.all(np.isinf(behind) | (np.abs(behind - 0.23) < 0.06))
    assert np.isfinite(behind).sum(axis=1).tolist() == [24] * len(behind)


def test_lidar_does_not_see_a_box_below_its_scan_plane():
    low = {"center_m": [1.5, 0.0], "size_m": [0.4, 0.4, 0.1]}
    tall = {"center_m": [1.5, 0.0], "size_m": [0.4, 0.4, 1.0]}
    ahead = [run({"duration_s": 0.1, "world": {"boxes": [box]}}).scans[0].ranges_m[0, 0]
             for box in (low, tall)]
    assert math.isinf(ahead[0])
    assert ahead[1] == pytest.approx(1.3 - LIDAR_X, abs=0.05)


def test_lidar_readings_follow_rep_117_as_gazebo_does():
    spec = LidarSpec(6, 1.0, 0.0, 1.0, 0.12, 12.0, 0.015, 10.0,
                     NoiseSpec("gaussian", 0.0, 0.0, bias_mean=0.01), "lidar_link", "scan")
    rng = np.random.default_rng(0)
    values = readings(np.array([[0.05, 0.12, 1.0071, 11.995, 12.0, 30.0]]), spec,
                      Noise(spec.noise, rng))
    bias = Noise(spec.noise, np.random.default_rng(0)).bias
    assert abs(bias) == pytest.approx(0.01)
    assert values[0, 0] == values[0, 1] == -np.inf  # at or closer than min
    assert values[0, 2] == 1.0071 + bias  # noisy, not rounded to the resolution
    assert values[0, 3] == min(11.995 + bias, 12.0)  # noisy, then clamped to max
    assert values[0, 4] == values[0, 5] == np.inf  # at or beyond max


def test_imu_at_rest_reads_gravity_with_the_urdf_noise():
    result = run({"duration_s": 20})
    imu, spec = result.imu, BODY.imu.spec
    accel, rate = imu.linear_acceleration_m_s2, imu.angular_velocity_rad_s
    assert len(imu.times_s) == spec.update_rate_hz * 20
    assert accel[:, 2].mean() == pytest.approx(9.8, abs=1e-3)
    assert accel[:, :2].mean(axis=0) == pytest.approx([0, 0], abs=1e-3)
    assert accel[:, 2].std() == pytest.approx(spec.linear_acceleration_noise[2].stddev, rel=0.1)
    assert rate.std(axis=0) == pytest.approx([spec.angular_velocity_noise[0].stddev] * 3,
                                             rel=0.1)
    np.testing.assert_allclose(imu.orientation_xyzw, [[0, 0, 0, 1]] * len(imu.times_s))


def test_imu_feels_the_centripetal_acceleration_of_a_turn():
    v = 0.5 * BODY.geometry.max_linear_m_s
    w = 0.5 * BODY.geometry.max_angular_rad_s / 2
    result = run({"duration_s": 10, "cmd_vel": [{"duration_s": 10, "linear_m_s": v,
                                                 "angular_rad_s": w}]})
    steady = result.imu.times_s > 1
    assert result.imu.linear_acceleration_m_s2[steady, 1].mean() == pytest.approx(v * w,
                                                                                 abs=5e-4)
    assert result.imu.angular_velocity_rad_s[steady, 2].mean() == pytest.approx(w, abs=1e-4)


def test_camera_info_from_resolution_and_field_of_view():
    camera = run({"duration_s": 1}).camera
    spec = BODY.camera.spec
    f = spec.width_px / (2 * math.tan(spec.horizontal_fov_rad / 2))
    assert camera.k == pytest.approx((f, 0, (spec.width_px + 1) / 2, 0, f,
                                      (spec.height_px + 1) / 2, 0, 0, 1))


def test_message_definitions_match_an_independent_copy():
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    for name, text in MESSAGE_DEFINITIONS.items():
        assert store.generate_msgdef(name, ros_version=2)[0] == text, name
