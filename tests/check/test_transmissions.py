"""SB511 is an error only where a reader of transmissions in the file refuses the joint.

ROS 1's gazebo_ros_control (DefaultRobotHWSim) does not start on a single-joint transmission
with a hardware interface whose joint is not in the model; ros2_control refuses a component
whose nested transmission names none of its joints; top-level transmissions nobody in the
file reads (NASA Valkyrie's motor transmissions) are a warning.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

# Valkyrie's shape: a joint the URDF has, a pushrod transmission over two real joints, and a
# motor transmission per finger whose "joint" is a motor, not a URDF joint. No plugin.
VALKYRIE_LIKE = """<?xml version="1.0"?>
<robot name="valkyrie_like">
  <link name="palm"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="finger"><inertial><mass value="0.1"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <link name="tip"><inertial><mass value="0.1"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="indexPitch1" type="revolute">
    <parent link="palm"/><child link="finger"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="1" effort="10" velocity="1"/>
  </joint>
  <joint name="indexPitch2" type="revolute">
    <parent link="finger"/><child link="tip"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="1" effort="10" velocity="1"/>
  </joint>
  <transmission name="indexPushrodTransmission">
    <type>robot_transmission_interface::PushrodTransmissionLoader</type>
    <joint name="indexPitch1"><role>pitch1</role>
      <hardwareInterface>EffortJointInterface</hardwareInterface></joint>
    <joint name="indexPitch2"><role>pitch2</role>
      <hardwareInterface>EffortJointInterface</hardwareInterface></joint>
    <actuator name="indexActuator"><mechanicalReduction>1</mechanicalReduction></actuator>
  </transmission>
  <transmission name="indexMotorPitch1Transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="indexMotorPitch1">
      {interface}
    </joint>
    <actuator name="indexMotorPitch1">
      <node name="/hand/index"/>
      <mechanicalReduction>1</mechanicalReduction>
      <api name="robot_hardware_interface/MotorAPI"/>
    </actuator>
  </transmission>
  {extra}
</robot>
"""
EFFORT = "<hardwareInterface>EffortJointInterface</hardwareInterface>"
GAZEBO_ROS_CONTROL = """<gazebo>
    <plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">{sim}</plugin>
  </gazebo>"""


def _sb511(run, tmp_path, text: str) -> tuple[list[dict], int]:
    path = tmp_path / "hand.urdf"
    path.write_text(text)
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    return [f for f in findings(result.stdout) if f["code"] == "SB511"], result.exit_code


def test_motor_transmissions_nobody_in_the_file_reads_are_a_warning(run, tmp_path):
    found, exit_code = _sb511(run, tmp_path, VALKYRIE_LIKE.format(interface=EFFORT, extra=""))
    assert [f["severity"] for f in found] == ["warning"]
    assert "'indexMotorPitch1'" in found[0]["message"]
    assert "nothing in this file that reads transmissions refuses it" in found[0]["message"]
    assert exit_code == 0


def test_gazebo_ros_control_makes_it_an_error(run, tmp_path):
    text = VALKYRIE_LIKE.format(interface=EFFORT, extra=GAZEBO_ROS_CONTROL.format(sim=""))
    found, exit_code = _sb511(run, tmp_path, text)
    assert [f["severity"] for f in found] == ["error"]
    assert "gazebo_ros_control does not start with it" in found[0]["message"]
    assert exit_code == 1


@pytest.mark.parametrize(("interface", "sim"), [
    ("", ""),  # no hardware interface: the parser drops the joint, the simulation skips it
    (EFFORT, "<robotSimType>my_pkg/MyRobotHWSim</robotSimType>"),  # not the default reader
])
def test_gazebo_ros_control_that_skips_the_transmission_leaves_a_warning(run, tmp_path,
                                                                         interface, sim):
    text = VALKYRIE_LIKE.format(interface=interface, extra=GAZEBO_ROS_CONTROL.format(sim=sim))
    found, _ = _sb511(run, tmp_path, text)
    assert [f["severity"] for f in found] == ["warning"]


def test_ros2_control_ignores_top_level_transmissions(run, tmp_path):
    control = """<ros2_control name="hand" type="system">
    <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin></hardware>
    <joint name="indexPitch1"><command_interface name="effort"/></joint>
  </ros2_control>
  <gazebo><plugin name="gazebo_ros2_control" filename="libgazebo_ros2_control.so"/></gazebo>"""
    found, _ = _sb511(run, tmp_path, VALKYRIE_LIKE.format(interface=EFFORT, extra=control))
    assert [f["severity"] for f in found] == ["warning"]


def test_a_ros2_control_transmission_of_a_joint_outside_the_component_is_an_error(run,
                                                                                 tmp_path):
    control = """<ros2_control name="hand" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="indexPitch1"><command_interface name="effort"/></joint>
    <transmission name="t1"><plugin>transmission_interface/SimpleTransmission</plugin>
      <joint name="indexPitch1" role="joint1"/></transmission>
    <transmission name="t2"><plugin>transmission_interface/SimpleTransmission</plugin>
      <joint name="indexPitch2" role="joint1"/></transmission>
  </ros2_control>"""
    text = VALKYRIE_LIKE.format(interface=EFFORT, extra=control)
    found, exit_code = _sb511(run, tmp_path, text)
    nested = [f for f in found if "in ros2_control 'hand'" in f["message"]]
    assert [(f["severity"], "'indexPitch2'" in f["message"]) for f in nested] == [("error", True)]
    assert "ros2_control refuses the component" in nested[0]["message"]
    assert exit_code == 1


def test_explain_names_the_readers(run):
    explained = run("check", "--explain", "SB511").stdout
    assert "gazebo_ros_control" in explained and "DefaultRobotHWSim" in explained
    assert "ros2_control" in explained and "ignore top-level" in explained
