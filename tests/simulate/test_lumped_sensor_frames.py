"""A ROS 2 sensor plugin without <frame_name> stamps the link Gazebo carries the sensor on.

sdformat's URDF converter lumps a fixed joint's child into its parent, and gazebo_ros's
``SensorFrameID`` names the sensor's parent link when no ``<frame_name>`` is written: Nav2's
sam_bot without its ``<frame_name>lidar_link`` publishes scans in ``base_link``. inspect
said ``lidar_link``, and simulate stamped the scans so.
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, bag_messages, edited

NO_FRAME_NAME = ("<frame_name>lidar_link</frame_name>", "")
KEPT = ('<joint name="lidar_joint" type="fixed">',
        '<gazebo reference="lidar_joint"><preserveFixedJoint>true</preserveFixedJoint></gazebo>'
        '<joint name="lidar_joint" type="fixed">')


def _lidar(robot) -> dict:
    result = run_servicebot("inspect", robot, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return next(s for s in json.loads(result.stdout)["sensors"] if s["name"] == "lidar")


def _lidar_text(robot) -> str:
    result = run_servicebot("inspect", robot, "--section", "sensors", env=NO_ROS)
    return next(line for line in result.stdout.splitlines() if line.startswith("lidar ")
                and " frame " in line)


def test_without_frame_name_the_scan_is_in_the_link_gazebo_lumps_it_into(tmp_path):
    robot = edited(SAM_BOT, tmp_path, NO_FRAME_NAME)
    lidar = _lidar(robot)
    assert (lidar["link"], lidar["frame"], lidar["carrier"]) == (
        "lidar_link", "base_link", "base_link")
    assert _lidar_text(robot).split(None, 2)[2] == "base_link (Gazebo lumps lidar_link into it)"
    pytest.importorskip("rosbags")
    scans = bag_messages(robot, tmp_path, duration_s="0.5")["/scan"]
    assert {scan.header.frame_id for scan in scans} == {"base_link"}


def test_a_joint_kept_apart_or_a_frame_name_keeps_the_sensors_link(tmp_path):
    kept = edited(SAM_BOT, tmp_path / "kept", NO_FRAME_NAME, KEPT)
    assert _lidar(kept)["frame"] == "lidar_link"
    assert _lidar(SAM_BOT)["frame"] == "lidar_link"  # written: <frame_name>lidar_link
    assert _lidar_text(SAM_BOT).split(None, 2)[2] == "lidar_link"


def test_gazebo_never_lumps_a_link_into_world(run, tmp_path):
    """sdformat keeps a fixed joint to ``world`` (it anchors the model): an IMU on the
    anchored base is stamped base_link, not world."""
    path = tmp_path / "anchored.urdf"
    path.write_text('<robot name="a"><link name="world"/><joint name="anchor" type="fixed">'
                    '<parent link="world"/><child link="base_link"/></joint>'
                    '<link name="base_link"><inertial><mass value="1"/><inertia ixx="1" '
                    'iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>'
                    '<gazebo reference="base_link"><sensor name="imu" type="imu"><plugin '
                    'filename="libgazebo_ros_imu_sensor.so" name="imu_plugin"><ros>'
                    '<namespace>/a</namespace></ros></plugin></sensor></gazebo></robot>')
    (sensor,) = json.loads(run("inspect", path, "--section", "sensors", "--format",
                               "json").stdout)["sensors"]
    assert (sensor["frame"], sensor["carrier"]) == ("base_link", "base_link")
