"""The tool frame commands use when none is named, and the note that says which it is."""

from __future__ import annotations

import pytest

from tests.conftest import REPO, run_servicebot

TURTLEBOT3 = REPO / "tests" / "realworld" / "ws" / "src" / "turtlebot3_description" / "urdf" \
    / "turtlebot3_burger.urdf.xacro"


def test_the_note_on_a_one_joint_chain_says_joint():
    result = run_servicebot("fk", TURTLEBOT3, env={"ROS_PACKAGE_PATH": "",
                                                   "AMENT_PREFIX_PATH": ""})
    assert result.returncode == 0, result.stderr
    assert result.stderr == ("note: no --frame given; using 'wheel_right_link', the tip of the "
                             "longest chain (1 joint)\n")


@pytest.mark.parametrize(("robot", "tool"), [
    ("tiago_description/robots/tiago.urdf", "hand_tool_link"),
    ("pr2_description/urdf/pr2.urdf", "l_gripper_tool_frame"),
    ("tiago_pro_description/robots/tiago_pro.urdf", "arm_right_tool_link"),
])
def test_a_link_named_as_the_tool_wins_over_the_tip_of_a_finger(robot, tool):
    """TIAGo's longest chain runs through its hand into hand_little_flex_3_link (15 joints):
    ik and fk moved a fingertip when no frame was named."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.kinematics.frames import default_tool_frame
    from tests.kinematics.robots import example_robot

    choice = default_tool_frame(load(RobotSource.of(example_robot(robot))))
    assert (choice.name, choice.obvious) == (tool, True)


def test_a_knee_is_no_end_effector():
    """'ee_link' is in 'right_knee_link': only whole words of a name count (Unitree's G1)."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.kinematics.frames import default_tool_frame
    from tests.kinematics.robots import example_robot

    robot = load(RobotSource.of(example_robot("g1_description/urdf/g1_29dof_rev_1_0.urdf")))
    assert "knee" not in default_tool_frame(robot).name
