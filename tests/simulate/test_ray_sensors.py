"""Ray sensors that are not the LIDAR, and a LIDAR of one ray, in a run with a bag.

A Create 3 base (TurtleBot 4's) declares one-ray cliff sensors before its LIDAR: each is
simulated on its own topic, and the LIDAR (the ray sensor with the most rays, wherever it
stands in the file) keeps ``/scan`` and its 360 rays. A one-ray scan is
still a sequence of one float in the bag (it was a numpy broadcast error, exit 3). The bag is
read back with rosbags, which shares no code with servicebot's writer.
"""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from tests.conftest import REPO, run_servicebot

BUNDLED = REPO / "robots" / "service_robot.urdf.xml"
CLIFF = """
  <gazebo reference="base_link">
    <sensor name="cliff_front" type="ray">
      <update_rate>62</update_rate>
      <ray>
        <scan><horizontal><samples>1</samples><resolution>1</resolution>
          <min_angle>0</min_angle><max_angle>0</max_angle></horizontal></scan>
        <range><min>0.01</min><max>0.15</max></range>
      </ray>
      <plugin name="cliff_front" filename="libgazebo_ros_ray_sensor.so"/>
    </sensor>
  </gazebo>
"""


def _robot(directory: Path, text: str) -> Path:
    shutil.copy(BUNDLED.with_name("controllers.yaml"), directory / "controllers.yaml")
    path = directory / "robot.urdf"
    path.write_text(text)
    return path


def _scans(bag: Path) -> list:
    pytest.importorskip("rosbags")
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader(bag) as reader:
        return [store.deserialize_cdr(raw, c.msgtype) for c, _, raw in reader.messages()
                if c.msgtype == "sensor_msgs/msg/LaserScan"]


def test_a_cliff_sensor_before_the_lidar_publishes_beside_it(tmp_path):
    text = BUNDLED.read_text()
    robot = _robot(tmp_path, re.sub(r"(<robot [^>]*>)", lambda m: m.group(1) + CLIFF, text,
                                    count=1))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "2", "--bag",
                            tmp_path / "bag", "--format", "json")
    assert result.returncode == 0, result.stderr
    messages = json.loads(result.stdout)["messages"]
    assert messages["/scan"] == 20  # the LIDAR's 10 Hz
    assert messages["/cliff_front/out"] == 124  # the cliff sensor's 62 Hz, its plugin's ~/out
    scans = _scans(tmp_path / "bag")  # the cliff sensor's are PointCloud2, the plugin's default
    assert {len(s.ranges) for s in scans} == {360}


def test_a_lidar_of_one_ray_is_written_to_the_bag(tmp_path):
    text = BUNDLED.read_text().replace("<samples>360</samples>", "<samples>1</samples>")
    text = re.sub(r"<max_angle>[^<]*</max_angle>", "<max_angle>0</max_angle>", text, count=1)
    robot = _robot(tmp_path, text)
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "2", "--bag",
                            tmp_path / "bag")
    assert result.returncode == 0, result.stderr
    scans = _scans(tmp_path / "bag")
    assert len(scans) == 20
    assert all(len(s.ranges) == 1 and s.angle_min == s.angle_max == 0.0 for s in scans)
    assert all(0.1 <= s.ranges[0] <= 12.0 for s in scans)  # the room's wall, within range
