"""Error messages for unknown names: the nearest names come first."""

from __future__ import annotations

from servicebot_cli.common.errors import FrameNotFound, JointNotFound

LINKS = ["base_link", "front_left_wheel", "lidar_link", "camera_link", "imu_link",
         "arm_base_link", "arm_link1", "arm_link2", "arm_tool_link"]


def test_close_names_are_suggested():
    message = str(FrameNotFound.for_name("arm_tol_link", LINKS, robot="r"))
    assert message.startswith("no frame 'arm_tol_link' in r; did you mean 'arm_tool_link'")


def test_without_a_close_name_the_known_names_come_nearest_first():
    message = str(FrameNotFound.for_name("tool", LINKS))
    assert "known, nearest first: arm_tool_link," in message
    message = str(JointNotFound.for_name("wheel", ["arm_joint", "left_wheel_joint"]))
    assert message.endswith("known, nearest first: left_wheel_joint, arm_joint")


def test_no_candidates():
    assert str(JointNotFound.for_name("x", [])) == "no joint 'x'; the robot has no joints"
