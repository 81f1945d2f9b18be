"""simulate on a gz-sim description: the bag's sensor topics are the gz topics, no ROS set.

Leo Rover (``tests/fixtures/leo_description``, MIT) has a camera on ``<topic>camera/image_raw``
and an IMU on ``imu/data_raw``, with no ROS plugin: ros_gz_bridge shows them as
``/camera/image_raw``, ``/camera/camera_info`` (gz-sensors puts the info beside the image) and
``/imu/data_raw``. The bag is read back with rosbags, which shares no code with the writer.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from tests.conftest import REPO, run_servicebot
from tests.simulate.helpers import DRIVE_ONLY, NO_ROS

LEO = REPO / "tests" / "fixtures" / "leo_description" / "urdf" / "leo_sim.urdf.xacro"


def test_leo_bag_has_the_camera_info_beside_the_image_and_the_imu_on_its_topic(tmp_path):
    pytest.importorskip("rosbags")
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    scenario, bag = tmp_path / "drive.yaml", tmp_path / "bag"
    scenario.write_text(DRIVE_ONLY)
    result = run_servicebot("simulate", LEO, "--headless", "-s", scenario, "--duration-s", "1",
                            "--camera-scale", "0.05", "--camera-rate-hz", "5", "--bag", bag,
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    store = get_typestore(Stores.ROS2_HUMBLE)
    last, types = {}, {}
    with Reader(Path(bag)) as reader:
        for connection, _, raw in reader.messages():
            types[connection.topic] = connection.msgtype
            last[connection.topic] = store.deserialize_cdr(raw, connection.msgtype)
    assert types["/camera/image_raw"] == "sensor_msgs/msg/Image"
    assert types["/camera/camera_info"] == "sensor_msgs/msg/CameraInfo"
    assert types["/imu/data_raw"] == "sensor_msgs/msg/Imu"
    info = last["/camera/camera_info"]
    assert info.header.frame_id == "camera_frame"
    assert (info.width, info.height) == (32, 24)  # 640 x 480 at 0.05
    assert last["/imu/data_raw"].header.frame_id == "imu_frame"


D435 = REPO / "tests" / "fixtures" / "d435_on_a_box" / "robot.urdf.xacro"


def test_a_camera_without_size_or_field_of_view_takes_sdf_defaults_as_gazebo_does(tmp_path):
    """Husarion's D435 colour camera puts <image> and <horizontal_fov> outside <camera>."""
    pytest.importorskip("rosbags")
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    bag = tmp_path / "bag"
    result = run_servicebot("simulate", D435, "--headless", "--duration-s", "1", "--bag", bag,
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader(Path(bag)) as reader:
        infos = [store.deserialize_cdr(raw, c.msgtype) for c, _, raw in reader.messages()
                 if c.topic == "/camera/color/camera_info"]
    assert len(infos) == 30  # 30 Hz for 1 s
    info = infos[-1]
    assert (info.width, info.height) == (320, 240)
    assert info.header.frame_id == "camera_color_optical_frame"
    assert info.k[0] == pytest.approx(320 / (2 * math.tan(1.047 / 2)))
