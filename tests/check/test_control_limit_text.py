"""SB512: command interface limits ros2_control cannot read, as real packages write them.

Interbotix's xsarm control.urdf.xacro writes ``<param name="min">"${waist_limit_lower}"</param>``:
xacro keeps the quotes, ros2_control logs "Error parsing the limits" and drops the limits.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

XACRO = """<?xml version="1.0"?>
<robot name="xsarm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="waist_limit_lower" value="${{-pi + 1e-5}}"/>
  <link name="base"/>
  <link name="shoulder">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="waist" type="revolute">
    <parent link="base"/><child link="shoulder"/><axis xyz="0 0 1"/>
    <limit lower="${{waist_limit_lower}}" upper="3.14" effort="10" velocity="1"/>
  </joint>
  <ros2_control name="XSHardwareInterface" type="system">
    <hardware><plugin>interbotix_xs_ros_control/XSHardwareInterface</plugin></hardware>
    <joint name="waist">
      <command_interface name="position">
        <param name="min">{minimum}</param>
        <param name="max">{maximum}</param>
      </command_interface>
      <state_interface name="position"/>
    </joint>
  </ros2_control>
</robot>
"""


def _limit_texts(run, tmp_path, minimum: str, maximum: str = "3.14") -> list[dict]:
    path = tmp_path / "xsarm.urdf.xacro"
    path.write_text(XACRO.format(minimum=minimum, maximum=maximum))
    result = run("check", path, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout  # a warning: the URDF limits still hold
    return [f for f in findings(result.stdout) if f["code"] == "SB512"]


def test_a_quoted_limit_from_xacro_is_no_number(run, tmp_path):
    (found,) = _limit_texts(run, tmp_path, '"${waist_limit_lower}"')
    assert found["severity"] == "warning" and found["line"] == 17, found
    assert "min '\"-3.141582653589793\"' is not a number" in found["message"]
    assert found["fix"] == "write -3.141582653589793, without the quotes"


@pytest.mark.parametrize("text", ["abc", "1,5", "0.5 rad", "٣", "--1"])
def test_words_units_and_commas_are_no_number(run, tmp_path, text):
    (found,) = _limit_texts(run, tmp_path, "-3", text)
    assert f"max '{text}' is not a number" in found["message"]


@pytest.mark.parametrize("text", ["${waist_limit_lower}", "-3", "+3", "-3.", ".5", "1e-3",
                                  "-inf", "  -3  "])
def test_numbers_are_left_to_sb508(run, tmp_path, text):
    assert _limit_texts(run, tmp_path, text) == []


def test_an_interface_name_with_a_quote_is_no_internal_error(run, tmp_path):
    """The <param> was found by an XPath built from the interface's name."""
    path = tmp_path / "xsarm.urdf.xacro"
    path.write_text(XACRO.format(minimum='"-3"', maximum="3").replace(
        '<command_interface name="position">', "<command_interface name=\"pos'ition\">"))
    result = run("check", path, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    assert {f["code"] for f in findings(result.stdout)} >= {"SB505", "SB512"}


@pytest.mark.parametrize("text", ["1e400", "-1e999"])
def test_a_number_beyond_a_double_is_no_limit(run, tmp_path, text):
    """Both of ros2_control's readers (istringstream, from_chars) fail out of range: 1e400
    passed as a number."""
    (found,) = _limit_texts(run, tmp_path, "-3", text)
    assert f"max '{text}' is beyond a double's range" in found["message"]
    assert found["fix"] == "write the limit, a finite number"


def test_a_negative_urdf_velocity_is_sb205s_not_a_range_the_command_leaves(run, tmp_path):
    """velocity="-3.14" in the URDF made SB508 read its range as [3.14, -3.14]."""
    path = tmp_path / "arm.urdf.xacro"
    path.write_text(XACRO.format(minimum="-3.14", maximum="3.14").replace(
        'velocity="1"', 'velocity="-3.14"').replace('name="position">\n        <param',
                                                    'name="velocity">\n        <param'))
    codes = [f["code"] for f in findings(run("check", path, "--format", "json",
                                             "--isolated").stdout)]
    assert "SB205" in codes and "SB508" not in codes
