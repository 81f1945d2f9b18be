"""Robots the model is refused for, in one line that names the joint as the file writes it.

A <mimic> of itself or of a joint that is not there: no joint drives the follower. fk,
inspect and simulate took such a joint as free, without a word, where MoveIt refuses the
robot and yourdfpy sets the joint to its offset (check: SB210, SB209). A negative friction,
which Pinocchio refuses in words that name no joint (check: SB216).
"""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

ROBOT = """<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="{leader}" multiplier="2"/></joint>
</robot>
"""
COMMANDS = [("fk", "-f", "b"), ("ik", "-f", "b", "--position", "0.1", "0", "0"),
            ("simulate", "--headless", "--duration-s", "0.1")]


@pytest.mark.parametrize("command", COMMANDS, ids=[c[0] for c in COMMANDS])
@pytest.mark.parametrize(("leader", "said"), [
    ("j9", "joint 'j2' mimics 'j9', which does not exist: nothing drives it"),
    ("j2", "joint 'j2' mimics itself: nothing drives it"),
])
def test_a_follower_without_a_leader_is_one_line(tmp_path, command, leader, said):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader=leader))
    extra = ("--out", str(tmp_path / "run")) if command[0] == "simulate" else ()
    result = run_servicebot(command[0], path, *command[1:], *extra)
    assert_one_line_error(result, 2, said, "servicebot check")
    assert not (tmp_path / "run").exists()


@pytest.mark.parametrize("command", COMMANDS, ids=[c[0] for c in COMMANDS])
@pytest.mark.parametrize(("mimic", "far"), [
    ('multiplier="1e308" offset="1e308"', "slides it out of a number's range"),
    ('offset="2e6"', "slides it 2e+06 m, beyond the 1e+06 m of any robot"),
    ('multiplier="nan"', "places it at no number")])
def test_a_sliding_follower_placed_beyond_any_robot_is_one_line(tmp_path, command, mimic, far):
    """multiplier and offset 1e308 put a finger 1e308 m out: simulate printed numpy's
    overflow warnings, distances to it being infinite."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace('<joint name="j2" type="revolute">',
                                                      '<joint name="j2" type="prismatic">')
                    .replace('multiplier="2"', mimic))
    extra = ("--out", str(tmp_path / "run")) if command[0] == "simulate" else ()
    result = run_servicebot(command[0], path, *command[1:], *extra)
    assert_one_line_error(result, 2, "joint 'j2' mimics 'j1' times", far)
    assert not (tmp_path / "run").exists()


def test_a_leader_that_is_there_still_drives_it(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1"))
    result = run_servicebot("fk", path, "-j", "j1=0.25", "-f", "b", "--format", "json")
    assert result.returncode == 0, result.stderr


def test_a_negative_friction_is_named_as_the_file_writes_it(tmp_path):
    """Pinocchio's words were "Some components of min_dry_friction are greater than
    max_dry_friction", at no joint; check reports SB216."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace(
        '<mimic joint="j1" multiplier="2"/>', '<dynamics damping="0.1" friction="-0.5"/>'))
    result = run_servicebot("fk", path, "-f", "b")
    line = assert_one_line_error(result, 2, "joint 'j2' has <dynamics friction=\"-0.5\">, which "
                                 "Pinocchio refuses")
    assert "min_dry_friction" not in line
    checked = run_servicebot("check", "urdf", path, "--isolated")
    assert "error SB216 [negative-dynamics]" in checked.stdout


def test_a_fixed_joint_s_dynamics_are_nobody_s(tmp_path):
    """Pinocchio reads the dynamics of joints that move along one axis only: a negative
    friction on a fixed joint is no refusal, and no SB216."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace(
        '<mimic joint="j1" multiplier="2"/>', "").replace(
        '<joint name="j1" type="revolute">', '<joint name="j1" type="fixed">').replace(
        '<axis xyz="0 0 1"/>\n    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>',
        '<dynamics friction="-0.5"/></joint>', 1))
    assert 'type="fixed"' in path.read_text() and 'friction="-0.5"' in path.read_text()
    assert run_servicebot("fk", path, "-f", "b").returncode == 0
    checked = run_servicebot("check", "urdf", path, "--isolated")
    assert "SB216" not in checked.stdout


def test_a_mimic_without_a_joint_attribute_says_so(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace('<mimic joint="j1" multiplier="2"/>',
                                                      '<mimic multiplier="2"/>'))
    line = assert_one_line_error(run_servicebot("fk", path, "-f", "b"), 2,
                                 "joint 'j2' mimics no joint (its <mimic> has no joint "
                                 "attribute)")
    assert "None" not in line


def test_inspect_shows_such_a_file_as_it_is(tmp_path):
    """inspect shows what a file holds, as RViz draws it (example-robot-data's Alex hands
    mimic a joint named 'index_q1' that the file does not have)."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j9"))
    result = run_servicebot("inspect", path, "--section", "joints")
    assert result.returncode == 0, result.stderr
    assert "j2" in result.stdout


@pytest.mark.parametrize("command", COMMANDS, ids=[c[0] for c in COMMANDS])
def test_limits_in_the_wrong_order_are_one_line_that_says_check_only_warns(tmp_path, command):
    """check passes such a file (SB203, a warning: pybullet reads it as no limit); the
    refusal pointed at check 'for details', which then said 'passed'."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace('lower="-1" upper="1"',
                                                      'lower="2.775" upper="-2.775"', 1))
    extra = ("--out", str(tmp_path / "run")) if command[0] == "simulate" else ()
    result = run_servicebot(command[0], path, *command[1:], *extra)
    line = assert_one_line_error(result, 2, "joint 'j1' has lower limit 2.775 above its upper "
                                 "limit -2.775", "check only warns: SB203", "continuous")
    assert "for details" not in line
    assert run_servicebot("check", "urdf", path, "--isolated").returncode == 0


def test_the_refusal_names_what_failed_the_model_not_a_link_urdfdom_kept(tmp_path):
    """urdfdom logs a link's unparsable <inertial> and keeps the link (model.cpp ignores
    parseLink's verdict); what fails the model is the joint without limits after it
    (urdf-importer-extension's crash_test.urdf)."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"><inertial><mass value="1"/>'
                    '</inertial></link><joint name="slide" type="prismatic">'
                    '<parent link="base_link"/><child link="carriage"/><axis xyz="1 0 0"/>'
                    '</joint><link name="carriage"/></robot>')
    line = assert_one_line_error(run_servicebot("fk", path, "-f", "carriage"), 2)
    assert "Joint [slide] is of type PRISMATIC without limits" in line
    assert "Inertial element" not in line


@pytest.mark.parametrize("xyz", ["0,0,0.45", "nan 0 0", "0 0"])
def test_an_origin_that_is_not_three_numbers_is_said_so(tmp_path, xyz):
    """fk said 'placed nan m from link ..., beyond the 1e+06 m of any robot'."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1").replace('<origin xyz="0.1 0 0"/>',
                                                      f'<origin xyz="{xyz}"/>'))
    line = assert_one_line_error(run_servicebot("fk", path, "-f", "b"), 2)
    assert "joint 'j2' has an <origin xyz> that is not three finite numbers" in line
    assert "nan m" not in line
