"""Odometry and joint states are published only where something configured publishes them.

diff_drive_controller publishes odometry only when a controllers file configures one,
joint_state_broadcaster joint states only when configured, a Classic
``gazebo_ros_joint_state_publisher`` (Neobotix MP-400) or the ROS 1 diff drive's
``<publishWheelJointState>`` (TurtleBot3) theirs; robot_state_publisher turns joint states
into the movable joints' transforms, so without them there are none. What the bag holds, read
back by rosbags, is what ``inspect --section topics`` lists.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import DIFFBOT, NO_ROS, REALWORLD_SRC
from tests.simulate.plugin_robots import MP_400, SAM_BOT, TURTLEBOT3, bag_messages

ODOMETRY, JOINT_STATE = "nav_msgs/msg/Odometry", "sensor_msgs/msg/JointState"
DIFFBOT_CONTROLLERS = REALWORLD_SRC / "example_2" / "bringup" / "config" / \
    "diffbot_controllers.yaml"


def _listed(robot: Path, *extra: object) -> dict[str, set[str]]:
    """``inspect --section topics``: the Odometry and JointState topics it publishes."""
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            *extra, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    rows = json.loads(result.stdout)["topics"]["topics"]
    return {kind: {"/" + t["name"].lstrip("/") for t in rows
                   if t["message"] == kind and t["direction"] == "out"}
            for kind in (ODOMETRY, JOINT_STATE)}


def _bagged(messages: dict[str, list]) -> dict[str, set[str]]:
    names = {ODOMETRY: "Odometry", JOINT_STATE: "JointState"}
    return {kind: {topic for topic, m in messages.items()
                   if type(m[0]).__name__.endswith("__" + name)}
            for kind, name in names.items()}


def test_a_robot_with_no_controller_configured_publishes_no_odometry_nor_joints(tmp_path):
    pytest.importorskip("rosbags")
    messages = bag_messages(DIFFBOT, tmp_path)
    assert _bagged(messages) == _listed(DIFFBOT) == {ODOMETRY: set(), JOINT_STATE: set()}
    assert "/tf" not in messages  # no odom -> base, no joint transforms


def test_the_controllers_files_diff_drive_and_broadcaster_publish(tmp_path):
    pytest.importorskip("rosbags")
    messages = bag_messages(DIFFBOT, tmp_path, "--controllers", DIFFBOT_CONTROLLERS)
    assert _bagged(messages) == _listed(DIFFBOT, "--controllers", DIFFBOT_CONTROLLERS) == {
        ODOMETRY: {"/diffbot_base_controller/odom"}, JOINT_STATE: {"/joint_states"}}


def test_a_controllers_file_without_a_broadcaster_publishes_no_joint_states(tmp_path):
    pytest.importorskip("rosbags")
    controllers = tmp_path / "controllers.yaml"
    text = DIFFBOT_CONTROLLERS.read_text()
    assert "joint_state_broadcaster/JointStateBroadcaster" in text
    controllers.write_text(text.replace("joint_state_broadcaster/JointStateBroadcaster",
                                        "some_package/SomethingElse"))
    messages = bag_messages(DIFFBOT, tmp_path, "--controllers", controllers)
    assert _bagged(messages) == _listed(DIFFBOT, "--controllers", controllers) == {
        ODOMETRY: {"/diffbot_base_controller/odom"}, JOINT_STATE: set()}
    # odom -> base only: robot_state_publisher has no joint states to make transforms of
    assert {t.child_frame_id for m in messages["/tf"] for t in m.transforms} == {"base_link"}


@pytest.mark.parametrize(("robot", "odometry", "joints"), [
    (SAM_BOT, {"/demo/odom"}, set()),  # Nav2 runs joint_state_publisher beside, not Gazebo
    (MP_400, {"/odom"}, {"/joint_states"}),  # gazebo_ros_joint_state_publisher
    (TURTLEBOT3, {"/odom"}, {"/joint_states"}),  # <publishWheelJointState>true
], ids=["sam_bot", "mp_400", "turtlebot3"])
def test_gazebo_plugins_publish_what_inspect_lists(tmp_path, robot, odometry, joints):
    pytest.importorskip("rosbags")
    assert _bagged(bag_messages(robot, tmp_path)) == _listed(robot) == {
        ODOMETRY: odometry, JOINT_STATE: joints}
