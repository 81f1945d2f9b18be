"""Sensor topics and frames of gz-sim descriptions (no ROS plugin in the sensor), no ROS set.

A gz-sim sensor publishes on its ``<topic>`` made absolute, and ros_gz_bridge gives the ROS
topic the same name; a camera's info goes beside its image (gz-sensors'
``CameraSensor::AdvertiseInfo``: the topic's parent, then ``camera_info``), a GPU lidar's points
under ``TOPIC/points``; messages are stamped with ``<ignition_frame_id>`` (Fortress),
``<gz_frame_id>`` or ``<frame_id>``. Vendored: Leo Rover's ``leo_description`` (MIT) and
Husarion's D435 macro (Apache-2.0), see each ``SOURCE.md``.
"""

from __future__ import annotations

import json

from tests.conftest import REPO, run_servicebot

FIXTURES = REPO / "tests" / "fixtures"
LEO = FIXTURES / "leo_description" / "urdf" / "leo_sim.urdf.xacro"
D435 = FIXTURES / "d435_on_a_box" / "robot.urdf.xacro"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def _sensors(path):
    result = run_servicebot("inspect", path, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return {s["name"]: s for s in json.loads(result.stdout)["sensors"]}


def _topics(sensor):
    return [(t["name"], t["message"]) for t in sensor["topics"]]


def test_leo_camera_and_imu_publish_on_their_gz_topics_made_absolute():
    sensors = _sensors(LEO)
    assert _topics(sensors["camera"]) == [("/camera/image_raw", "sensor_msgs/msg/Image"),
                                          ("/camera/camera_info", "sensor_msgs/msg/CameraInfo")]
    assert _topics(sensors["leo_imu_sensor"]) == [("/imu/data_raw", "sensor_msgs/msg/Imu")]
    assert sensors["camera"]["plugin"] is None
    assert "gz <topic>" in sensors["camera"]["topics_from"]
    assert sensors["camera"]["frame"] == "camera_frame"  # its <ignition_frame_id>


def test_the_gz_frame_id_stamps_the_messages_not_the_link_the_sensor_sits_on():
    sensors = _sensors(D435)
    color = sensors["{prefix}camera_intel_realsense_d435_color"]  # the macro's own typo
    depth = sensors["camera_intel_realsense_d435_depth"]
    assert (color["link"], color["frame"]) == ("camera_link", "camera_color_optical_frame")
    assert (depth["link"], depth["frame"]) == ("camera_link", "camera_depth_optical_frame")
    assert _topics(color) == [("/camera/color/image_raw", "sensor_msgs/msg/Image"),
                              ("/camera/color/camera_info", "sensor_msgs/msg/CameraInfo")]
    assert _topics(depth)[1] == ("/camera/depth/camera_info", "sensor_msgs/msg/CameraInfo")


def test_the_text_view_says_where_the_gz_topics_come_from():
    result = run_servicebot("inspect", LEO, "--section", "sensors", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert "camera/image_raw, /camera/camera_info" in result.stdout
    assert "topics from" in result.stdout
    assert "None x None" not in run_servicebot("inspect", D435, "--section", "sensors",
                                               env=NO_ROS).stdout
