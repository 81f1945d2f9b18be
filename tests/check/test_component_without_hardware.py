"""SB509 for a ros2_control component without ``<hardware>`` in a simulated robot: a warning.

ROBOTIS's OMY arms wrap their end unit's ``<hardware>`` in ``xacro:unless use_sim``, so in
simulation the component keeps only its GPIOs. ros2_control's parser reads a component with
no ``<hardware>`` (its plugin name empty); gz_ros2_control then fails to load that one
plugin, logs it and runs the others. A ``<hardware>`` without ``<plugin>`` is refused by the
parser, for the whole robot: an error with or without a simulator, as is a component without
hardware that ros2_control_node alone would load.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"/>
  <link name="link1">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0"
      izz="0.01"/></inertial>
  </link>
  <joint name="joint1" type="revolute"><parent link="base_link"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <ros2_control name="ArmSystem" type="system">
    <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
    <joint name="joint1"><command_interface name="position"/>
      <state_interface name="position"/></joint>
  </ros2_control>
  <ros2_control name="EndUnitSystem" type="system">
    HARDWARE<gpio name="end"><command_interface name="led"/></gpio>
  </ros2_control>
  SIMULATOR
</robot>
"""
GZ = ('<gazebo><plugin filename="gz_ros2_control-system" '
      'name="gz_ros2_control::GazeboSimROS2ControlPlugin"/></gazebo>')


@pytest.mark.parametrize(("hardware", "simulator", "severity"), [
    ("", GZ, "warning"), ("", "", "error"), ("<hardware/>", GZ, "error")])
def test_only_a_simulated_component_without_hardware_is_a_warning(
        tmp_path, hardware, simulator, severity):
    robot = tmp_path / "arm.urdf"
    robot.write_text(ROBOT.replace("HARDWARE", hardware).replace("SIMULATOR", simulator))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB509")
    (found,) = findings(result.stdout)
    assert found["severity"] == severity and "EndUnitSystem" in found["message"]
    assert ("gz_ros2_control-system skips it" in found["message"]) == (severity == "warning")
