"""One rule for every option of drive and emulate: units in the names, no option without effect.

Each refusal is one line and exit 2, before any port opens (a real pty checks that nothing
was sent).
"""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error

ONE_SHOT = ("--linear", "0.02", "--duration-s", "1")


@pytest.mark.parametrize(("command", "old", "new"), [
    ("drive", "--duration", "--duration-s"),
    ("drive", "--link-timeout", "--link-timeout-s"),
    ("drive", "--connect-timeout", "--connect-timeout-s"),
    ("emulate", "--latency", "--latency-s"),
    ("emulate", "--die-after", "--die-after-s"),
    ("emulate", "--mute-after", "--mute-after-s"),
])
def test_durations_carry_their_unit(run, command, old, new):
    assert_one_line_error(run(command, old, "1"), 2, f"No such option '{old}'",
                          f"'{new}'")  # click suggests the new spelling


@pytest.mark.parametrize(("option", "value"), [
    ("--log", "run.csv"), ("--reconnect", None), ("--connect-timeout-s", "3"),
    ("--link-timeout-s", "3"), ("--port", "/dev/ttyUSB1"), ("--boot-time-s", "1.5"),
    ("--reconnect-attempts", "3"),
])
def test_dry_run_refuses_what_only_a_port_uses(run, option, value):
    args = (option,) if value is None else (option, value)
    assert_one_line_error(run("drive", "--dry-run", *ONE_SHOT, *args), 2,
                          f"{option} has no effect with --dry-run", f"drop {option} or --dry-run")
    assert run("drive", "--dry-run", *ONE_SHOT).exit_code == 0  # and without it, it runs


@pytest.mark.parametrize("command", ["drive", "emulate"])
@pytest.mark.parametrize(("option", "value"), [("--ticks-per-rev", "3436"), ("--pid-rate", "50")])
def test_arduino_options_need_the_arduino_protocol(run, command, option, value):
    extra = ("--dry-run", *ONE_SHOT) if command == "drive" else ()
    assert_one_line_error(run(command, option, value, *extra), 2,
                          f"{option} has no effect without --protocol arduino")


def _largest_m_ticks(stdout):
    return max(int(word) for line in stdout.splitlines() if "'m " in line
               for word in line.split("'m ")[1].split("'")[0].split())


def test_the_arduino_options_with_the_arduino_protocol(run):
    arduino = ("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "3436",
               "--linear", "0.05", "--duration-s", "1")
    at_30, at_60 = run(*arduino), run(*arduino, "--pid-rate", "60")
    assert at_30.exit_code == at_60.exit_code == 0, at_60.stderr
    # the same speed is half as many ticks per interval when the PID loop runs twice as often
    assert _largest_m_ticks(at_30.stdout) == 9 and _largest_m_ticks(at_60.stdout) == 4


def test_a_log_that_is_not_csv_fails_before_the_port_opens(run, tmp_path, fake_device):
    device = fake_device()
    assert_one_line_error(run("drive", "--port", device.path, "--log", tmp_path / "run.txt",
                              *ONE_SHOT), 2, "Invalid value for '--log'", "files end in .csv")
    assert_one_line_error(run("drive", "--port", device.path, "--log", tmp_path, *ONE_SHOT),
                          2, "Invalid value for '--log'")
    assert device.received == b"" and list(tmp_path.iterdir()) == []


def test_a_state_file_that_is_not_json(run, tmp_path):
    result = run("emulate", "--state-file", tmp_path / "state.yaml")
    assert_one_line_error(result, 2, "Invalid value for '--state-file'", "files end in .json")
    assert result.stdout == ""  # no device was announced


def test_a_seed_without_random_faults_has_no_effect(run):
    assert_one_line_error(run("emulate", "--seed", "3"), 2,
                          "--seed has no effect without --drop P or --corrupt P")


def test_a_mute_after_the_death_never_happens(run):
    assert_one_line_error(run("emulate", "--die-after-s", "1", "--mute-after-s", "2"), 2,
                          "Invalid value for --mute-after-s", "never happens")


def test_the_port_and_baud_need_a_description_or_an_option(run):
    """A value only the description rules out is still one line naming the option."""
    assert_one_line_error(run("drive", "--robot", "sim", "--dry-run", *ONE_SHOT), 2,
                          "Invalid value for --baud", "names no baud_rate")
