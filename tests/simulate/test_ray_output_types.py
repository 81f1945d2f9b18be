"""A ray sensor publishes the type its plugin names, filled as the plugin converts a scan.

gazebo_ros_pkgs' ROS 2 ``gazebo_ros_ray_sensor``: ``<output_type>`` LaserScan, PointCloud,
PointCloud2 (the default) or Range; any other, nothing. Nav2's sam_bot (LaserScan, 360 rays,
0.12-3.5 m) edited one tag at a time, run with the same seed, read back by rosbags: each
cloud's points are the scan's finite ranges at the rays' angles, in the sensor frame.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import (
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
    listed_topics,
)

OUTPUT = "<output_type>sensor_msgs/LaserScan</output_type>"
VERTICAL = ("</horizontal>\n        </scan>",
            "</horizontal>\n          <vertical><samples>3</samples><min_angle>-0.3</min_angle>"
            "<max_angle>0.3</max_angle></vertical>\n        </scan>")


def _output(tmp_path: Path, text: str, *more: tuple[str, str]) -> Path:
    return edited(SAM_BOT, tmp_path / "robot", (OUTPUT, text), *more)


def _listed(robot: Path) -> dict[str, str]:
    """``inspect --section topics``: the lidar's topics and their types."""
    return {t["name"]: t["message"] for t in listed_topics(robot) if t["provider"] == "lidar"}


def _scans(tmp_path: Path) -> list:
    """sam_bot's LaserScans, as written."""
    (tmp_path / "scan").mkdir()
    return bag_messages(SAM_BOT, tmp_path / "scan")["/scan"]


def _xyz(cloud) -> np.ndarray:
    """A PointCloud2's points, (N, 4): x, y, z, intensity."""
    assert [(f.name, f.offset, f.datatype, f.count) for f in cloud.fields] == [
        ("x", 0, 7, 1), ("y", 4, 7, 1), ("z", 8, 7, 1), ("intensity", 12, 7, 1)]
    assert (cloud.height, cloud.point_step, cloud.is_dense, cloud.is_bigendian) == \
        (1, 16, True, False)
    assert cloud.row_step == 16 * cloud.width == len(cloud.data)
    return np.frombuffer(bytes(cloud.data), dtype="<f4").reshape(-1, 4)


def _finite(scan) -> tuple[np.ndarray, np.ndarray]:
    """A LaserScan's finite ranges and their angles."""
    ranges = np.array(scan.ranges)
    angles = np.linspace(scan.angle_min, scan.angle_max, len(ranges))
    ok = np.isfinite(ranges)
    return ranges[ok], angles[ok]


def test_without_an_output_type_the_plugin_publishes_pointcloud2(tmp_path):
    pytest.importorskip("rosbags")
    robot = _output(tmp_path, "")
    assert _listed(robot) == {"scan": "sensor_msgs/msg/PointCloud2"}
    clouds, scans = bag_messages(robot, tmp_path)["/scan"], _scans(tmp_path)
    assert type(clouds[0]).__name__.endswith("PointCloud2") and len(clouds) == len(scans) == 10
    for cloud, scan in zip(clouds, scans, strict=True):
        assert cloud.header == scan.header  # stamp, and frame lidar_link
        points = _xyz(cloud)
        ranges, angles = _finite(scan)
        assert len(points) == len(ranges) > 0
        assert np.linalg.norm(points[:, :3], axis=1) == pytest.approx(ranges, abs=1e-5)
        assert np.arctan2(points[:, 1], points[:, 0]) % (2 * math.pi) == \
            pytest.approx(angles % (2 * math.pi), abs=1e-4)
        assert not points[:, 2].any() and not points[:, 3].any()  # level; no retro-reflector


def test_pointcloud_has_the_points_and_an_intensity_channel_floored(tmp_path):
    pytest.importorskip("rosbags")
    robot = _output(tmp_path, "<output_type>sensor_msgs/PointCloud</output_type>"
                    "<min_intensity>101.5</min_intensity>")
    assert _listed(robot) == {"scan": "sensor_msgs/msg/PointCloud"}
    cloud, scan = bag_messages(robot, tmp_path)["/scan"][-1], _scans(tmp_path)[-1]
    ranges, _ = _finite(scan)
    points = np.array([(p.x, p.y, p.z) for p in cloud.points])
    assert np.linalg.norm(points, axis=1) == pytest.approx(ranges, abs=1e-5)
    [channel] = cloud.channels
    assert channel.name == "intensity" and set(channel.values) == {101.5}


