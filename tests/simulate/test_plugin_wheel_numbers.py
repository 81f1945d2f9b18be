"""A Gazebo diff-drive plugin drives with its own wheel numbers; the URDF's wheels roll.

gazebo_ros_diff_drive sets each wheel joint to ``(v -+ w * wheel_separation / 2) /
(wheel_diameter / 2)`` (gz-sim's DiffDrive the same with ``wheel_radius``), and the wheels
carry the robot by their own radius and track. simulate drove with the URDF's numbers:
sam_bot's plugin (0.4 m on wheels 0.36 m apart) turned as commanded, not as Gazebo turns it.
"""

from __future__ import annotations

import json

import pytest

_WHEEL = ('<link name="{side}"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
          'radius="0.1" length="0.04"/></geometry></collision></link>'
          '<joint name="{side}_joint" type="continuous"><parent link="base_link"/>'
          '<child link="{side}"/><origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>'
          '<limit effort="10" velocity="10"/></joint>')
_CASTER = ('<link name="caster"><collision><geometry><sphere radius="0.1"/></geometry>'
           '</collision></link><joint name="caster_joint" type="fixed"><parent link="base_link"/>'
           '<child link="caster"/><origin xyz="-0.2 0 0"/></joint>')


def _robot(tmp_path, plugin: str):
    wheels = _WHEEL.format(side="left", y=0.18) + _WHEEL.format(side="right", y=-0.18)
    path = tmp_path / "base.urdf"
    path.write_text(f'<robot name="base"><link name="base_link"/>{wheels}{_CASTER}'
                    f"<gazebo>{plugin}</gazebo></robot>")
    return path


def _final_pose(run, tmp_path, robot, linear: float, angular: float) -> dict:
    scenario = tmp_path / "go.yaml"
    scenario.write_text(f"duration_s: 4\ncmd_vel:\n  - {{duration_s: 4, linear_m_s: {linear}, "
                        f"angular_rad_s: {angular}}}\n")
    result = run("simulate", robot, "--headless", "-s", scenario, "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


_CLASSIC = ('<plugin name="d" filename="libgazebo_ros_diff_drive.so"><left_joint>left_joint'
            "</left_joint><right_joint>right_joint</right_joint>{}</plugin>")
_GZ = ('<plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">'
       "<left_joint>left_joint</left_joint><right_joint>right_joint</right_joint>{}</plugin>")


@pytest.mark.parametrize(("plugin", "metres"), [
    (_CLASSIC.format("<wheel_separation>0.36</wheel_separation><wheel_diameter>0.2"
                     "</wheel_diameter>"), 0.8),  # the URDF's own: as commanded
    (_CLASSIC.format("<wheel_separation>0.36</wheel_separation><wheel_diameter>0.25"
                     "</wheel_diameter>"), 0.64),  # 0.2 / 0.125 rad/s on a 0.1 m wheel
    (_CLASSIC.format("<wheel_separation>0.36</wheel_separation>"), 0.8 * 0.1 / 0.075),
    (_GZ.format("<wheel_separation>0.36</wheel_separation><wheel_radius>0.08"
                "</wheel_radius>"), 1.0),
])
def test_the_plugins_radius_sets_the_wheel_speed(run, tmp_path, plugin, metres):
    summary = _final_pose(run, tmp_path, _robot(tmp_path, plugin), 0.2, 0.0)
    assert summary["final_pose"]["x_m"] == pytest.approx(metres, rel=1e-6)


@pytest.mark.parametrize(("separation", "default"), [("0.4", False), ("", True)])
def test_the_plugins_separation_sets_the_turn(run, tmp_path, separation, default):
    written = f"<wheel_separation>{separation}</wheel_separation>" if separation else ""
    plugin = _CLASSIC.format(f"{written}<wheel_diameter>0.2</wheel_diameter>")
    summary = _final_pose(run, tmp_path, _robot(tmp_path, plugin), 0.0, 0.5)
    used = 0.34 if default else 0.4  # gazebo_ros_diff_drive's default when not written
    assert summary["final_pose"]["yaw_rad"] == pytest.approx(0.5 * used / 0.36 * 4, rel=1e-6)
    assert summary["controller"]["wheel_separation_m"]["value"] == used
