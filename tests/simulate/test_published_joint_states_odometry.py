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
from tests.simulate.plugin_robots import (
    MP_400,
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
    tf_pairs,
)

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


SAM_WHEELS = {("base_link", "drivewhl_l_link"), ("base_link", "drivewhl_r_link")}
TB3_WHEELS = {("base_link", "wheel_left_link"), ("base_link", "wheel_right_link")}
MP_400_WHEELS = {("base_link", "mp_400_fixed_wheel_left_link"),
                 ("base_link", "mp_400_fixed_wheel_right_link")}


@pytest.mark.parametrize(("robot", "odometry", "joints", "tf"), [
    # Nav2 runs joint_state_publisher beside, not Gazebo; the plugin's <publish_wheel_tf>
    (SAM_BOT, {"/demo/odom"}, set(), SAM_WHEELS),  # (repro: lost in 14cf5e0)
    # gazebo_ros_joint_state_publisher's joints through robot_state_publisher, and the
    # plugin's <publish_wheel_tf> from base_footprint, which Gazebo merges base_link into
    (MP_400, {"/odom"}, {"/joint_states"}, MP_400_WHEELS | {("odom", "base_footprint")} | {
        ("base_footprint", child) for _, child in MP_400_WHEELS}),
    (TURTLEBOT3, {"/odom"}, {"/joint_states"},  # <publishWheelJointState>true
     TB3_WHEELS | {("odom", "base_footprint")}),
], ids=["sam_bot", "mp_400", "turtlebot3"])
def test_gazebo_plugins_publish_what_inspect_lists(tmp_path, robot, odometry, joints, tf):
    pytest.importorskip("rosbags")
    messages = bag_messages(robot, tmp_path)
    assert _bagged(messages) == _listed(robot) == {ODOMETRY: odometry, JOINT_STATE: joints}
    assert tf_pairs(messages) == tf


def test_the_diff_drive_plugin_puts_its_wheels_on_tf_at_its_rate(tmp_path):
    """ROS 2 ``PublishWheelsTf``: right then left, one transform a message, each update."""
    pytest.importorskip("rosbags")
    messages = bag_messages(SAM_BOT, tmp_path)
    wheels = [m.transforms for m in messages["/tf"]]
    assert all(len(t) == 1 for t in wheels)
    assert [t[0].child_frame_id for t in wheels[:4]] == [
        "drivewhl_r_link", "drivewhl_l_link"] * 2
    stamps = [t[0].header.stamp.sec + t[0].header.stamp.nanosec * 1e-9 for t in wheels[::2]]
    odometry = [m.header.stamp.sec + m.header.stamp.nanosec * 1e-9
                for m in messages["/demo/odom"]]
    assert stamps == odometry  # at <update_rate> (100 Hz), with the odometry
    assert wheels[0][0].transform.translation.y == pytest.approx(-0.18)  # -(0.3/2 + 0.03)


def test_the_ros1_diff_drive_puts_wheels_on_tf_without_joint_states(tmp_path):
    """<publishWheelTF>true, <publishWheelJointState>false: the wheels from Gazebo's
    base_footprint, into which it merges base_link (fixed joint)."""
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path,
                   ("<publishWheelTF>false</publishWheelTF>",
                    "<publishWheelTF>true</publishWheelTF>"),
                   ("<publishWheelJointState>true</publishWheelJointState>",
                    "<publishWheelJointState>false</publishWheelJointState>"),
                   file=TURTLEBOT3_GAZEBO)
    messages = bag_messages(robot, tmp_path)
    assert "/joint_states" not in messages
    assert tf_pairs(messages) == {("odom", "base_footprint"),
                                  ("base_footprint", "wheel_left_link"),
                                  ("base_footprint", "wheel_right_link")}
    left = next(m.transforms[0] for m in messages["/tf"]
                if m.transforms[0].child_frame_id == "wheel_left_link")
    assert left.transform.translation.z == pytest.approx(0.023 + 0.010)  # base_joint's too


MP_400_JOINTS = ("<joint_name>mp_400_fixed_wheel_left_joint</joint_name>\n"
                 "        <joint_name>mp_400_fixed_wheel_right_joint</joint_name>")


@pytest.mark.parametrize(("joints", "rate_hz"), [
    (("mp_400_fixed_wheel_right_joint", "mp_400_fixed_wheel_left_joint"), 20),
    (("mp_400_fixed_wheel_left_joint",), 10),
], ids=["reordered", "subset"])
def test_the_joint_state_publisher_sends_its_joints_in_order_at_its_rate(tmp_path, joints,
                                                                         rate_hz):
    """ros2 gazebo_ros_joint_state_publisher.cpp: its <joint_name>s, that order, <update_rate>."""
    pytest.importorskip("rosbags")
    names = "".join(f"<joint_name>{n}</joint_name>" for n in joints)
    robot = edited(MP_400, tmp_path,
                   (MP_400_JOINTS, f"{names}<update_rate>{rate_hz}</update_rate>"))
    out = tmp_path / "out"
    messages = bag_messages(robot, tmp_path, "--out", out)
    states = messages["/joint_states"]
    assert {tuple(m.name) for m in states} == {joints}
    assert len(states) == pytest.approx(2 * rate_hz, abs=1)  # 2 s
    header = (out / "joint_states.csv").read_text().splitlines()[0].split(",")
    assert header == ["time_s", *(f"{n}_{unit}" for unit in ("rad", "rad_s") for n in joints)]
    assert (out / "joint_states.csv").read_text().count("\n") - 1 == len(states)
    moving = {t.child_frame_id for m in messages["/tf"] for t in m.transforms
              if t.header.frame_id == "base_link"}  # robot_state_publisher's, from them
    assert moving == {n.replace("_joint", "_link") for n in joints}


def test_the_joint_state_publisher_runs_at_100_hz_by_default(tmp_path):
    pytest.importorskip("rosbags")
    states = bag_messages(MP_400, tmp_path)["/joint_states"]
    assert len(states) == pytest.approx(200, abs=1)
    assert tuple(states[0].name) == ("mp_400_fixed_wheel_left_joint",
                                     "mp_400_fixed_wheel_right_joint")