def test_range_is_the_least_ray_with_the_radiation_type_given(tmp_path):
    pytest.importorskip("rosbags")
    robot = _output(tmp_path, "<output_type>sensor_msgs/Range</output_type>"
                    "<radiation_type>ultrasound</radiation_type>")
    assert _listed(robot) == {"scan": "sensor_msgs/msg/Range"}
    ranges, scans = bag_messages(robot, tmp_path)["/scan"], _scans(tmp_path)
    for sonar, scan in zip(ranges, scans, strict=True):
        assert sonar.range == np.float32(np.min(scan.ranges))
        assert (sonar.radiation_type, sonar.min_range, sonar.max_range) == \
            (0, pytest.approx(0.12), pytest.approx(3.5))
        assert sonar.field_of_view == pytest.approx(6.28)  # the larger span, horizontal
    infrared = _output(tmp_path / "ir", "<output_type>sensor_msgs/Range</output_type>")
    assert bag_messages(infrared, tmp_path / "ir")["/scan"][0].radiation_type == 1


@pytest.mark.parametrize("text", [
    "<output_type>sensor_msgs/Image</output_type>",
    "<output_type>sensor_msgs/Range</output_type><radiation_type>radar</radiation_type>",
    "<output_type></output_type>",  # empty: the plugin logs it invalid
    "<output_type>sensor_msgs/Range</output_type><radiation_type/>"])
def test_an_output_the_plugin_refuses_publishes_nothing(tmp_path, text):
    pytest.importorskip("rosbags")
    robot = _output(tmp_path, text)
    assert _listed(robot) == {}
    assert "/scan" not in bag_messages(robot, tmp_path)


def test_several_rings_laserscan_is_the_middle_ring_and_the_cloud_has_them_all(tmp_path):
    pytest.importorskip("rosbags")
    scan = bag_messages(edited(SAM_BOT, tmp_path / "a", VERTICAL), tmp_path / "a")["/scan"][-1]
    level = _scans(tmp_path)[-1]
    assert len(scan.ranges) == 360
    both = np.isfinite(scan.ranges) & np.isfinite(level.ranges)
    assert np.array(scan.ranges)[both] == pytest.approx(np.array(level.ranges)[both], abs=0.06)
    robot = _output(tmp_path / "b", "", VERTICAL)
    points = _xyz(bag_messages(robot, tmp_path / "b")["/scan"][-1])
    up = np.arcsin(points[:, 2] / np.linalg.norm(points[:, :3], axis=1))
    assert set(np.round(up.astype(float), 3).tolist()) <= {-0.3, 0.0, 0.3}
    assert len(points) > both.sum()


def test_a_ros1_range_plugin_is_listed_as_range_and_not_written(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, ("libgazebo_ros_laser.so", "libgazebo_ros_range.so"),
                   file=TURTLEBOT3_GAZEBO)
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    rows = json.loads(result.stdout)["topics"]["topics"]
    assert {(t["name"], t["message"]) for t in rows if t["provider"] == "lds_lfcd_sensor"} == {
        ("scan", "sensor_msgs/msg/Range")}
    bag = tmp_path / "bag"
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1", "--bag", bag,
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert "note: /scan (sensor_msgs/msg/Range) is not published" in result.stderr


@pytest.mark.parametrize("plugin", ["libgazebo_ros_laser.so", "libgazebo_ros_gpu_laser.so"])
def test_ros1_laser_plugins_put_every_ring_in_their_laserscan(tmp_path, plugin):
    """noetic gazebo_ros_laser.cpp copies all of Gazebo's ranges and intensities, scan_time 0."""
    pytest.importorskip("rosbags")
    rings = ("</horizontal>\n        </scan>",
             "</horizontal>\n          <vertical><samples>3</samples><min_angle>-0.2"
             "</min_angle><max_angle>0.2</max_angle></vertical>\n        </scan>")
    robot = edited(TURTLEBOT3, tmp_path, rings, ("libgazebo_ros_laser.so", plugin),
                   file=TURTLEBOT3_GAZEBO)
    scan = bag_messages(robot, tmp_path)["/scan"][-1]
    assert len(scan.ranges) == len(scan.intensities) == 3 * 360
    assert scan.scan_time == 0.0
    assert (scan.angle_min, scan.angle_max) == (0.0, pytest.approx(6.28319))
    (tmp_path / "level").mkdir()
    level = bag_messages(TURTLEBOT3, tmp_path / "level")["/scan"][-1]
    middle, flat = np.array(scan.ranges[360:720]), np.array(level.ranges)
    both = np.isfinite(middle) & np.isfinite(flat)
    assert both.any() and middle[both] == pytest.approx(flat[both], abs=0.06)
