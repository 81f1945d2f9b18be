"""A robot that is not a differential drive is refused with the reason for each joint.

Real descriptions: r2d2 (pybullet_data) rolls along its y, so its wheels turn about x; the
ros2_control_demos rrbot's continuous joints carry boxes; the FANUC arm has no continuous joint.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import REPO, assert_one_line_error, run_servicebot

SRC = REPO / "tests" / "realworld" / "ws" / "src"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def _refusal(path: Path) -> str:
    result = run_servicebot("simulate", path, "--headless", env=NO_ROS)
    line = assert_one_line_error(result, 2, "not a differential drive", "(found: none); ")
    return line.split("(found: none); ", 1)[1]


def test_wheels_turning_about_x_are_named_with_their_axis():
    pybullet_data = pytest.importorskip("pybullet_data")
    why = _refusal(Path(pybullet_data.getDataPath()) / "r2d2.urdf")
    assert why.startswith("right_front_wheel_joint, right_back_wheel_joint, "
                          "left_front_wheel_joint, left_back_wheel_joint turn about (1 0 0) in "
                          "base_link, not across the robot (its y")
    # the head is a sphere, round about any axis, but it turns about the vertical
    assert "head_swivel turns about (0 0 1) in base_link, not across the robot" in why


def test_continuous_joints_without_a_cylinder_are_named_with_their_link():
    why = _refusal(SRC / "example_1" / "description" / "urdf" / "rrbot.urdf.xacro")
    assert why == ("joint1 (link 'link1'), joint2 (link 'link2') turn but their links have no "
                   "<cylinder> or <sphere> collision or visual to take a radius from")


def test_mimic_joints_come_after_the_joints_that_could_be_wheels(tmp_path):
    """ros-naoqi's Pepper: three mimic fingers were named first, one reason each, and its
    mesh wheels were cut off behind '...'."""
    links = "".join(f'<link name="{n}_link"/>' for n in ("F1", "F2", "F3", "WL", "WR"))
    joints = "".join(
        f'<joint name="{n}" type="continuous"><parent link="base"/><child link="{n}_link"/>'
        f'<axis xyz="0 1 0"/>{mimic}</joint>'
        for n, mimic in (("F1", ""), ("F2", '<mimic joint="F1"/>'), ("F3", '<mimic joint="F1"/>'),
                         ("WL", ""), ("WR", "")))
    robot = tmp_path / "pepper.urdf"
    robot.write_text(f'<robot name="p"><link name="base"/>{links}{joints}</robot>')
    why = _refusal(robot)
    assert why.startswith("F1 (link 'F1_link'), WL (link 'WL_link'), WR (link 'WR_link'), "
                          "F2 (link 'F2_link'), F3 (link 'F3_link') turn but their links")


def test_an_arm_without_continuous_joints_says_so():
    assert _refusal(SRC / "fanuc_description" / "urdf" / "fanuc.urdf") == \
        "it has no continuous joint"
