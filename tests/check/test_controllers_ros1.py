"""A ROS 1 ros_control controllers file (MiR's ``diffdrive_controller.yaml`` layout) given to
``check controllers`` is named as such, with what to do, not only "no sections"."""

from __future__ import annotations

ROS1 = """\
mobile_base_controller:
  type        : "diff_drive_controller/DiffDriveController"
  left_wheel  : 'left_wheel_joint'
  right_wheel : 'right_wheel_joint'
  publish_rate: 41.2
"""


def test_a_ros1_controllers_file_is_named_as_one(run, tmp_path):
    path = tmp_path / "diffdrive_controller.yaml"
    path.write_text(ROS1)
    result = run("check", "controllers", path, "--robot", "sim")
    assert result.exit_code == 1
    assert "SB601" in result.stdout
    assert "a ROS 1 ros_control file ('mobile_base_controller: type: ...'" in result.stdout
    assert "fix: check ROS 2 controllers files only, or port this one" in result.stdout


def test_a_file_of_no_controllers_keeps_the_plain_message(run, tmp_path):
    path = tmp_path / "other.yaml"
    path.write_text("costmap:\n  width: 10\n")
    result = run("check", "controllers", path, "--robot", "sim")
    assert "no controller sections" in result.stdout and "ROS 1" not in result.stdout
    assert "Fix the YAML" not in result.stdout  # valid YAML: another kind of file
    assert "fix: name the ros2_control controllers file" in result.stdout


def test_a_namespaced_ros1_file_and_a_moveit_controller_list_are_named(run, tmp_path):
    """op3_gazebo's position_controller.yaml (under robotis:) and atlas_v3_moveit_config's
    controller_list got 'Fix the YAML at the reported line'; the YAML is valid."""
    path = tmp_path / "c.yaml"
    path.write_text("robotis:\n" + "".join(f"  {line}\n" for line in ROS1.splitlines()))
    result = run("check", "controllers", path, "--robot", "sim")
    assert "a ROS 1 ros_control file ('mobile_base_controller: type: ...'" in result.stdout
    path.write_text("controller_list:\n  - name: arm_controller\n    action_ns: "
                    "follow_joint_trajectory\n    type: FollowJointTrajectory\n")
    result = run("check", "controllers", path, "--robot", "sim")
    assert "a MoveIt controller_list (moveit_simple_controller_manager's)" in result.stdout
    assert "Fix the YAML" not in result.stdout


def test_a_node_parameters_file_says_nothing_was_checked(run, tmp_path):
    """roverrobotics_driver's max_100_config.yaml: a driver node's parameters, no controller;
    check controllers passed it with no word of having checked nothing."""
    path = tmp_path / "max_100_config.yaml"
    path.write_text("roverrobotics_driver:\n  ros__parameters:\n    device_port: /dev/rover\n"
                    "    wheel_radius: 0.08\n")
    result = run("check", "controllers", path, "--robot", "sim")
    assert result.exit_code == 0
    assert "info SB601 [controllers-yaml] no controller here: its sections " \
        "(roverrobotics_driver) give no controller type and name no joint" in result.stdout
