"""The note naming the chosen tool frame counts its chain's joints in good English."""

from __future__ import annotations

from tests.conftest import REPO, run_servicebot

TURTLEBOT3 = REPO / "tests" / "realworld" / "ws" / "src" / "turtlebot3_description" / "urdf" \
    / "turtlebot3_burger.urdf.xacro"


def test_the_note_on_a_one_joint_chain_says_joint():
    result = run_servicebot("fk", TURTLEBOT3, env={"ROS_PACKAGE_PATH": "",
                                                   "AMENT_PREFIX_PATH": ""})
    assert result.returncode == 0, result.stderr
    assert result.stderr == ("note: no --frame given; using 'wheel_right_link', the tip of the "
                             "longest chain (1 joint)\n")
