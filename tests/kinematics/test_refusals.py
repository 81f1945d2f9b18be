"""Inputs ``fk`` and ``ik`` refuse at once, with one line that says why."""

from __future__ import annotations

import json

from tests.conftest import assert_one_line_error


def test_a_fixed_joint_is_said_to_be_fixed_not_unknown(run):
    for args in (("fk", "-j", "arm_tool_joint=0.1"),
                 ("ik", "--position", "0.5", "0.2", "0.4", "--start", "arm_tool_joint=0.1")):
        result = run(*args)
        assert_one_line_error(result, code=2)
        assert "joint 'arm_tool_joint' is fixed: it has no value to give" in result.stderr
        assert "arm_" in result.stderr.split("one degree of freedom", 1)[1]  # the nearest ones
        assert "did you mean" not in result.stderr


def test_a_huge_target_is_one_clear_line_without_numpy_warnings(run):
    result = run("ik", "--position", "1e308", "0", "0")
    assert_one_line_error(result, code=2)
    assert "target position 1e+308 m is not a place a robot reaches" in result.stderr
    assert "Warning" not in result.stderr and result.stdout == ""


def test_a_target_beyond_reach_stops_after_one_attempt_whatever_the_budget(run):
    result = run("ik", "--position", "2", "1", "0.5", "--max-attempts", "100000000",
                 "--format", "json", "--seed", "1")
    assert result.exit_code == 1
    answer = json.loads(result.stdout)
    assert answer["attempts"] == 1 and not answer["success"]
    assert answer["hint"].startswith("out of reach: the target is 1.43 m beyond")


def test_a_floating_or_planar_joint_is_said_to_take_no_single_value(run, tmp_path):
    """fk said 'no joint free' of a joint inspect lists (urdf-importer-extension's
    test_floating.urdf), and suggested another joint's name."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
                    '<link name="d"/><joint name="hinge" type="continuous"><parent link="a"/>'
                    '<child link="b"/></joint><joint name="free" type="floating">'
                    '<parent link="b"/><child link="c"/></joint><joint name="slide" '
                    'type="planar"><parent link="b"/><child link="d"/></joint></robot>')
    for joint, kind, dimensions in (("free", "floating", "six"), ("slide", "planar", "three")):
        line = assert_one_line_error(run("fk", path, "-j", f"{joint}=0.3", "-f", "c"), 2)
        assert f"joint '{joint}' is {kind}: it moves in {dimensions} dimensions" in line
        assert "(hinge, ...)" in line
