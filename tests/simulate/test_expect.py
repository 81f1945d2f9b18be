"""simulate --expect: a run that does not meet an expectation says no (exit 1), for CI."""

from __future__ import annotations

import json

import pytest

from tests.conftest import assert_one_line_error

SHORT = ("simulate", "--headless", "--duration-s", "10")


def test_met_expectations_exit_0(run):
    result = run(*SHORT, "--expect", "collisions == 0", "--expect", "distance_m > 0.1")
    assert result.exit_code == 0, result.stderr


def test_an_unmet_expectation_exits_1_with_the_value_it_had(run):
    result = run(*SHORT, "--expect", "collisions == 0", "--expect", "distance_m > 100",
                 "--format", "json")
    summary = json.loads(result.stdout)  # the summary is still printed, whole
    assert result.exit_code == 1
    errors = [ln for ln in result.stderr.splitlines() if ln.startswith("Error:")]
    assert errors == [f"Error: 1 of the run's expectations not met: distance_m > 100 "
                      f"(is {summary['distance_m']:g})"]


@pytest.mark.parametrize(("expression", "needle"), [
    ("colisions == 0", "did you mean 'collisions'"),
    ("collisions = 0", "is not FIELD OP NUMBER"),
    ("distance_m < nan", "is not FIELD OP NUMBER"),
    ("odometry_drift.final_possition_m < 1", "did you mean 'final_position_m'"),
])
def test_a_bad_expectation_is_refused_before_the_run(run, expression, needle):
    assert_one_line_error(run(*SHORT, "--expect", expression), 2, "--expect", needle)


def test_sweep_and_simulate_share_one_parser():
    """The sweep's expect: list and simulate --expect are read by the same module."""
    import ast
    import inspect

    from servicebot_cli.sweep import session

    imported = {node.module for node in ast.walk(ast.parse(inspect.getsource(session)))
                if isinstance(node, ast.ImportFrom)}
    assert "servicebot_cli.simulate.expectations" in imported
    assert not any("expectations" in name for name in imported
                   if name and name.startswith("servicebot_cli.sweep"))


def test_yaml_numbers_as_people_write_them(run, tmp_path):
    scenario = tmp_path / "s.yaml"
    scenario.write_text("duration_s: 1e1\ncmd_vel:\n"
                        "  - {start_s: 0, duration_s: 5e0, linear_m_s: 5e-2}\n")
    result = run("simulate", "--headless", "-s", scenario, "--format", "json")
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["duration_s"] == 10.0


def test_a_topic_count_and_a_controller_value_can_be_expected(run):
    counted = run(*SHORT, "--format", "json")
    summary = json.loads(counted.stdout)
    scans, radius = summary["messages"]["/scan"], summary["controller"]["wheel_radius_m"]["value"]
    assert scans > 0 and radius > 0
    met = run(*SHORT, "--expect", f"messages./scan == {scans}",
              "--expect", "messages./pi_camera/camera_info >= 1",
              "--expect", f"controller.wheel_radius_m.value == {radius!r}")
    assert met.exit_code == 0, met.stderr
    unmet = run(*SHORT, "--expect", f"messages./scan > {scans}", "--expect",
                "messages./scna >= 1")
    errors = [ln for ln in unmet.stderr.splitlines() if ln.startswith("Error:")]
    assert unmet.exit_code == 1 and len(errors) == 1, unmet.stderr
    assert f"messages./scan > {scans} (is {scans})" in errors[0]
    assert "messages./scna >= 1 (no value: the run has no '/scna' in messages, which holds " \
        "/robot_description" in errors[0] and "/scan" in errors[0]


@pytest.mark.parametrize(("expression", "needle"), [
    ("controller.wheel_radus_m.value > 0", "did you mean 'wheel_radius_m'"),
    ("controller.wheel_radius_m > 0", "compare one of them, e.g. controller.wheel_radius_m.value"),
    ("messages > 0", "e.g. messages./scan"),
    ("messages[0] > 0", "keyed by name"),
    ("final_pose > 0", "e.g. final_pose.x_m"),
    ("end_effector.frame > 0", "end_effector.frame is text"),
    ("closest_obstacle > 0", "closest_obstacle is text"),
    ("collisions.x_m > 0", "an item, collisions[0].x_m"),
    ("collisions[0].x > 0", "'x' is not a field of collisions[0]"),
    ("distance_m.x > 0", "nothing below it"),
    ("controller.saturation.value == 1", "controller.saturation.value is text"),
])
def test_a_field_that_holds_no_number_is_refused_before_the_run(run, expression, needle):
    assert_one_line_error(run(*SHORT, "--expect", expression), 2, "--expect", needle)
