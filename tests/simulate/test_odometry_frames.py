"""The odometry's frames, and the odom tf's, are the base controller's, read back from the bag.

Names and defaults checked against the sources: ros2_controllers' diff_drive_controller
(``odom_frame_id`` "odom", ``base_frame_id`` "base_link", ``diff_drive_controller_parameter.yaml``);
gazebo_ros_pkgs' ROS 2 ``gazebo_ros_diff_drive.cpp`` (``<odometry_frame>`` "odom",
``<robot_base_frame>`` "base_footprint") and ROS 1 one (``<odometryFrame>``,
``<robotBaseFrame>``, same defaults, through ``tf::resolve``); gz-sim's ``DiffDrive.cc``
(``<frame_id>`` "MODEL/odom", ``<child_frame_id>`` "MODEL/" its canonical link).
"""

from __future__ import annotations

import pytest

from tests.simulate.plugin_robots import (
    LEO,
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
    tf_pairs,
)

pytest.importorskip("rosbags")


def _frames(messages: dict[str, list], topic: str) -> tuple[str, str]:
    [frames] = {(m.header.frame_id, m.child_frame_id) for m in messages[topic]}
    return frames


def _controllers(tmp_path, frames: str = ""):
    path = tmp_path / "controllers.yaml"
    path.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 50\n"
                    "    base:\n      type: diff_drive_controller/DiffDriveController\n"
                    "base:\n  ros__parameters:\n    publish_rate: 10.0\n" + frames)
    return str(path)


def test_a_controllers_files_frames_name_the_odometry_and_its_tf(tmp_path):
    frames = "    odom_frame_id: map_odom\n    base_frame_id: chassis\n"
    messages = bag_messages(SAM_BOT, tmp_path, "--controllers", _controllers(tmp_path, frames))
    assert _frames(messages, "/base/odom") == ("map_odom", "chassis")
    assert ("map_odom", "chassis") in tf_pairs(messages)


def test_a_controllers_file_without_frames_gives_the_controllers_defaults(tmp_path):
    # TurtleBot3's root link is base_footprint; diff_drive_controller still says base_link
    messages = bag_messages(TURTLEBOT3, tmp_path, "--controllers", _controllers(tmp_path))
    assert _frames(messages, "/base/odom") == ("odom", "base_link")
    assert ("odom", "base_link") in tf_pairs(messages)


def test_a_tf_frame_prefix_goes_before_both_frames(tmp_path):
    frames = "    tf_frame_prefix: /robot1\n"
    messages = bag_messages(SAM_BOT, tmp_path, "--controllers", _controllers(tmp_path, frames))
    assert _frames(messages, "/base/odom") == ("robot1/odom", "robot1/base_link")


def test_a_ros2_classic_plugins_frames(tmp_path):
    robot = edited(SAM_BOT, tmp_path, ("<publish_odom_tf>false", "<publish_odom_tf>true"),
                   ("<odometry_frame>odom<", "<odometry_frame>demo/odom<"))
    messages = bag_messages(robot, tmp_path)
    assert _frames(messages, "/demo/odom") == ("demo/odom", "base_link")
    assert ("demo/odom", "base_link") in tf_pairs(messages)


def test_a_ros2_classic_plugins_default_base_frame_is_base_footprint(tmp_path):
    robot = edited(SAM_BOT, tmp_path, ("<robot_base_frame>base_link</robot_base_frame>", ""))
    assert _frames(bag_messages(robot, tmp_path), "/demo/odom") == ("odom", "base_footprint")


def test_a_ros1_plugins_frames_lose_a_leading_slash(tmp_path):
    robot = edited(TURTLEBOT3, tmp_path, ("<odometryFrame>odom<", "<odometryFrame>/tb3_odom<"),
                   ("<robotBaseFrame>base_footprint<", "<robotBaseFrame>base_link<"),
                   file=TURTLEBOT3_GAZEBO)
    messages = bag_messages(robot, tmp_path)
    assert _frames(messages, "/odom") == ("tb3_odom", "base_link")
    assert ("tb3_odom", "base_link") in tf_pairs(messages)


def test_the_gz_diff_drives_frames_and_their_defaults(tmp_path):
    (tmp_path / "given").mkdir()
    messages = bag_messages(LEO, tmp_path / "given")
    assert _frames(messages, "/odom") == ("odom", "base_footprint")
    assert ("odom", "base_footprint") in tf_pairs(messages)
    robot = edited(LEO, tmp_path, ("<frame_id>odom</frame_id>", ""),
                   ("<child_frame_id>${link_prefix}base_footprint</child_frame_id>", ""),
                   file="macros.xacro")
    messages = bag_messages(robot, tmp_path)
    assert _frames(messages, "/odom") == ("leo_sim/odom", "leo_sim/base_footprint")
    assert ("leo_sim/odom", "leo_sim/base_footprint") in tf_pairs(messages)
