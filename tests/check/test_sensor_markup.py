"""SB502 for a sensor Gazebo does not create: no name, a type in the wrong case; and a range
minimum that is no number said as such.

A <sensor> without its required name fails sdformat's load; Gazebo Classic's sensor factory
looks 'RAY' up as written and makes nothing, so /scan was missing from a run check passed.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="r">
  <link name="base_link"/><link name="laser"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="laser"/></joint>
  <gazebo reference="laser"><sensor {sensor}><update_rate>10</update_rate>
    <ray><scan><horizontal><samples>360</samples><min_angle>-3</min_angle><max_angle>3</max_angle>
    </horizontal></scan><range><min>{near}</min><max>10</max></range></ray>
    <plugin name="p" filename="libgazebo_ros_ray_sensor.so"/></sensor></gazebo>
</robot>
"""


@pytest.mark.parametrize(("sensor", "near", "said"), [
    ('name="lidar" type="ray"', "0.1", None),
    ('type="ray"', "0.1", "a <sensor> without a name, which sdformat requires: Gazebo does "
     "not load it"),
    ('name="lidar" type="RAY"', "0.1", "type 'RAY': Gazebo looks sensor types up as written, "
     "in lower case ('ray'), and creates no sensor of this one"),
    ('name="lidar" type="ray"', "nan", "range min is not a number"),
])
def test_a_sensor_gazebo_does_not_create_is_sb502(tmp_path, sensor, near, said):
    robot = tmp_path / "r.urdf"
    robot.write_text(ROBOT.format(sensor=sensor, near=near))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB502")
    found = [(f["severity"], f["message"].split("': ", 1)[1]) for f in findings(result.stdout)]
    assert found == ([("error", said)] if said else [])


@pytest.mark.parametrize("block", ['<gazebo reference="">', "<gazebo>"])
def test_a_sensor_in_a_block_that_names_no_link_is_made_by_no_one(tmp_path, block):
    """sdformat puts a <gazebo> block without a link into the model, which holds no sensor:
    check passed it, inspect listed its topics and simulate dropped it without a word."""
    robot = tmp_path / "r.urdf"
    robot.write_text(ROBOT.format(sensor='name="lidar" type="ray"', near="0.1")
                     .replace('<gazebo reference="laser">', block))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB502")
    ((severity, message),) = [(f["severity"], f["message"]) for f in findings(result.stdout)]
    assert severity == "warning" and "is in a <gazebo> block that names no link" in message
    from tests.conftest import SIM_URDF

    robot.write_text(SIM_URDF.read_text().replace('<gazebo reference="imu_link">', block))
    noted = run_servicebot("simulate", robot, "--headless", "--duration-s", "0.1")
    assert noted.returncode == 0, noted.stderr
    assert "is not simulated: its <gazebo> block names no link" in noted.stderr


@pytest.mark.parametrize(("block", "said"), [
    ("<gazebo>", "its <gazebo> block names no link"),
    ('<gazebo reference="no_such_link">', "its <gazebo> block names 'no_such_link', no link or "
     "joint of the robot")])
def test_inspect_lists_no_topic_of_a_sensor_gazebo_does_not_make(tmp_path, block, said):
    """inspect listed the topics of such a sensor as published."""
    import json

    robot = tmp_path / "r.urdf"
    robot.write_text(ROBOT.format(sensor='name="lidar" type="ray"', near="0.1")
                     .replace('<gazebo reference="laser">', block))
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json")
    topics = json.loads(result.stdout)["topics"]
    assert topics["topics"] == []
    assert [note for note in topics["notes"] if note.startswith("sensor 'lidar' publishes "
                                                                 f"nothing: {said}")]
