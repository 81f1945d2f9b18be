"""Scenario YAML read as YAML 1.2 (as README says), merge keys taken, no tag a crash.

PyYAML reads YAML 1.1: 'duration_s: 010' ran 8 s (octal), '1:30' 90 s (base 60), '1_0'
10 s and 'depth: yes' turned depth on, where YAML 1.2 and JSON read 10 and three strings.
A merge key ('<<: *segment', common in ROS YAML) or a tagged key ('!foo k: 1') ended the run
with an internal error (exit 3).
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import assert_one_line_error, run_servicebot


def _run(tmp_path, text: str, *extra: str):
    scenario = tmp_path / "scenario.yaml"
    scenario.write_text(text)
    return run_servicebot("simulate", "--headless", "-s", scenario, "--format", "json", *extra)


@pytest.mark.parametrize(("written", "seconds"), [("010", 10), ("0o10", 8), ("0x10", 16),
                                                  ("1e1", 10), ("+2", 2)])
def test_numbers_as_yaml_1_2_writes_them(tmp_path, written, seconds):
    result = _run(tmp_path, f"duration_s: {written}\n")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["duration_s"] == seconds


@pytest.mark.parametrize(("line", "message"), [
    ("duration_s: 1:30", "duration_s: expected a number, got '1:30'"),
    ("duration_s: 1_0", "duration_s: expected a number, got '1_0'"),
    ("duration_s: 1\ncamera: {depth: yes}", "camera.depth: expected true or false, got 'yes'")])
def test_what_only_yaml_1_1_reads_as_numbers_or_booleans_is_refused(tmp_path, line, message):
    assert_one_line_error(_run(tmp_path, line + "\n"), 2, message)


def test_a_merge_key_brings_its_mapping_and_written_keys_win(tmp_path):
    result = _run(tmp_path, "duration_s: 2\ncmd_vel:\n  - &segment {duration_s: 1, "
                            "linear_m_s: 0.02}\n  - <<: *segment\n    linear_m_s: 0.01\n")
    assert result.returncode == 0, result.stderr
    final = json.loads(result.stdout)["final_pose"]
    plain = _run(tmp_path, "duration_s: 2\ncmd_vel:\n  - {duration_s: 1, linear_m_s: 0.02}\n"
                           "  - {duration_s: 1, linear_m_s: 0.01}\n")
    assert final == json.loads(plain.stdout)["final_pose"]


def test_a_tagged_key_is_one_line(tmp_path):
    assert_one_line_error(_run(tmp_path, "!foo duration_s: 1\n"), 2,
                          "scenario.yaml:1: document: a key YAML cannot read")
