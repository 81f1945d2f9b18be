"""SB517: <ros2_control> markup ros2_control's component parser refuses, and SB515's mimic.

Each variant made parse_control_resources_from_urdf or the resource manager refuse the robot
(component_parser.cpp, resource_manager.cpp); check passed every one with no finding.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

_JOINT = ('<joint name="w" type="continuous"><parent link="base"/><child link="wheel"/>'
          '<axis xyz="0 1 0"/><limit effort="1" velocity="1"/></joint>')
_BLOCK = ('<ros2_control name="RobotSystem" type="system"><hardware><plugin>mock_components/'
          'GenericSystem</plugin><param name="rate">100</param></hardware><joint name="w">'
          '<command_interface name="velocity"/><state_interface name="velocity"/></joint>'
          "</ros2_control>")


def _found(run, tmp_path, block: str, extra: str = ""):
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="base"/><link name="wheel"/>{_JOINT}'
                    f"{block}{extra}</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB5")
    return [(f["code"], f["severity"], f["message"]) for f in findings(result.stdout)]


def test_the_plain_component_passes(run, tmp_path):
    assert _found(run, tmp_path, _BLOCK) == []


@pytest.mark.parametrize(("old", "new", "says"), [
    (' name="RobotSystem"', "", "<ros2_control> without a 'name' attribute"),
    (' type="system"', "", "<ros2_control> without a 'type' attribute"),
    ('<state_interface name="velocity"/>', "<state_interface/>",
     "<state_interface> of <joint name=\"w\"> has no 'name' attribute"),
    ('<param name="rate">', "<param>", "<param> of <hardware> has no 'name' attribute"),
    ('<joint name="w">', "<joint>", "<joint> has no 'name' attribute"),
    ('type="system"', 'type="sytem"', 'type="sytem">: ros2_control_node loads only'),
])
def test_markup_the_parser_refuses_is_an_error(run, tmp_path, old, new, says):
    found = _found(run, tmp_path, _BLOCK.replace(old, new, 1))
    assert any(code == "SB517" and severity == "error" and says in message
               for code, severity, message in found), found


def test_two_components_of_one_name(run, tmp_path):
    second = _BLOCK.replace('<joint name="w">', '<joint name="other">')
    found = _found(run, tmp_path, _BLOCK, second)
    assert ("SB517", "error") in {(code, severity) for code, severity, _ in found}


def test_an_unknown_type_where_gazebo_loads_it_is_a_warning(run, tmp_path):
    plugin = ('<gazebo><plugin filename="libgz_ros2_control-system.so" name="gz_ros2_control::'
              'GazeboSimROS2ControlPlugin"/></gazebo>')
    found = _found(run, tmp_path, _BLOCK.replace('type="system"', 'type="sytem"'), plugin)
    assert [(c, s) for c, s, _ in found if c == "SB517"] == [("SB517", "warning")]


def test_a_mimic_attribute_that_is_no_boolean(run, tmp_path):
    found = _found(run, tmp_path, _BLOCK.replace('<joint name="w">',
                                                 '<joint name="w" mimic="yes">'))
    assert any(code == "SB515" and 'mimic="yes": ros2_control reads only true or false' in m
               for code, _, m in found), found


def test_an_interface_name_with_a_trailing_blank_says_which_releases_read_it(run, tmp_path):
    found = _found(run, tmp_path, _BLOCK.replace('<command_interface name="velocity"/>',
                                                 '<command_interface name="velocity "/>'))
    ((code, severity, message),) = found
    assert (code, severity) == ("SB505", "warning")
    assert "has blanks around its name: Jazzy and later strip them, Humble" in message
