"""A sensor plugin's topic under a namespace written absolute is absolute.

Nav2's sam_bot: the IMU plugin's <ros><namespace>/demo</namespace> and '~/out:=imu' were
listed as 'demo/imu', where the model plugins in the same namespace (p3d) were '/demo/...'.
"""

from __future__ import annotations

import json

_ROBOT = ('<robot name="r"><link name="base_link"/><link name="imu_link"/><joint name="j" '
          'type="fixed"><parent link="base_link"/><child link="imu_link"/></joint>'
          '<gazebo reference="imu_link"><sensor name="imu" type="imu"><plugin name="p" '
          'filename="libgazebo_ros_imu_sensor.so"><ros>{namespace}<remapping>~/out:=imu'
          "</remapping></ros></plugin><update_rate>100</update_rate></sensor></gazebo></robot>")


def _topics(run, tmp_path, namespace: str) -> list[str]:
    path = tmp_path / "r.urdf"
    path.write_text(_ROBOT.format(namespace=namespace))
    result = run("inspect", path, "--format", "json")
    assert result.exit_code == 0, result.output
    (sensor,) = json.loads(result.stdout)["sensors"]
    return [topic["name"] for topic in sensor["topics"]]


def test_an_absolute_namespace_gives_an_absolute_topic(run, tmp_path):
    assert _topics(run, tmp_path, "<namespace>/demo</namespace>") == ["/demo/imu"]


def test_without_a_namespace_the_topic_stays_relative(run, tmp_path):
    assert _topics(run, tmp_path, "") == ["imu"]
