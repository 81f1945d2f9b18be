"""ik on planar arms (every joint about one axis) says the target is off the arm's plane.

ros2_control_demos' rrbot turns both joints about y, so its tool stays in the plane y = 0.2 m
(fk at random angles shows it); urdf_tutorial's gripper slides along x and turns about z. A
target off that plane used to get "the limits may forbid it", though rrbot has no limits.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from tests.conftest import REPO, run_servicebot

SRC = REPO / "tests" / "realworld" / "ws" / "src"
RRBOT = SRC / "example_1" / "description" / "urdf" / "rrbot.urdf.xacro"
TUTORIAL = SRC / "urdf_tutorial" / "urdf" / "08-macroed.urdf.xacro"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def test_rrbot_tool_stays_in_the_plane_y_0_2():
    rng = np.random.default_rng(3)
    for q1, q2 in rng.uniform(-np.pi, np.pi, (3, 2)):
        result = run_servicebot("fk", RRBOT, "-j", f"joint1={q1}", "-j", f"joint2={q2}",
                                "--format", "json", env=NO_ROS)
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout)["poses"][0]["position_m"][1] == pytest.approx(0.2)


@pytest.mark.parametrize(("path", "frame", "normal", "off_m"), [
    (RRBOT, "tool_link", "(0 1 0)", "0.1"),
    (TUTORIAL, "right_gripper", "(0 0 -1)", "0.2"),
])
def test_a_target_off_the_plane_is_out_of_reach_by_its_distance(path, frame, normal, off_m):
    result = run_servicebot("ik", path, "--position", "0.3", "0.1", "0.4", "--seed", "1",
                            env=NO_ROS)
    assert result.returncode == 1, result.stderr
    error = result.stderr.splitlines()[-1]
    assert error.endswith(f"out of reach: every joint that moves '{frame}' turns about {normal} "
                          f"or slides across it, so it moves in one plane; the target is "
                          f"{off_m} m off that plane"), error


def test_a_target_in_the_plane_is_still_reached():
    result = run_servicebot("ik", RRBOT, "--position", "0.3", "0.2", "0.4", "--seed", "1",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
