"""SB217: a mimic joint the joint it follows takes outside its own limits.

moveo_ros' SolidWorks export: Tip_Gripper_Idol_Joint ([-1.5, 0]) mimics Gripper_Idol_Gear_Joint
([-1.5707, 0]) with multiplier -1, so it would run over [0, 1.57]; check passed, and fk refused
every value of the gear but 0.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings


def _gripper(tmp_path, tip_limits: str, mimic: str):
    path = tmp_path / "gripper.urdf"
    path.write_text(
        '<robot name="g"><link name="palm"/><link name="gear"/><link name="tip"/>'
        '<joint name="gear_joint" type="revolute"><parent link="palm"/><child link="gear"/>'
        '<axis xyz="0 0 1"/><limit lower="-1.5707" upper="0" effort="1" velocity="1"/></joint>'
        '<joint name="tip_joint" type="revolute"><parent link="gear"/><child link="tip"/>'
        f'<axis xyz="0 0 1"/><limit {tip_limits} effort="1" velocity="1"/>{mimic}</joint>'
        "</robot>")
    return path


def test_a_multiplier_of_the_wrong_sign_is_named_with_the_sign_that_fits(run, tmp_path):
    path = _gripper(tmp_path, 'lower="-1.5" upper="0"', '<mimic joint="gear_joint" '
                    'multiplier="-1"/>')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB217")
    (found,) = findings(result.stdout)
    assert "it moves over [0, 1.5707], outside its limits [-1.5, 0]" in found["message"]
    assert found["fix"] == 'multiplier="1", if the two turn the other way round'
    fk = run("fk", path, "-j", "gear_joint=-1")
    assert fk.exit_code == 2  # what fk refuses, check now names


@pytest.mark.parametrize(("limits", "mimic"), [
    ('lower="-1.5" upper="0"', '<mimic joint="gear_joint"/>'),  # 3 % past the end: rounding
    ('lower="0" upper="3.2"', '<mimic joint="gear_joint" multiplier="-2"/>'),
    ('lower="-1" upper="1"', '<mimic joint="gear_joint" multiplier="1" offset="0.6"/>'),
])
def test_a_mimic_within_its_limits_is_not_named(run, tmp_path, limits, mimic):
    path = _gripper(tmp_path, limits, mimic)
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB217")
    assert findings(result.stdout) == []


def test_a_followed_joint_defined_twice_is_judged_by_its_first_definition(run, tmp_path):
    """urdfdom refuses the file (SB102); SB217 read the second 'gear_joint', whose range
    [0, 1.5707] the tip would leave, where every other rule reads the first."""
    path = tmp_path / "gripper.urdf"
    path.write_text(
        '<robot name="g"><link name="palm"/><link name="gear"/><link name="tip"/>'
        '<link name="spare"/>'
        '<joint name="gear_joint" type="revolute"><parent link="palm"/><child link="gear"/>'
        '<axis xyz="0 0 1"/><limit lower="-1.5707" upper="0" effort="1" velocity="1"/></joint>'
        '<joint name="tip_joint" type="revolute"><parent link="gear"/><child link="tip"/>'
        '<axis xyz="0 0 1"/><limit lower="-1.5707" upper="0" effort="1" velocity="1"/>'
        '<mimic joint="gear_joint"/></joint>'
        '<joint name="gear_joint" type="revolute"><parent link="palm"/><child link="spare"/>'
        '<axis xyz="0 0 1"/><limit lower="0" upper="1.5707" effort="1" velocity="1"/></joint>'
        "</robot>")
    codes = [f["code"] for f in findings(run("check", "urdf", path, "--format", "json",
                                             "--isolated").stdout)]
    assert "SB102" in codes and "SB217" not in codes


@pytest.mark.parametrize("kind", ["fixed", "floating"])
def test_a_mimic_of_a_joint_that_cannot_move_is_an_error(run, tmp_path, kind):
    """panda's finger mimicking the fixed panda_hand_joint: Pinocchio (with mimic joints)
    refuses it, MuJoCo drops the mimic, yourdfpy holds the finger still; check passed."""
    path = _gripper(tmp_path, 'lower="-1.5" upper="0"', '<mimic joint="gear_joint"/>')
    path.write_text(path.read_text().replace(
        '<joint name="gear_joint" type="revolute">', f'<joint name="gear_joint" type="{kind}">'))
    found = [f for f in findings(run("check", path, "--format", "json", "--isolated").stdout)
             if f["code"] == "SB209"]
    assert len(found) == 1 and found[0]["severity"] == "error"
    assert f"mimics 'gear_joint', a {kind} joint" in found[0]["message"]


def test_a_mimic_of_a_joint_with_a_misspelled_type_is_that_joints_error_only(run, tmp_path):
    path = _gripper(tmp_path, 'lower="-1.5" upper="0"', '<mimic joint="gear_joint"/>')
    path.write_text(path.read_text().replace(
        '<joint name="gear_joint" type="revolute">', '<joint name="gear_joint" type="revolut">'))
    codes = [f["code"] for f in findings(run("check", path, "--format", "json",
                                             "--isolated").stdout)]
    assert "SB201" in codes and "SB209" not in codes
