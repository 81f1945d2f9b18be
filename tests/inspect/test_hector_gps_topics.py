"""inspect lists hector_gazebo_plugins' GPS topics, as its IMU's.

moose's description mounts libhector_gazebo_ros_gps.so with <topicName>/navsat/fix and
<velocityTopicName>/navsat/vel: inspect showed its parameters and none of the two topics
(hector's gazebo_ros_gps.cpp publishes NavSatFix on the one, Vector3Stamped on the other).
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_servicebot

GPS = ('<robot name="r"><link name="base_link"/><gazebo><plugin name="gps_controller" '
       'filename="libhector_gazebo_ros_gps.so">{params}<bodyName>base_link</bodyName>'
       '</plugin></gazebo></robot>')


@pytest.mark.parametrize(("params", "expected"), [
    ("<topicName>/navsat/fix</topicName><velocityTopicName>/navsat/vel</velocityTopicName>",
     {"/navsat/fix": "sensor_msgs/msg/NavSatFix",
      "/navsat/vel": "geometry_msgs/msg/Vector3Stamped"}),
    ("<robotNamespace>moose</robotNamespace>",  # hector's defaults, in the namespace
     {"/moose/fix": "sensor_msgs/msg/NavSatFix",
      "/moose/fix_velocity": "geometry_msgs/msg/Vector3Stamped"})])
def test_the_gps_topics_are_listed(tmp_path, params, expected):
    path = tmp_path / "r.urdf"
    path.write_text(GPS.format(params=params))
    result = run_servicebot("inspect", path, "--section", "topics", "--format", "json")
    assert result.returncode == 0, result.stderr
    topics = {t["name"]: t["message"] for t in json.loads(result.stdout)["topics"]["topics"]
              if t["provider"] == "gps_controller"}
    assert topics == expected
