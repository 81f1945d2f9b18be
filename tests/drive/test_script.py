"""The drive script format: parsing, timing, and errors that name the line."""

from __future__ import annotations

import pytest

from servicebot_cli.drive.plan import Plan, Setpoint
from servicebot_cli.drive.script import ScriptError, parse_script
from tests.conftest import assert_one_line_error

GOOD = """# a square-ish tour
twist 0.02 0 2.0          # forward
arm arm_base_to_link1=0.5 arm_link1_to_link2=-0.3
stop 0.5
twist 0 0.05 1.5
arm arm_base_to_link1=0
twist -0.01 0 1
"""


def test_a_script_becomes_timed_steps(real_motors):
    plan = Plan(parse_script(GOOD, "tour.txt", real_motors))
    assert plan.duration_s == pytest.approx(5.0)
    assert plan.setpoint(0.0) == Setpoint(0.02, 0.0, ())
    arm = (("arm_base_to_link1", 0.5), ("arm_link1_to_link2", -0.3))
    assert plan.setpoint(2.2) == Setpoint(0.0, 0.0, arm)
    assert plan.setpoint(3.0) == Setpoint(0.0, 0.05, arm)
    later = (("arm_base_to_link1", 0.0), ("arm_link1_to_link2", -0.3))  # targets accumulate
    assert plan.setpoint(4.5) == Setpoint(-0.01, 0.0, later)
    assert plan.setpoint(5.0) is None


@pytest.mark.parametrize(("text", "needle"), [
    ("twist 0.1 0\n", "tour.txt:1: twist LINEAR ANGULAR DURATION (m/s, rad/s, s) takes 3 values, "
                      "got 2"),
    ("stop 1\njump 2\n", "tour.txt:2: unknown command 'jump'; use twist, stop or arm"),
    ("twist 0.1 fast 1\n", "tour.txt:1: ANGULAR 'fast' is not a number"),
    ("twist 0.1 0 nan\n", "tour.txt:1: DURATION 'nan' is not a finite number"),
    ("stop 0\n", "tour.txt:1: DURATION must be positive, got 0"),
    ("stop 1\narm elbow=0.1\nstop 1\n", "tour.txt:2: no joint 'elbow' in service_robot's arm"),
    ("arm arm_base_to_link1=2\nstop 1\n", "tour.txt:1: joint 'arm_base_to_link1' = 2 rad is "
                                         "outside its limits [-1.57, 1.57] rad"),
    ("arm front_left_wheel_joint=1\nstop 1\n", "no joint 'front_left_wheel_joint' in "
                                               "service_robot's arm"),
    ("arm arm_base_to_link1\nstop 1\n", "tour.txt:1: 'arm_base_to_link1' is not NAME=VALUE"),
    ("stop 1\narm arm_base_to_link1=0.1\n", "tour.txt:2: arm targets after the last timed step "
                                            "are never sent"),
    ("# nothing\n\n", "tour.txt: no twist or stop lines, so nothing to drive"),
])
def test_errors_name_the_line(real_motors, text, needle):
    with pytest.raises(ScriptError) as error:
        parse_script(text, "tour.txt", real_motors)
    assert needle in str(error.value)


def test_a_bad_script_is_one_line_exit_2(run, tmp_path):
    script = tmp_path / "bad.txt"
    script.write_text("twist 0.02 0 1\ntwist 0.02 0\n")
    assert_one_line_error(run("drive", "--dry-run", "--script", script), 2, f"{script}:2:")


def test_script_errors_for_the_file_itself(run, tmp_path):
    assert_one_line_error(run("drive", "--dry-run", "--script", tmp_path / "none.txt"), 2,
                          "no such file")
    assert_one_line_error(run("drive", "--dry-run", "--script", tmp_path), 2, "is a directory")
    latin = tmp_path / "latin.txt"
    latin.write_bytes("stop 1 # caf\u00e9\n".encode("latin-1"))
    assert_one_line_error(run("drive", "--dry-run", "--script", latin), 2, "not UTF-8")


def test_a_script_from_stdin(run):
    result = run("drive", "--dry-run", "--script", "-", input="twist 0.02 0 0.1\n")
    assert result.exit_code == 0, result.stderr
    assert "SET_WHEELS" in result.stdout and result.stdout.rstrip().endswith("STOP seq=4")


def test_arm_lines_with_the_arduino_protocol_name_the_line(run, tmp_path):
    script = tmp_path / "arm.txt"
    script.write_text("stop 0.5\narm arm_base_to_link1=0.2\nstop 0.5\n")
    assert_one_line_error(run("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev",
                              "3436", "--script", script), 2, f"{script}:2:", "no arm")


def test_a_twist_beyond_the_limit_is_scaled_with_a_warning(run, tmp_path):
    script = tmp_path / "fast.txt"
    script.write_text("twist 1.0 0 0.1\n")
    result = run("drive", "--dry-run", "--script", script)
    assert result.exit_code == 0
    assert f"warning: {script}:1: twist 1 m/s, 0 rad/s needs 14.3 rad/s of the wheels" in \
        result.stderr
    assert "scaled to 0.035 m/s, 0 rad/s (curvature kept)" in result.stderr


def test_a_twist_exactly_at_the_limit_is_not_said_to_be_scaled(run):
    """0.01 m/s and 0.1 rad/s need exactly the diffbot's 1 rad/s (r 0.015 m, track 0.10 m);
    rounding made it 1.0000000000000002 and a warning that scaled nothing."""
    from tests.simulate.helpers import DIFFBOT

    args = ("drive", DIFFBOT, "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "1000",
            "--baud", "57600", "--duration-s", "1", "--linear", "0.01")
    result = run(*args, "--angular", "0.1")
    assert result.exit_code == 0 and "scaled" not in result.stderr, result.stderr
    result = run(*args, "--angular", "0.11")
    assert "needs 1.03 rad/s of the wheels" in result.stderr
