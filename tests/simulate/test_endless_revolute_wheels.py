"""Wheels on revolute joints with endless limits and sphere collisions (neobotix's MP-400).

``tests/fixtures/neo_simulation2``: the MP-400's drive wheels are revolute joints with limits
of 1e16 rad whose links collide as spheres, driven by Gazebo Classic's diff drive plugin.
inspect, simulate and drive took it for a robot without wheels ("no continuous joint").
"""

from __future__ import annotations

import json

from tests.conftest import REPO, run_servicebot
from tests.simulate.helpers import NO_ROS

MP_400 = REPO / "tests" / "fixtures" / "neo_simulation2" / "robots" / "mp_400" / "mp_400.urdf"


def test_its_wheels_radius_and_track_are_found():
    result = run_servicebot("inspect", MP_400, "--section", "totals", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    drive = json.loads(result.stdout)["totals"]["drive"]
    assert drive["left"] == ["mp_400_fixed_wheel_left_joint"]
    assert drive["right"] == ["mp_400_fixed_wheel_right_joint"]
    assert drive["wheel_radius_m"] == 0.0765  # the spheres'
    assert drive["track_m"] == 0.52  # wheels at y = +-0.26


def test_it_is_simulated_with_its_plugins_odometry():
    result = run_servicebot("simulate", MP_400, "--headless", "--duration-s", "5",
                            "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["messages"]["/odom"] == 500  # the plugin's <update_rate>100</update_rate>
    assert summary["distance_m"] > 0.5


def test_an_arm_joint_with_ordinary_limits_is_no_wheel(tmp_path):
    robot = tmp_path / "limited.urdf"
    robot.write_text(MP_400.read_text().replace('lower="-1e+16" upper="1e+16"',
                                                'lower="-3.14" upper="3.14"'))
    result = run_servicebot("inspect", robot, "--section", "totals", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert "wheel radius" not in result.stdout
