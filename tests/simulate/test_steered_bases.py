"""A car-like base is refused by simulate, naming its steering joint and wheel.

ros2_control_demos' carlikebot steers its front wheels with revolute joints about the
vertical; pybullet's racecar puts each wheel's spin joint below a steering hinge. Their rear
wheels passed as a differential drive, and the run turned them in place.
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
