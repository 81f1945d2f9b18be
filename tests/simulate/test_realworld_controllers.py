"""simulate reads a real ros2_control controllers file written for Jazzy.

ros2_control_demos' example_2 declares its controller's ``type`` in the controller's own
``ros__parameters`` (as ros2_control does since Jazzy) and gives limits without Humble's
``has_*_limits`` flags. The file was ignored: every controller value came from the defaults.
"""

from __future__ import annotations

import json
import re

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import DIFFBOT, DRIVE_ONLY, NO_ROS, REALWORLD_SRC

CONTROLLERS = REALWORLD_SRC / "example_2" / "bringup" / "config" / "diffbot_controllers.yaml"


def _summary(tmp_path, *options: object) -> dict:
    scenario = tmp_path / "drive.yaml"
    scenario.write_text(DRIVE_ONLY)
    result = run_servicebot("simulate", DIFFBOT, "--headless", "-s", scenario, "--format",
                            "json", *options, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_the_jazzy_controllers_file_sets_the_limits_and_covariances(tmp_path):
    controller = _summary(tmp_path, "--controllers", CONTROLLERS)["controller"]
    for field, value in (("max_linear_velocity_m_s", 1.0), ("min_linear_velocity_m_s", -1.0),
                         ("max_linear_acceleration_m_s2", 1.0),
                         ("max_angular_acceleration_rad_s2", 1.0),
                         ("min_angular_acceleration_rad_s2", -1.0),
                         ("pose_covariance_diagonal", [0.001] * 5 + [0.01])):
        assert controller[field] == {"value": value, "source": str(CONTROLLERS)}, field


def test_its_acceleration_limit_changes_the_run(tmp_path):
    free = _summary(tmp_path)["final_pose"]["x_m"]
    limited = _summary(tmp_path, "--controllers", CONTROLLERS)["final_pose"]["x_m"]
    assert free == pytest.approx(6 * 0.015)  # wheels' 1 rad/s at r = 0.015 m, for 6 s
    # 0.1 m/s braked at 1 m/s^2 keeps the wheels saturated 0.085 s longer: 1.3 mm further
    assert limited - free == pytest.approx(0.085 * 0.015, rel=0.1)


def test_odometry_is_published_under_the_controllers_name(tmp_path):
    rosbags = pytest.importorskip("rosbags.rosbag2")
    bag = tmp_path / "bag"
    summary = _summary(tmp_path, "--controllers", CONTROLLERS, "--bag", bag)
    assert summary["messages"]["/diffbot_base_controller/odom"] == 600  # 50 Hz for 12 s
    assert "/diff_controller/odom" not in summary["messages"]
    with rosbags.Reader(bag) as reader:
        odometry = [c.topic for c in reader.connections if c.msgtype == "nav_msgs/msg/Odometry"]
    assert odometry == ["/diffbot_base_controller/odom"]


def test_streams_are_published_at_most_once_a_control_tick(tmp_path):
    controllers = tmp_path / "slow.yaml"  # articubot_one's rates: a 30 Hz controller manager
    controllers.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 30\n"
                           + CONTROLLERS.read_text())
    summary = _summary(tmp_path, "--controllers", controllers)
    assert summary["controller"]["update_rate_hz"]["value"] == 30.0
    messages = summary["messages"]
    assert messages["/clock"] == 12 * 30 + 1
    # the file asks odometry at 50 Hz and joint states default to 50 Hz: 30 Hz is the most
    assert messages["/diffbot_base_controller/odom"] == 12 * 30
    assert messages["/joint_states"] == 12 * 30


SLOW = """\
duration_s: 20
initial_pose: {x_m: 0, y_m: 0, yaw_rad: 0}
cmd_vel:
  - {duration_s: 10, linear_m_s: 0.01}
  - {duration_s: 10, angular_rad_s: 0.1}
"""
"""Slow enough that no wheel reaches its 1 rad/s limit: 0.67 and 0.33 rad/s."""


