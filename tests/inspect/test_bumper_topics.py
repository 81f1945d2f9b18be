"""gazebo_ros_bumper's topic: hyq's eight foot contacts were listed with no topic at all.

gazebo_plugins' gazebo_ros_bumper.cpp publishes gazebo_msgs/msg/ContactsState on
``bumper_states`` in the plugin's namespace (ROS 2, remappable), or on ``<bumperTopicName>``
(ROS 1, as hyq-description writes it).
"""

from __future__ import annotations

import json

import pytest

HEAD = ('<robot name="b"><link name="base"><inertial><mass value="1"/><inertia ixx="0.01" '
        'iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry>'
        '<sphere radius="0.1"/></geometry></collision></link><gazebo reference="base">')


def _contact(name: str, plugin: str) -> str:
    return (f'<sensor name="{name}" type="contact"><update_rate>250</update_rate><contact>'
            f'<collision>base_collision</collision></contact><plugin filename='
            f'"libgazebo_ros_bumper.so" name="{name}_plugin">{plugin}</plugin></sensor>')


@pytest.mark.parametrize(("plugin", "topic"), [
    ("<ros><namespace>/b</namespace></ros><frame_name>base</frame_name>", "/b/bumper_states"),
    ("<ros><namespace>/b</namespace><remapping>bumper_states:=foot_bumper</remapping></ros>",
     "/b/foot_bumper"),
    ("<bumperTopicName>/hyq/lf_foot_bumper</bumperTopicName><frameName>world</frameName>",
     "/hyq/lf_foot_bumper"),
])
def test_a_bumper_publishes_contacts_states_where_the_plugin_says(run, tmp_path, plugin, topic):
    path = tmp_path / "b.urdf"
    path.write_text(f"{HEAD}{_contact('foot', plugin)}</gazebo></robot>")
    result = run("inspect", path, "--section", "sensors", "--format", "json")
    assert result.exit_code == 0, result.output
    (sensor,) = json.loads(result.stdout)["sensors"]
    assert sensor["topics"] == [{"name": topic, "message": "gazebo_msgs/msg/ContactsState"}]
    listed = run("inspect", path, "--section", "topics").stdout
    assert f"{topic}  gazebo_msgs/msg/ContactsState  foot" in listed
