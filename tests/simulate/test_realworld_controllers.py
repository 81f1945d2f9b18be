"""simulate reads a real ros2_control controllers file written for Jazzy.

ros2_control_demos' example_2 declares its controller's ``type`` in the controller's own
``ros__parameters`` (as ros2_control does since Jazzy) and gives limits without Humble's
``has_*_limits`` flags. The file was ignored: every controller value came from the defaults.
"""

from __future__ import annotations

import json

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
