"""A ``.xacro.urdf`` file is xacro input, as gz_ros2_control_demos' launch files use it."""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import REPO

DEMOS = REPO / "tests" / "realworld" / "ws" / "src" / "gz_ros2_control_demos"
PENDULUM = DEMOS / "urdf" / "test_pendulum_effort.xacro.urdf"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def test_a_xacro_urdf_file_is_expanded_and_has_no_false_error(run):
    # cart_example_effort.launch.py: Command([xacro, .../urdf/test_pendulum_effort.xacro.urdf])
    result = run("check", "urdf", PENDULUM, "--format", "json", "--isolated", env=NO_ROS)
    assert result.exit_code == 0, result.stdout
    assert findings(result.stdout) == []


def test_a_xacro_urdf_file_found_in_a_directory_is_expanded_with_the_arguments(run, tmp_path):
    robot = tmp_path / "robot.xacro.urdf"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:arg name="size" default="x"/>'
                     '<link name="base"><visual><geometry><box size="$(arg size)"/>'
                     '</geometry></visual></link></robot>')
    result = run("check", "urdf", tmp_path, "size:=0.1 0.2 0.3", "--format", "json",
                 "--isolated", env=NO_ROS)
    assert result.exit_code == 0 and findings(result.stdout) == [], result.stdout
