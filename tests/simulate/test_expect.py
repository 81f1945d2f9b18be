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
