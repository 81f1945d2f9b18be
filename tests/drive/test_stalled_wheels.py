"""Wheels commanded to turn whose encoders do not count: the run stops, and says why.

The real ROSArduinoBridge with its encoder cable pulled answered '0 0' to every 'e' while its
PID drove the motors towards full power; drive ended 'done ... 0 errors; motors stopped (the
firmware confirmed)', exit 0. Here ``servicebot emulate --stall-after-s`` freezes the wheels
(commands still answered), over a real pseudo-terminal.
"""

from __future__ import annotations

import json

import pytest

from tests.drive.conftest import finish, servicebot

ARDUINO = ("--protocol", "arduino", "--ticks-per-rev", "3436")


@pytest.mark.parametrize("protocol", [(), ARDUINO], ids=["servicebot", "arduino"])
def test_wheels_that_stop_turning_mid_run_stop_the_run(emulator, protocol):
    emu = emulator(*protocol, "--stall-after-s", "0.5")
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", emu.path, *protocol, "--linear", "0.03", "--duration-s", "6",
        "--format", "json"))
    assert code == 4, stderr
    summary = json.loads(stdout)
    assert summary["outcome"] == "wheels_stalled" and not summary["stop_confirmed"]
    assert summary["duration_s"] < 4  # the second after the stall, not the six asked for
    (line,) = [ln for ln in stderr.splitlines() if ln.startswith("Error:")]
    assert "wheels stalled: wheel '" in line and "its encoder did not count once" in line
    assert "stop sent but not confirmed" in line


def test_encoders_that_never_count_confirm_no_stop(emulator):
    """A run shorter than the stall window: its end proves nothing stopped."""
    emu = emulator(*ARDUINO, "--stall-after-s", "0.001")
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", emu.path, *ARDUINO, "--linear", "0.03", "--duration-s", "0.6",
        "--format", "json"))
    summary = json.loads(stdout)
    assert code == 4 and summary["outcome"] == "stop_unconfirmed", stderr
    assert not summary["stop_confirmed"]
    assert "no encoder on" in stderr and "counted once" in stderr


def test_wheels_that_turn_are_never_stalled(emulator):
    emu = emulator(*ARDUINO)
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", emu.path, *ARDUINO, "--linear", "0.03", "--duration-s", "2.5",
        "--format", "json"))
    assert code == 0, stderr
    assert json.loads(stdout)["stop_confirmed"]


def test_a_gap_in_the_readings_starts_every_streak_again():
    """The stall window counts commanded time with readings, never across a reconnect."""
    from servicebot_cli.drive.session.stall import WINDOW_S, StallWatch

    def watched(restart: bool) -> StallWatch:
        watch = StallWatch(["left", "right"])
        watch.observe(0.0, [0.0, 0.0], [0.4, 0.4])
        watch.observe(0.5, [0.0, 0.0], [0.4, 0.4])  # not counted yet
        if restart:
            watch.restart()  # the link back, after WINDOW_S without readings
        watch.observe(0.5 + 2 * WINDOW_S, [0.0, 0.0], [0.4, 0.4])
        return watch

    assert watched(restart=False).stalled is not None
    watch = watched(restart=True)
    assert watch.stalled is None
    watch.observe(0.6 + 3 * WINDOW_S, [0.0, 0.0], [0.4, 0.4])  # a whole window since: stalled
    assert watch.stalled is not None
