"""Mesh wheels that a Gazebo diff-drive plugin names make a differential drive.

A link gives no radius when its wheel is a mesh; the plugin that Gazebo drives the robot
with names the wheel joints and their diameter (Classic, ROS 1 and ROS 2) or radius (gz-sim).
"""

from __future__ import annotations

import json

import pytest

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.drive_geometry import drive_geometry

WHEELS = "".join(
    f'<link name="{side}_wheel"><visual><geometry><mesh filename="wheel.stl"/></geometry>'
    f'</visual><inertial><mass value="0.5"/><inertia ixx="1e-3" ixy="0" ixz="0" iyy="1e-3" '
    f'iyz="0" izz="1e-3"/></inertial></link><joint name="{side}_wheel_joint" '
    f'type="continuous"><parent link="base_link"/><child link="{side}_wheel"/><origin '
    f'xyz="0 {y} 0.07" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/><limit effort="5" '
    f'velocity="8"/></joint>' for side, y in (("left", 0.2), ("right", -0.2)))
ROBOT = ('<robot name="r"><link name="base_link"><inertial><mass value="5"/><inertia '
         'ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>'
         f'{WHEELS}<gazebo>{{plugin}}</gazebo></robot>')
PLUGINS = {
    "classic ROS 1": '<plugin name="d" filename="libgazebo_ros_diff_drive.so"><leftJoint>'
                     'left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>'
                     '<wheelDiameter>0.14</wheelDiameter></plugin>',
    "classic ROS 2": '<plugin name="d" filename="libgazebo_ros_diff_drive.so"><ros>'
                     '<namespace>/</namespace></ros><left_joint>left_wheel_joint</left_joint>'
                     '<right_joint>right_wheel_joint</right_joint><wheel_diameter>0.14'
                     '</wheel_diameter></plugin>',
    "gz sim": '<plugin name="gz::sim::systems::DiffDrive" filename="gz-sim-diff-drive-system">'
              '<left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint'
              '</right_joint><wheel_radius>0.07</wheel_radius></plugin>',
}


def _geometry(tmp_path, plugin: str):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(plugin=plugin))
    return drive_geometry(load(RobotSource(path, str(path)), build_model=False))


@pytest.mark.parametrize("kind", PLUGINS)
def test_the_plugin_names_the_wheels_and_their_size(tmp_path, kind):
    drive = _geometry(tmp_path, PLUGINS[kind])
    assert (drive.left, drive.right) == (("left_wheel_joint",), ("right_wheel_joint",))
    assert (drive.wheel_radius_m, drive.track_m) == pytest.approx((0.07, 0.4))
    assert drive.max_wheel_speed_rad_s == 8


def test_without_a_plugin_or_a_size_mesh_wheels_are_no_drive(tmp_path):
    with pytest.raises(DescriptionError, match="not a differential drive"):
        _geometry(tmp_path, "")
    with pytest.raises(DescriptionError, match="not a differential drive"):
        _geometry(tmp_path, PLUGINS["classic ROS 1"].replace("0.14", "fourteen"))


def test_inspect_counts_the_plugins_wheels_as_wheels(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(plugin=PLUGINS["gz sim"]))
    result = run("inspect", path, "--section", "totals", "--format", "json")
    dof = json.loads(result.stdout)["totals"]["dof"]
    assert (dof["wheels"], dof["arm"]) == (2, 0), dof
