"""inspect lists what a Classic diff-drive plugin publishes exactly where simulate publishes it.

gazebo_ros_pkgs' ROS 1 ``gazebo_ros_diff_drive.cpp`` (noetic-devel) publishes odometry only
while ``<publishTf>`` is true (default true), odom -> base on /tf only when ``<publishOdomTF>``
is true as well (default true), and the wheels on /tf with ``<publishWheelTF>`` (default
false); the ROS 2 plugin (ros2 branch) publishes ``odom`` only with ``<publish_odom>true``.
"""

from __future__ import annotations

import pytest

from tests.simulate.plugin_robots import (
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
    plugin_topics,
    tf_pairs,
)

TB3_PLUGIN = "turtlebot3_burger_controller"


def test_turtlebot3_without_publish_odom_tf_lists_and_broadcasts_no_odom_tf(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, ("<publishOdomTF>true", "<publishOdomTF>false"),
                   file=TURTLEBOT3_GAZEBO)
    assert plugin_topics(robot, TB3_PLUGIN) == {"/cmd_vel": "in", "/odom": "out",
                                                "/joint_states": "out"}
    messages = bag_messages(robot, tmp_path)
    assert messages["/odom"]
    assert not {pair for pair in tf_pairs(messages) if pair[0] == "odom"}


def test_turtlebot3_with_publish_wheel_tf_alone_still_lists_tf(tmp_path):
    robot = edited(TURTLEBOT3, tmp_path, ("<publishOdomTF>true", "<publishOdomTF>false"),
                   ("<publishWheelTF>false", "<publishWheelTF>true"), file=TURTLEBOT3_GAZEBO)
    assert plugin_topics(robot, TB3_PLUGIN) == {"/cmd_vel": "in", "/odom": "out", "/tf": "out",
                                                "/joint_states": "out"}


def test_turtlebot3_without_publish_tf_publishes_no_odometry_at_all(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, ("<publishTf>true", "<publishTf>false"),
                   file=TURTLEBOT3_GAZEBO)
    # <publishWheelJointState> is not gated by <publishTf>
    assert plugin_topics(robot, TB3_PLUGIN) == {"/cmd_vel": "in", "/joint_states": "out"}
    messages = bag_messages(robot, tmp_path)
    assert not [topic for topic in messages if "odom" in topic]
    assert not {pair for pair in tf_pairs(messages) if pair[0] == "odom"}


def test_sam_bot_without_publish_odom_lists_no_odometry(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, ("<publish_odom>true</publish_odom>", ""))
    assert "/demo/odom" not in plugin_topics(robot, "diff_drive")
    assert "/demo/odom" not in bag_messages(robot, tmp_path)
