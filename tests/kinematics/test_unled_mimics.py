"""A <mimic> of itself or of a joint that is not there: no joint drives the follower.

fk, inspect and simulate took such a joint as free, without a word, where MoveIt refuses
the robot and yourdfpy sets the joint to its offset. check reports SB210 and SB209; every
command that builds the model now refuses the robot in one line naming the joint.
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
            ("inspect", "--section", "joints"), ("simulate", "--headless", "--duration-s", "0.1")]


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


def test_a_leader_that_is_there_still_drives_it(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(leader="j1"))
    result = run_servicebot("fk", path, "-j", "j1=0.25", "-f", "b", "--format", "json")
    assert result.returncode == 0, result.stderr
