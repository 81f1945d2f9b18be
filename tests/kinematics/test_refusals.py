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
        assert "arm_" in result.stderr.split("movable joint", 1)[1]  # the nearest movable ones
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
