"""drive's and emulate's domain functions, called without the CLI: a request in, a result out."""

from __future__ import annotations

import os

import pytest

from servicebot_cli.description.loader import RobotSource
from servicebot_cli.drive.dry_run import DryRun
from servicebot_cli.drive.emulator.session import EmulateRequest, emulate
from servicebot_cli.drive.emulator.wire import Faults
from servicebot_cli.drive.request import BadOption, DriveRequest, Keyboard, OneShot
from servicebot_cli.drive.run import drive
from servicebot_cli.drive.teleop.terminal import NoTerminal, Terminal
from servicebot_cli.output.drive_text import done_line, dry_run_lines, emulate_end_line

REAL = RobotSource.bundled("real")


def request(mode, **overrides):
    values = dict(robot=REAL, mode=mode, protocol="servicebot", arduino=None, port=None,
                  baud=None, rate_hz=20.0, max_accel_rad_s2=1.0, link_timeout_s=1.0,
                  connect_timeout_s=2.0, dry_run=True)
    return DriveRequest(**{**values, **overrides})


def test_a_dry_run_is_a_result_and_warnings_go_to_the_log():
    lines = []
    result = drive(request(OneShot(0.03, 0.1, 0.1)), log=lines.append)
    assert isinstance(result, DryRun)
    assert [f.meaning.split()[0] for f in result.frames] == ["PING", "SET_WHEELS",
                                                             "SET_WHEELS", "STOP"]
    assert len(lines) == 1 and lines[0].startswith("warning: --linear/--angular: twist 0.03")
    text = list(dry_run_lines(result))
    assert text[0].startswith("# servicebot protocol, 20 Hz, 0.1 s")
    assert text[-1].endswith(result.frames[-1].meaning)


def test_a_rate_the_link_cannot_carry_names_the_option():
    with pytest.raises(BadOption) as caught:
        drive(request(OneShot(0.0, 0.0, 1.0), rate_hz=31.0), log=print)
    assert caught.value.option == "--rate" and "at most 30.0 Hz" in str(caught.value)


def test_teleop_without_a_terminal_is_refused_before_any_port(tmp_path):
    with (tmp_path / "keys").open("w+") as keys, (tmp_path / "status").open("w+") as status:
        with pytest.raises(NoTerminal, match="teleop needs a terminal"):
            drive(request(Keyboard(), dry_run=False, port=str(tmp_path / "none")),
                  log=print, terminal=Terminal(keys, status))


def test_the_emulator_serves_a_pty_until_it_dies():
    devices, lines = [], []
    result = emulate(EmulateRequest(REAL, "servicebot", None, None, None,
                                    Faults(die_after_s=0.3), 0, False),
                     log=lines.append, announce=devices.append)
    assert result.ending == "died" and emulate_end_line(result) == "port closed"
    assert len(devices) == 1 and devices[0].startswith("/dev/pts/")
    assert not os.path.exists(devices[0])  # the pty is gone with the emulator
    assert "motor controller (servicebot protocol, watchdog 500 ms, unpaced)" in lines[0]
    assert "dying now" in lines[-1] and "--die-after-s" in lines[-1]


def test_the_done_line():
    from servicebot_cli.drive.driving import Summary

    summary = Summary("servicebot", "/dev/pts/1", 9600, "v1", "completed", 1.04, 20.0, 20, 21,
                      0.01, 0, 0, True, (), ())
    assert done_line(summary) == ("done: 20 commands and 21 replies in 1.0 s, 0 errors, "
                                  "0 reconnects; motors stopped (the firmware confirmed)")