def _slow_run(tmp_path, **geometry: float) -> dict:
    text = CONTROLLERS.read_text()
    for key, value in geometry.items():
        text = text.replace(f"    {key}: ", f"    {key}: {value}  # was ")
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text(text)
    scenario = tmp_path / "slow.yaml"
    scenario.write_text(SLOW)
    result = run_servicebot("simulate", DIFFBOT, "--headless", "-s", scenario, "--format",
                            "json", "--controllers", controllers, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


@pytest.mark.parametrize(("geometry", "ratios"), [
    ({}, (1.0, 1.0)),  # the file's geometry is the URDF's (0.015 m, 0.10 m)
    # twice the radius: the controller asks half the wheel speed; its odometry believes it
    ({"wheel_radius": 0.03}, (0.5, 0.5)),
    # a wider track than the robot's: the wheels part more, the robot turns 1.2 times
    ({"wheel_separation": 0.12}, (1.0, 1.2)),
    ({"wheel_separation_multiplier": 1.2}, (1.0, 1.2)),
])
def test_the_files_wheel_geometry_commands_the_wheels_and_reads_the_odometry(
        tmp_path, geometry, ratios):
    """diff_drive_controller computes with its parameters; the robot moves on its wheels."""
    summary = _slow_run(tmp_path, **geometry)
    final, odom = summary["final_pose"], summary["odometry_final_pose"]
    # 10 s straight, then a turn in place: x is the distance, yaw the turn; the odometry
    # says what was commanded (the file's acceleration limits take a little off each)
    assert (odom["x_m"], odom["yaw_rad"]) == pytest.approx((0.1, 1.0), rel=0.01)
    assert (final["x_m"] / odom["x_m"], final["yaw_rad"] / odom["yaw_rad"]) == pytest.approx(
        ratios, rel=1e-6)
    for key, value in geometry.items():
        field = {"wheel_radius": "wheel_radius_m",
                 "wheel_separation": "wheel_separation_m"}.get(key, key)
        assert summary["controller"][field]["value"] == value


def test_a_wheel_radius_that_is_not_positive_is_one_line(tmp_path):
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text(CONTROLLERS.read_text().replace("wheel_radius: 0.015",
                                                           "wheel_radius: 0.0"))
    result = run_servicebot("simulate", DIFFBOT, "--headless", "--controllers", controllers,
                            env=NO_ROS)
    assert result.returncode == 2
    assert result.stderr.strip().splitlines() == [
        f"Error: {controllers}: diffbot_base_controller.wheel_radius: must be positive, got 0.0"]


def test_a_base_controller_simulate_does_not_model_is_named(tmp_path):
    """Clearpath's do100 names a mecanum controller: it was driven as a differential drive
    without a word."""
    controllers = tmp_path / "mecanum.yaml"
    controllers.write_text(
        "controller_manager:\n  ros__parameters:\n    update_rate: 50\n"
        "    platform_velocity_controller:\n"
        "      type: clearpath_mecanum_drive_controller/MecanumDriveController\n"
        "platform_velocity_controller:\n  ros__parameters:\n    wheels_radius: 0.05\n")
    scenario = tmp_path / "drive.yaml"
    scenario.write_text(DRIVE_ONLY)
    result = run_servicebot("simulate", DIFFBOT, "--headless", "-s", scenario,
                            "--controllers", controllers, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert ("the base's controller 'platform_velocity_controller' is a clearpath_mecanum_drive_"
            "controller/MecanumDriveController, which simulate does not model") in result.stderr
    # and what it prints does not say odometry was published: it printed 'odometry says'
    assert re.search(r"^wheel odometry +x \S+ m, .* \(no controller publishes it\)$",
                     result.stdout, re.MULTILINE), result.stdout
    assert "odometry says" not in result.stdout
    plain = run_servicebot("simulate", DIFFBOT, "--headless", "-s", scenario, "--controllers",
                           CONTROLLERS, env=NO_ROS)
    assert "does not model" not in plain.stderr
    assert re.search(r"^odometry says +x \S+ m, [^(]*$", plain.stdout, re.MULTILINE)
