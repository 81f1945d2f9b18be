"""check controllers: a joint only <ros2_control> names is no joint of the robot.

A rename done halfway (the URDF's left_wheel_joint renamed left_whl_joint, its
<ros2_control> and controllers.yaml left as they were) passed check controllers: a name
the <ros2_control> block exports was taken for a URDF joint, where gz_ros2_control skips
such a joint ('not in the gazebo model') and robot_state_publisher has no state of it.
And SB602's fix said 'Use the suggested name.' where no name was close enough to suggest.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

WHEEL = ('<joint name="{name}" type="continuous"><parent link="base_link"/><child '
         'link="{side}_wheel"/><origin xyz="0 {y} 0" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/>'
         '<limit effort="1" velocity="10"/></joint><link name="{side}_wheel"><collision>'
         '<geometry><cylinder radius="0.033" length="0.026"/></geometry></collision></link>')
CONTROL = ('<ros2_control name="Real" type="system"><hardware><plugin>diffdrive_arduino/'
           'DiffDriveArduino</plugin></hardware>{joints}<sensor name="imu"><state_interface '
           'name="orientation.x"/></sensor></ros2_control>')
JOINT = ('<joint name="{name}"><command_interface name="velocity"/><state_interface '
         'name="position"/><state_interface name="velocity"/></joint>')
YAML = """controller_manager:
  ros__parameters:
    update_rate: 30
    diff_cont:
      type: diff_drive_controller/DiffDriveController
diff_cont:
  ros__parameters:
    left_wheel_names: ['{left}']
    right_wheel_names: ['right_wheel_joint']
    wheel_separation: 0.3
    wheel_radius: 0.033
"""


def _check(tmp_path, urdf_left: str, yaml_left: str):
    (tmp_path / "robot.urdf").write_text(
        '<robot name="r"><link name="base_link"/>'
        + WHEEL.format(name=urdf_left, side="left", y=0.15)
        + WHEEL.format(name="right_wheel_joint", side="right", y=-0.15)
        + CONTROL.format(joints=JOINT.format(name=yaml_left)
                         + JOINT.format(name="right_wheel_joint")) + "</robot>")
    (tmp_path / "controllers.yaml").write_text(YAML.format(left=yaml_left))
    result = run_servicebot("check", "controllers", "controllers.yaml", "--urdf", "robot.urdf",
                            "--isolated", "--format", "json", cwd=tmp_path)
    return result, [f for f in findings(result.stdout) if f["code"] == "SB602"]


def test_a_joint_only_ros2_control_names_is_not_in_the_urdf(tmp_path):
    result, (found,) = _check(tmp_path, "left_whl_joint", "left_wheel_joint")
    assert result.returncode == 1
    assert "joint 'left_wheel_joint' is not in robot.urdf (only its <ros2_control> names it" \
        in found["message"]
    assert "did you mean 'left_whl_joint'" in found["message"]


@pytest.mark.parametrize(("left", "fix"), [
    ("left_whl_joint", "Use the suggested name."),
    ("zzzz", "name a joint of the URDF; if the launch spawns no 'diff_cont' (a file shared by "
             "several robots), check with --spawned NAME[,NAME]"),
])
def test_the_fix_suggests_a_name_only_when_one_is_close(tmp_path, left, fix):
    _, (found,) = _check(tmp_path, "left_wheel_joint", left)
    assert found["fix"] == fix


def test_with_spawned_given_the_fix_names_the_joint_only(tmp_path):
    _check(tmp_path, "left_wheel_joint", "zzzz")
    result = run_servicebot("check", "controllers", "controllers.yaml", "--urdf", "robot.urdf",
                            "--spawned", "diff_cont", "--isolated", "--format", "json",
                            cwd=tmp_path)
    [found] = [f for f in findings(result.stdout) if f["code"] == "SB602"]
    assert found["fix"] == "name a joint of the URDF"



def test_a_joint_the_other_side_names_is_not_suggested(tmp_path):
    """The URDF's left wheel renamed wheel_left_joint: right_wheel_joint (in
    right_wheel_names) was suggested first for left_wheel_names."""
    _, (found,) = _check(tmp_path, "wheel_left_joint", "left_wheel_joint")
    assert "did you mean 'wheel_left_joint'?" in found["message"]
    assert "right_wheel_joint'" not in found["message"].split("did you mean")[1]


def test_a_misspelled_chained_controller_is_suggested_as_its_reference(tmp_path):
    """A typo in a chained reference's controller: the joints suggested (casters first)
    would have undone the chain."""
    chain = ("pid_left_wheel_joint:\n  ros__parameters:\n    type: pid_controller/PidController\n"
             "    dof_names: [left_wheel_joint]\n    command_interface: velocity\n"
             "    reference_and_state_interfaces: [velocity]\n")
    _check(tmp_path, "left_wheel_joint", "pid_left_wheel/left_wheel_joint")
    text = (tmp_path / "controllers.yaml").read_text()
    (tmp_path / "controllers.yaml").write_text(text.replace(
        "diff_cont:\n      type:", "pid_left_wheel_joint:\n      type: pid_controller/"
        "PidController\n    diff_cont:\n      type:") + chain)
    result = run_servicebot("check", "controllers", "controllers.yaml", "--urdf", "robot.urdf",
                            "--isolated", "--format", "json", cwd=tmp_path)
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB602"]
    assert "did you mean 'pid_left_wheel_joint/left_wheel_joint', a reference of the " \
        "controller 'pid_left_wheel_joint'?" in found["message"]


@pytest.mark.parametrize(("wrong", "meant", "not_meant"), [
    ("arm_link1_to_link3", "arm_link2_to_link3", "arm_link1_to_link2"),  # already listed
    ("arm_base_to_link", "arm_base_to_link1", "arm_base_joint"),  # fixed: SB606 if taken
])
def test_no_joint_the_controller_would_refuse_is_suggested(run, tmp_path, wrong, meant,
                                                           not_meant):
    from tests.check.helpers import check_controllers
    from tests.conftest import REPO

    bundled = (REPO / "robots" / "controllers.yaml").read_text()
    gone = "arm_link2_to_link3" if wrong == "arm_link1_to_link3" else "arm_base_to_link1"
    text = bundled.replace(f"      - {gone}\n", f"      - {wrong}\n", 1)
    _, found = check_controllers(run, tmp_path, text)
    (unknown,) = [f for f in found if f["code"] == "SB602"]
    hint = str(unknown["message"]).split("did you mean", 1)[1]
    assert f"'{meant}'" in hint and f"'{not_meant}'" not in hint
