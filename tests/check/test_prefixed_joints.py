"""check controllers on joints a launch file prefixes ($(var prefix)joint1, <prefix>joint1).

Whatever the prefix, such a name ends as written: it is judged by that end, as a plain name
is by the whole (SB602 when no joint ends so, SB606 when only fixed ones do), suggestions
leave out what the lists name already, and a section another robot's joints fill (a
multi-robot file) is still left to that robot.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

_ARM = ('<robot name="arm"><link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/>'
        '<link name="tool"/>' + "".join(
            f'<joint name="j{k}" type="revolute"><parent link="{p}"/><child link="l{k}"/>'
            '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            for k, p in ((1, "base"), (2, "l1"), (3, "l2")))
        + '<joint name="tool_joint" type="fixed"><parent link="l3"/><child link="tool"/></joint>'
        '<ros2_control name="arm" type="system"><hardware><plugin>mock_components/GenericSystem'
        '</plugin></hardware>' + "".join(
            f'<joint name="j{k}"><command_interface name="position"/><state_interface '
            'name="position"/></joint>' for k in (1, 2, 3))
        + '<gpio name="tool_gpio"><state_interface name="io"/></gpio></ros2_control></robot>')


def _check(tmp_path, sections: str) -> list[tuple[str, str, str | None]]:
    (tmp_path / "arm.urdf").write_text(_ARM)
    (tmp_path / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    update_rate: 100\n    traj:\n"
        "      type: joint_trajectory_controller/JointTrajectoryController\n" + sections)
    result = run_servicebot("check", "controllers", "controllers.yaml", "--urdf", "arm.urdf",
                            "--isolated", "--format", "json", cwd=tmp_path)
    assert result.returncode in (0, 1), result.stderr
    return [(f["code"], f["message"], f["fix"]) for f in findings(result.stdout)
            if f["code"] in ("SB602", "SB606")]


def _traj(*joints: str, namespace: str = "") -> str:
    return (f"{namespace}traj:\n  ros__parameters:\n    joints: [{', '.join(joints)}]\n"
            "    command_interfaces: [position]\n    state_interfaces: [position]\n")


def test_a_prefixed_fixed_joint_is_sb606(tmp_path):
    ((code, message, _),) = _check(tmp_path, _traj("$(var p)j1", "$(var p)tool_joint"))
    assert code == "SB606" and "'tool_joint'" in message


def test_a_prefixed_suggestion_leaves_out_the_joints_listed(tmp_path):
    ((code, message, _),) = _check(tmp_path, _traj("$(var p)j1", "$(var p)j2", "$(var p)j2x"))
    assert code == "SB602" and "ends in 'j2x'" in message and "'$(var p)j2'" not in message


def test_with_every_moving_joint_listed_nothing_is_suggested(tmp_path):
    ((code, message, fix),) = _check(tmp_path, _traj("j1", "j2", "j3", "j4"))
    assert code == "SB602" and "every joint of the URDF that moves is listed already" in message
    assert fix.startswith("name a joint of the URDF")


@pytest.mark.parametrize("name", ["$(var p)tool_gpio", "tool_gpio"])
def test_a_prefixed_gpio_is_no_unknown_joint(tmp_path, name):
    sections = ("jsb:\n  ros__parameters:\n    type: joint_state_broadcaster/"
                f"JointStateBroadcaster\n    joints: [$(var p)j1, {name}]\n")
    assert _check(tmp_path, _traj("j1") + sections) == []


def test_a_section_another_robots_prefixed_joints_fill_is_left_to_that_robot(tmp_path):
    """One file for two robots (as ros2_control_demos' example 15), every joint prefixed."""
    sections = (_traj("$(var p)j1", "$(var p)j2", namespace="/robot1/")
                + _traj("$(var p)leg_hip", "$(var p)leg_knee", namespace="/robot2/"))
    assert _check(tmp_path, sections) == []


def test_a_urdf_with_no_joint_that_moves_says_so(tmp_path):
    (tmp_path / "arm.urdf").write_text('<robot name="r"><link name="a"/><link name="b"/>'
                                       '<joint name="j" type="fixed"><parent link="a"/>'
                                       '<child link="b"/></joint></robot>')
    (tmp_path / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    update_rate: 100\n    fwd:\n"
        "      type: forward_command_controller/ForwardCommandController\n"
        "fwd:\n  ros__parameters:\n    joints: [jj]\n    interface_name: position\n")
    result = run_servicebot("check", "controllers", "controllers.yaml", "--urdf", "arm.urdf",
                            "--isolated", "--format", "json", cwd=tmp_path)
    (unknown,) = [f for f in findings(result.stdout) if f["code"] == "SB602"]
    assert "the URDF has no joint that moves" in unknown["message"]
