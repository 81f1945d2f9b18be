"""Wheels of unequal radii roll the base on a curve, as inspect says it does.

Left r = 0.055 m, right r = 0.045 m, both driven at v / (d / 2) = 4 rad/s by the plugin:
the sides move at 0.22 and 0.18 m/s, so the base yaws at -0.04 / 0.3 rad/s. simulate drove it
dead straight on the mean radius.
"""

from __future__ import annotations

import json
import math

import pytest

_WHEEL = ('<link name="{side}"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
          'radius="{r}" length="0.04"/></geometry></collision></link>'
          '<joint name="{side}_joint" type="continuous"><parent link="base_link"/>'
          '<child link="{side}"/><origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>'
          '<limit effort="10" velocity="20"/></joint>')
_CASTER = ('<link name="caster"><collision><geometry><sphere radius="0.05"/></geometry>'
           '</collision></link><joint name="caster_joint" type="fixed"><parent link="base_link"/>'
           '<child link="caster"/><origin xyz="-0.2 0 0"/></joint>')
_PLUGIN = ('<gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so"><left_joint>'
           "left_joint</left_joint><right_joint>right_joint</right_joint><wheel_separation>0.3"
           "</wheel_separation><wheel_diameter>0.1</wheel_diameter></plugin></gazebo>")


def test_unequal_wheels_curve_where_equal_ones_go_straight(run, tmp_path):
    scenario = tmp_path / "straight.yaml"
    scenario.write_text("duration_s: 5\ncmd_vel:\n  - {duration_s: 5, linear_m_s: 0.2}\n")
    poses = {}
    for left_r, right_r in ((0.05, 0.05), (0.055, 0.045)):
        wheels = (_WHEEL.format(side="left", r=left_r, y=0.15)
                  + _WHEEL.format(side="right", r=right_r, y=-0.15))
        robot = tmp_path / f"base_{left_r}.urdf"
        robot.write_text(f'<robot name="b"><link name="base_link"/>{wheels}{_CASTER}{_PLUGIN}'
                         "</robot>")
        result = run("simulate", robot, "--headless", "-s", scenario, "--format", "json")
        assert result.exit_code == 0, result.output
        poses[right_r] = json.loads(result.stdout)["final_pose"]
    assert poses[0.05]["yaw_rad"] == 0 and poses[0.05]["x_m"] == pytest.approx(1.0)
    yaw = -0.04 / 0.3 * 5
    assert poses[0.045]["yaw_rad"] == pytest.approx(yaw, rel=1e-6)
    radius = 0.2 / (0.04 / 0.3)  # the arc's radius at the mean speed
    assert poses[0.045]["x_m"] == pytest.approx(radius * math.sin(-yaw), rel=1e-6)
