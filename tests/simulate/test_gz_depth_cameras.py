"""gz-sim's depth and RGBD cameras: the depth image on gz-sensors' topics, 32FC1.

A gz ``depth_camera`` publishes its depth image (R_FLOAT32, bridged as 32FC1) on its
``<topic>`` and its points on ``TOPIC/points`` (DepthCameraSensor.cc); an ``rgbd_camera``
publishes ``TOPIC/image``, ``TOPIC/depth_image``, ``TOPIC/points`` and ``TOPIC/camera_info``
(RgbdCameraSensor.cc). simulate wrote colour pixels on a depth camera's topic and its depth
on gazebo_ros_camera's ``depth/image_raw``, which gz never publishes and inspect did not
list. Leo Rover's camera (``tests/fixtures/leo_description``, MIT) made each kind, read
back with rosbags.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import REPO, run_servicebot
from tests.simulate.helpers import DRIVE_ONLY, NO_ROS
from tests.simulate.plugin_robots import edited

LEO = REPO / "tests" / "fixtures" / "leo_description" / "urdf" / "leo_sim.urdf.xacro"
CAMERA = '<sensor name="camera" type="camera">'


def _leo(tmp_path: Path, kind: str) -> Path:
    return edited(LEO, tmp_path / "robot", (CAMERA, f'<sensor name="camera" type="{kind}">'),
                  file="macros.xacro")


def _listed(robot: Path) -> list[tuple[str, str]]:
    result = run_servicebot("inspect", robot, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    (camera,) = [s for s in json.loads(result.stdout)["sensors"] if s["name"] == "camera"]
    return [(t["name"], t["message"]) for t in camera["topics"]]


def _images(robot: Path, tmp_path: Path, *extra: str) -> dict[str, object]:
    """The last image of each Image topic of a 1 s run, by topic."""
    pytest.importorskip("rosbags")
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    scenario, bag = tmp_path / "drive.yaml", tmp_path / "bag"
    scenario.write_text(DRIVE_ONLY)
    result = run_servicebot("simulate", robot, "--headless", "-s", scenario, "--duration-s", "1",
                            "--camera-scale", "0.05", "--camera-rate-hz", "5", "--bag", bag,
                            *extra, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    store, last = get_typestore(Stores.ROS2_HUMBLE), {}
    with Reader(bag) as reader:
        for connection, _, raw in reader.messages():
            if connection.msgtype == "sensor_msgs/msg/Image":
                last[connection.topic] = store.deserialize_cdr(raw, connection.msgtype)
    return last


def test_a_depth_cameras_topic_carries_its_depth(tmp_path):
    robot = _leo(tmp_path, "depth_camera")
    assert _listed(robot) == [("/camera/image_raw", "sensor_msgs/msg/Image"),
                              ("/camera/camera_info", "sensor_msgs/msg/CameraInfo"),
                              ("/camera/image_raw/points", "sensor_msgs/msg/PointCloud2")]
    images = _images(robot, tmp_path)  # no --camera-depth: its one image is its depth
    assert list(images) == ["/camera/image_raw"]
    depth = images["/camera/image_raw"]
    assert (depth.encoding, depth.width, depth.height, depth.step) == ("32FC1", 32, 24, 128)
    values = np.frombuffer(bytes(depth.data), "<f4")
    assert np.all((values > 0.2) | np.isinf(values))  # metres beyond the near clip, or none


def test_an_rgbd_camera_publishes_colour_and_depth_on_gz_topics(tmp_path):
    robot = _leo(tmp_path, "rgbd_camera")
    assert _listed(robot) == [("/camera/image_raw/image", "sensor_msgs/msg/Image"),
                              ("/camera/image_raw/camera_info", "sensor_msgs/msg/CameraInfo"),
                              ("/camera/image_raw/depth_image", "sensor_msgs/msg/Image"),
                              ("/camera/image_raw/points", "sensor_msgs/msg/PointCloud2")]
    images = _images(robot, tmp_path, "--camera-depth")
    assert {topic: image.encoding for topic, image in images.items()} == {
        "/camera/image_raw/image": "rgb8", "/camera/image_raw/depth_image": "32FC1"}
