"""SB520: a drive plugin's odometry frames that leave the robot without odometry in TF.

RoverSimulation's skid steer writes <odometry_frame> and <robot_base_frame> both
'rover_robot_base_link': tf2 drops every transform from a frame to itself
(TF_SELF_TRANSFORM), and check said nothing. A <robot_base_frame> naming no link (a
base_footprint the URDF lacks) leaves odom apart from robot_state_publisher's tree.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = ('<robot name="r"><link name="base_link"><collision><geometry><box size="0.2 0.15 '
         '0.05"/></geometry></collision></link><gazebo><plugin name="drive" '
         'filename="{filename}">{params}</plugin></gazebo></robot>')
ROS2 = "libgazebo_ros_diff_drive.so"


def _sb520(tmp_path, params: str, filename: str = ROS2) -> list[str]:
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(filename=filename, params=params))
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json",
                            "--select", "SB520")
    found = findings(result.stdout)
    assert all(f["severity"] == "warning" for f in found) and result.returncode == 0
    return [f["message"] for f in found]


def test_an_odometry_frame_equal_to_the_base_frame_is_found(tmp_path):
    (message,) = _sb520(tmp_path, "<publish_odom_tf>true</publish_odom_tf><odometry_frame>"
                        "base_link</odometry_frame><robot_base_frame>base_link"
                        "</robot_base_frame>")
    assert "<odometry_frame> and <robot_base_frame> are both 'base_link'" in message
    assert "TF_SELF_TRANSFORM" in message


def test_a_base_frame_that_is_no_link_is_found(tmp_path):
    (message,) = _sb520(tmp_path, "<publish_odom_tf>true</publish_odom_tf>"
                        "<robot_base_frame>base_footprint</robot_base_frame>")
    assert "<robot_base_frame> 'base_footprint' is no link of the robot" in message


def test_ros1_names_and_their_leading_slash(tmp_path):
    (message,) = _sb520(tmp_path, "<commandTopic>cmd_vel</commandTopic><robotBaseFrame>"
                        "/base_footprint</robotBaseFrame>")  # ROS 1 publishes the tf
    assert "<robotBaseFrame> 'base_footprint' is no link" in message
    assert _sb520(tmp_path, "<commandTopic>cmd_vel</commandTopic><robotBaseFrame>/base_link"
                  "</robotBaseFrame>") == []


def test_gz_sims_diff_drive_child_frame(tmp_path):
    (message,) = _sb520(tmp_path, "<child_frame_id>chassis</child_frame_id>",
                        filename="gz-sim-diff-drive-system")
    assert "<child_frame_id> 'chassis' is no link" in message


@pytest.mark.parametrize("params", [
    "<publish_odom_tf>true</publish_odom_tf>",  # defaults: a launch may publish base_footprint
    "<odometry_frame>base_link</odometry_frame><robot_base_frame>base_link</robot_base_frame>",
    "<publish_odom_tf>true</publish_odom_tf><robot_base_frame>base_link</robot_base_frame>"])
def test_frames_not_written_or_not_broadcast_are_not_judged(tmp_path, params):
    # ROS 2's diff drive puts nothing on /tf unless <publish_odom_tf> says so
    assert _sb520(tmp_path, params) == []


def test_a_leading_slash_is_no_other_frame(tmp_path):
    """tf2 strips a leading '/' from both frames (BufferCore::setTransform): ROS 2's
    <robot_base_frame>/base_link is base_link, and /base_link to base_link is a self
    transform."""
    assert _sb520(tmp_path, "<publish_odom_tf>true</publish_odom_tf><robot_base_frame>"
                  "/base_link</robot_base_frame>") == []
    (message,) = _sb520(tmp_path, "<publish_odom_tf>true</publish_odom_tf><odometry_frame>"
                        "/base_link</odometry_frame><robot_base_frame>base_link"
                        "</robot_base_frame>")
    assert "are both 'base_link'" in message
    assert _sb520(tmp_path, "<child_frame_id>/base_link</child_frame_id>",
                  filename="gz-sim-diff-drive-system") == []


def test_a_part_of_no_link_has_its_links_elsewhere(tmp_path):
    """tortoisebot's tortoisebot_plugins.gazebo: the plugins alone, checked as a file, were
    told base_link 'is no link of the robot' and to name the base link ('None')."""
    path = tmp_path / "plugins.gazebo"
    path.write_text('<robot><gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so">'
                    '<publish_odom_tf>true</publish_odom_tf><robot_base_frame>base_link'
                    '</robot_base_frame></plugin></gazebo></robot>')
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json",
                            "--select", "SB520")
    assert findings(result.stdout) == []
