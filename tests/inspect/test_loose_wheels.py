"""Wheels of a robot that is no differential drive are still wheels, not arm joints.

agilex's scout_mini draws its wheels as meshes only and names no Gazebo drive plugin: its
four wheel joints were '0 wheels + 4 arm', with an arm reach of 0 m from a wheel joint to
its wheel. A caster wheel on one side only (a Pioneer whose drive wheels are fixed) and its
swivel were an arm too.
"""

from __future__ import annotations

from tests.check.helpers import tetrahedron_stl
from tests.conftest import run_servicebot

WHEEL = ('<link name="{side}_wheel"><visual><geometry><mesh filename="wheel.stl"/></geometry>'
         '</visual></link><joint name="{side}_wheel_joint" type="continuous">'
         '<parent link="base_link"/><child link="{side}_wheel"/><origin xyz="0 {y} 0"/>'
         '<axis xyz="0 1 0"/></joint>')
ARM = ('<link name="upper"><visual><geometry><mesh filename="wheel.stl"/></geometry></visual>'
       '</link><link name="hand"/><joint name="shoulder" type="continuous">'
       '<parent link="base_link"/><child link="upper"/><origin xyz="0 0 0.3"/>'
       '<axis xyz="0 1 0"/></joint><joint name="elbow" type="revolute"><parent link="upper"/>'
       '<child link="hand"/><origin xyz="0.3 0 0"/><axis xyz="0 1 0"/>'
       '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')


def _totals(tmp_path, body: str) -> str:
    (tmp_path / "wheel.stl").write_bytes(tetrahedron_stl(0.1))
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="base_link"/>{body}</robot>')
    result = run_servicebot("inspect", path, "--section", "totals")
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_mesh_wheels_without_a_plugin_are_wheels(tmp_path):
    out = _totals(tmp_path, WHEEL.format(side="left", y=0.2) + WHEEL.format(side="right",
                                                                              y=-0.2))
    assert "degrees of freedom     2: 2 wheels + 0 arm" in out
    assert "arm reach" not in out
    assert "not a differential drive" in out  # no radius to drive with


def test_an_arm_whose_shoulder_turns_freely_is_still_an_arm(tmp_path):
    """A continuous shoulder about y with a mesh link carries a moving elbow: no wheel."""
    out = _totals(tmp_path, WHEEL.format(side="left", y=0.2) + ARM)
    assert "degrees of freedom     3: 1 wheel + 2 arm" in out
    assert "arm reach" in out and "shoulder to hand" in out


CYLINDER_WHEEL = ('<link name="{side}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry>'
                  '<cylinder radius="{radius}" length="0.02"/></geometry></collision></link>'
                  '<joint name="{side}_wheel_joint" type="continuous"><parent link="base_link"/>'
                  '<child link="{side}_wheel"/><origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>'
                  '<limit effort="1" velocity="20"/></joint>')


def test_wheels_of_unequal_radii_are_named_in_a_note(tmp_path):
    """Their mean was shown as the wheel radius, without a word (tracer_mini's 0.01-0.05 m)."""
    out = _totals(tmp_path, CYLINDER_WHEEL.format(side="left", radius=0.05, y=0.2)
                  + CYLINDER_WHEEL.format(side="right", radius=0.1, y=-0.2))
    assert "wheel radius              0.075 m" in out
    assert "radii differ (left_wheel_joint 0.05 m, right_wheel_joint 0.1 m)" in \
        " ".join(out.split())
    same = _totals(tmp_path, CYLINDER_WHEEL.format(side="left", radius=0.05, y=0.2)
                   + CYLINDER_WHEEL.format(side="right", radius=0.05, y=-0.2))
    assert "radii differ" not in same
