"""velodyne_simulator's Gazebo plugin: a PointCloud2 of rings, within the plugin's own band.

autoware's and tier4's sensor kits mount their lidars with ``libgazebo_ros_velodyne_laser.so``.
inspect and simulate took it for a LaserScan plugin: they listed and recorded ``LaserScan``,
with the ray's range (0.3-131 m where the plugin keeps 0.9-130 m) and without the plugin's
``<gaussian_noise>``. The plugin (``GazeboRosVelodyneLaser.cpp``) publishes PointCloud2 of
``x y z intensity ring time`` (22 bytes a point), column after column, and keeps the ranges
strictly between ``max(<min_range>, ray min)`` and ``min(<max_range>, ray max)``. nav2's
sam_bot, its lidar's plugin swapped for Velodyne's, is run and read back by rosbags.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, bag_messages, edited, listed_topics

PLUGIN = ('<plugin name="scan" filename="libgazebo_ros_ray_sensor.so">',
          '<plugin name="scan" filename="libgazebo_ros_velodyne_laser.so"><min_range>0.5'
          '</min_range><max_range>3.0</max_range><gaussian_noise>0.02</gaussian_noise>')
NO_OUTPUT_TYPE = ("<output_type>sensor_msgs/LaserScan</output_type>", "")
RINGS = ("</horizontal>\n        </scan>",
         "</horizontal>\n          <vertical><samples>3</samples><min_angle>-0.2</min_angle>"
         "<max_angle>0.2</max_angle></vertical>\n        </scan>")


def _velodyne(tmp_path):
    return edited(SAM_BOT, tmp_path / "robot", PLUGIN, NO_OUTPUT_TYPE, RINGS)


def test_inspect_lists_a_cloud_in_the_plugins_band_with_its_noise(tmp_path):
    robot = _velodyne(tmp_path)
    assert {t["name"]: t["message"] for t in listed_topics(robot)
            if t["provider"] == "lidar"} == {"scan": "sensor_msgs/msg/PointCloud2"}
    result = run_servicebot("inspect", robot, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    (lidar,) = [s for s in json.loads(result.stdout)["sensors"] if s["name"] == "lidar"]
    text = json.dumps(lidar)
    assert '"min_range_m": 0.5' in text and '"max_range_m": 3.0' in text, text
    assert f'"stddev": {math.hypot(0.01, 0.02)}' in text, text  # the ray's and the plugin's


def test_simulate_records_the_plugins_pointcloud2(tmp_path):
    pytest.importorskip("rosbags")
    clouds = bag_messages(_velodyne(tmp_path), tmp_path)["/scan"]
    assert type(clouds[0]).__name__.endswith("PointCloud2") and len(clouds) == 10  # 5 Hz, 2 s
    points = 0
    for cloud in clouds:
        assert [(f.name, f.offset, f.datatype, f.count) for f in cloud.fields] == [
            ("x", 0, 7, 1), ("y", 4, 7, 1), ("z", 8, 7, 1), ("intensity", 12, 7, 1),
            ("ring", 16, 4, 1), ("time", 18, 7, 1)]
        assert (cloud.height, cloud.point_step, cloud.is_dense) == (1, 22, True)
        assert cloud.row_step == 22 * cloud.width == len(cloud.data)
        assert cloud.header.frame_id == "lidar_link"
        record = np.dtype([("xyz", "<f4", 3), ("intensity", "<f4"), ("ring", "<u2"),
                           ("time", "<f4")])
        data = np.frombuffer(bytes(cloud.data), record)
        ranges = np.linalg.norm(data["xyz"].astype(np.float64), axis=1)
        assert np.all((ranges > 0.5 - 1e-6) & (ranges < 3.0 + 1e-6))
        assert set(data["ring"].tolist()) <= {0, 1, 2}
        inclination = np.arcsin(data["xyz"][:, 2] / ranges)
        assert inclination == pytest.approx(-0.2 + 0.2 * data["ring"], abs=1e-5)
        azimuth = np.arctan2(data["xyz"][:, 1], data["xyz"][:, 0]) % (2 * math.pi)
        assert np.all(np.diff(azimuth) >= -1e-5)  # column after column, as the plugin writes
        points += len(data)
    assert points > 0


@pytest.mark.parametrize(("band", "kept"), [
    ("<min_range>0.5</min_range><max_range>abc</max_range>", "between 0.5 and 0 m"),
    ("<min_range>5</min_range><max_range>1</max_range>", "between 5 and 1 m")])
def test_a_band_that_keeps_no_point_is_said_as_the_plugins(tmp_path, band, kept):
    """sdformat reads <max_range>abc as 0 (Get<double> fails and leaves 0): the plugin keeps
    no point, where check passed it and simulate wrote full clouds; an inverted band was
    said as the ray's own range ('range min 5 m must be below range max 1 m')."""
    robot = edited(SAM_BOT, tmp_path / "robot", (PLUGIN[0], PLUGIN[1].replace(
        "<min_range>0.5</min_range><max_range>3.0</max_range>", band)), NO_OUTPUT_TYPE, RINGS)
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB502", env=NO_ROS)
    (finding,) = json.loads(result.stdout)["files"][0]["findings"]
    assert f"its Velodyne plugin keeps the ranges {kept}" in finding["message"]
    assert "must be below range max" not in finding["message"]
