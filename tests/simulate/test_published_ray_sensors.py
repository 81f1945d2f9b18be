"""Only a ray sensor published on ROS gives scans: the topics ``inspect`` lists, no others.

A Gazebo Classic ray sensor publishes on ROS only through a ROS plugin (gz-sim's through its
``<topic>``); one with neither, like a kobuki's cliff sensor, publishes nothing. Nav2's
sam_bot, edited one tag at a time, read back from the bag by rosbags and from ``--out``.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, bag_messages, edited

SCAN = "sensor_msgs/msg/LaserScan"
NO_PLUGIN = (('<plugin name="scan" filename="libgazebo_ros_ray_sensor.so">',
              '<!-- <plugin name="scan" filename="libgazebo_ros_ray_sensor.so">'),
             ("<frame_name>lidar_link</frame_name>\n      </plugin>",
              "<frame_name>lidar_link</frame_name>\n      </plugin> -->"))
CLIFF = ('<gazebo reference="lidar_link">',
         '<gazebo reference="base_link"><sensor name="cliff" type="ray">'
         "<update_rate>50</update_rate><ray><scan><horizontal><samples>1000</samples>"
         "<min_angle>-0.04</min_angle><max_angle>0.04</max_angle></horizontal></scan>"
         "<range><min>0.01</min><max>0.15</max></range></ray></sensor></gazebo>\n"
         '  <gazebo reference="lidar_link">')


def _scan_topics(robot: Path, tmp_path: Path) -> tuple[dict[str, list], dict, set[str]]:
    """The bag's LaserScan topics and their messages, the summary, the CSV files."""
    out = tmp_path / "out"
    messages = bag_messages(robot, tmp_path, "--out", out)
    scans = {topic: m for topic, m in messages.items()
             if type(m[0]).__name__.endswith("LaserScan")}
    summary = json.loads((out / "summary.json").read_text())
    return scans, summary, {p.name for p in out.iterdir()}


def _listed_scans(robot: Path) -> set[str]:
    """``inspect --section topics``: the LaserScan topics, absolute (a root node's names)."""
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return {"/" + t["name"].lstrip("/") for t in json.loads(result.stdout)["topics"]["topics"]
            if t["message"] == SCAN}


def test_a_ray_sensor_without_a_ros_plugin_publishes_no_scan(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, *NO_PLUGIN)
    assert _listed_scans(robot) == set()
    scans, summary, files = _scan_topics(robot, tmp_path)
    assert scans == {}
    assert not any("scan" in topic for topic in summary["messages"])
    assert "scan.csv" not in files


def test_a_cliff_sensor_with_more_rays_is_not_the_published_lidar(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, CLIFF)
    listed = _listed_scans(robot)
    scans, summary, files = _scan_topics(robot, tmp_path)
    assert set(scans) == listed == {"/scan"}
    assert len(scans["/scan"][0].ranges) == 360  # the LIDAR's, not the cliff sensor's 1000
    assert summary["messages"]["/scan"] == len(scans["/scan"]) == 10  # 2 s at 5 Hz
    assert "scan.csv" in files
