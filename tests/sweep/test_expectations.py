"""Exit 0 when every run meets every expectation, 1 with a table of the runs that do not."""

from __future__ import annotations

import csv
import json

import pytest

from servicebot_cli.simulate.expectations import ExpectationError, parse_expectation

SUMMARY = {"collisions": [{"time_s": 1.0}], "distance_m": 2.5,
           "odometry_drift": {"final_position_m": 0.3}, "odometry_final_pose": None,
           "end_effector": {"frame": "tool", "position_m": [0.1, 0.2, 0.6]}}


@pytest.mark.parametrize(("text", "holds"), [
    ("collisions == 1", True), ("collisions == 0", False), ("collisions < 1", False),
    ("distance_m >= 2.5", True), ("distance_m > 2.5", False), ("distance_m != 2.5", False),
    ("odometry_drift.final_position_m < 0.5", True), ("odometry_drift.final_position_m<.25",
                                                      False),
    ("end_effector.position_m[2] > 5e-1", True), ("odometry_final_pose.x_m < 100", False),
])
def test_expectations_compare_summary_fields(text, holds):
    assert parse_expectation(text).holds(SUMMARY) is holds


@pytest.mark.parametrize("text", ["collisions", "collisions == ", "== 0", "collisions ~= 0",
                                  "collisions == 1e999", "len(collisions) == 0",
                                  "collisions == 0 or True", "distance_meters > 1"])
def test_malformed_expectations_are_refused(text):
    with pytest.raises(ExpectationError):
        parse_expectation(text)


def test_all_expectations_hold_exit_0(run, write_sweep, tmp_path):
    sweep = write_sweep({"seeds": 2, "set": {"duration_s": 5},
                         "grid": {"slip.track_factor": [0.9, 1.1]},
                         "expect": ["collisions == 0", "distance_m > 0"]})
    result = run("sweep", sweep, "--out", tmp_path / "out")
    assert result.exit_code == 0, result.stderr
    assert "finished 4, 4 passed, 0 failed" in result.stdout


def test_a_failing_expectation_exits_1_with_the_failing_runs(run, write_sweep, tmp_path):
    # A wheel separation multiplier that does not match the floor makes odometry drift when
    # the robot turns (the default scenario's first turn starts at 30 s).
    sweep = write_sweep({"seeds": 2, "set": {"duration_s": 45},
                         "grid": {"controller.wheel_separation_multiplier": [1.1, 1.5]},
                         "expect": ["collisions == 0",
                                    "odometry_drift.final_yaw_rad < 0.1"]})
    out = tmp_path / "out"
    result = run("sweep", sweep, "--out", out)
    assert result.exit_code == 1
    assert result.stderr.splitlines()[-1] == ("Error: 2 of 4 runs failed an expectation "
                                             "(table above)")
    lines = result.stdout.splitlines()
    header = lines.index(next(ln for ln in lines if ln.startswith("run ")))
    failing = lines[header + 2:]
    assert len(failing) == 2
    assert all("controller.wheel_separation_multiplier=1.5" in ln for ln in failing)
    assert all("odometry_drift.final_yaw_rad < 0.1" in ln for ln in failing)

    rows = list(csv.DictReader((out / "runs.csv").open()))
    bad = [r for r in rows if r["passed"] == "False"]
    assert [float(r["odometry_drift.final_yaw_rad"]) >= 0.1 for r in rows] == \
        [r["passed"] == "False" for r in rows]
    assert len(bad) == 2
    summary = json.loads((out / "summary.json").read_text())
    assert summary["failed"] == 2 and summary["passed"] == 2
    assert summary["expectations"] == [
        {"expect": "collisions == 0", "failed_runs": 0},
        {"expect": "odometry_drift.final_yaw_rad < 0.1", "failed_runs": 2}]
    assert sorted(r["run"] for r in summary["failed_runs"]) == \
        sorted(int(r["run"]) for r in bad)


def test_a_json_report_is_not_called_a_table(run, write_sweep, tmp_path):
    """With --format json the stderr line still pointed at a '(table above)' that was not."""
    sweep = write_sweep({"seeds": 1, "set": {"duration_s": 1}, "expect": ["collisions > 0"]})
    result = run("sweep", sweep, "--out", tmp_path / "out", "--format", "json")
    assert result.exit_code == 1
    assert result.stderr.splitlines()[-1] == ("Error: 1 of 1 runs failed an expectation "
                                             "(failed_runs in the report above)")
    assert json.loads(result.stdout)["failed_runs"]
