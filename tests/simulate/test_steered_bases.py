"""A car-like base is refused by simulate and drive, naming its steering joint and wheel.

ros2_control_demos' carlikebot steers its front wheels with revolute joints about the
vertical; pybullet's racecar puts each wheel's spin joint below a steering hinge. Their rear
wheels passed as a differential drive: the run turned them in place, and drive sent the
rear motors opposite speeds to turn.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import REPO, assert_one_line_error, run_servicebot

CARLIKEBOT = REPO / "tests" / "realworld" / "ws" / "src" / "example_11" / "description" \
    / "urdf" / "carlikebot.urdf.xacro"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def test_carlikebot_is_refused_with_its_steering_joint():
    result = run_servicebot("simulate", CARLIKEBOT, "--headless", env=NO_ROS)
    assert_one_line_error(result, 2, "not a differential drive: joint "
                          "'virtual_front_wheel_joint' steers the wheel on link "
                          "'virtual_front_wheel' about the vertical (a car-like base")


def test_a_steering_hinge_above_the_wheel_joint_is_found():
    pybullet_data = pytest.importorskip("pybullet_data")
    racecar = Path(pybullet_data.getDataPath()) / "racecar" / "racecar.urdf"
    result = run_servicebot("simulate", racecar, "--headless")
    assert_one_line_error(result, 2, "joint 'left_steering_hinge_joint' steers the wheel on "
                          "link 'left_front_wheel'")


def test_its_wheels_still_show_in_inspect():
    result = run_servicebot("inspect", CARLIKEBOT, "--section", "totals", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert "wheel radius" in result.stdout


def test_an_arm_waist_carrying_a_cylinder_on_its_side_steers_no_wheel(tmp_path):
    """A mobile manipulator: the waist turns about the vertical, and the link after it is a
    horizontal cylinder, high above the floor. It is no steered wheel: the run goes on."""
    from tests.conftest import SIM_URDF

    text = SIM_URDF.read_text()
    start = text.index('<link name="arm_link2">')
    end = text.index("</link>", start)
    link2 = text[start:end].replace('<origin rpy="0 0 0" xyz="0.15 0 0"/>',
                                    '<origin rpy="0 1.5708 0" xyz="0.15 0 0"/>').replace(
        '<box size="0.3 0.1 0.1"/>', '<cylinder length="0.3" radius="0.05"/>')
    assert "cylinder" in link2 and "1.5708" in link2
    robot = tmp_path / "cylinder_arm.urdf"
    robot.write_text(text[:start] + link2 + text[end:])
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "5",
                            "--format", "json")
    assert result.returncode in (0, 1), result.stderr  # 1: an expectation, never a refusal
    assert "not a differential drive" not in result.stderr


@pytest.mark.parametrize("command", [
    ("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "3436", "--baud",
     "57600", "--linear", "0.1", "--angular", "0.3", "--duration-s", "1"),
    ("emulate", "--protocol", "arduino", "--ticks-per-rev", "3436", "--baud", "57600"),
])
def test_drive_and_emulate_refuse_it_too(command):
    result = run_servicebot(command[0], CARLIKEBOT, *command[1:], env=NO_ROS)
    assert_one_line_error(result, 2, "joint 'virtual_front_wheel_joint' steers the wheel",
                          "differential-drive bases only")
