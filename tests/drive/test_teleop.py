"""Teleop on a real terminal (a pty), the emulator in another process; and key parsing."""

from __future__ import annotations

import fcntl
import os
import pty
import re
import select
import signal
import struct
import subprocess
import sys
import termios
import time

import pytest

from servicebot_cli.drive.teleop.keyboard import Teleop, parse_keys
from tests.conftest import REPO
from tests.drive.conftest import PATIENCE_S, wait_for

MEASURED_FORWARD = re.compile(r"L\+0\.\d\d/\+0\.(0[1-9]|[1-9])")


def test_keys():
    assert parse_keys(b"w\x1b[Aa\x1b[D s") == ["forward", "forward", "left", "left", "stop",
                                                  "back"]
    assert parse_keys(b"\x1b") == ["quit"] and parse_keys(b"zq") == ["quit"]


def test_keys_step_the_twist_within_the_limits():
    teleop = Teleop(0, 0.035, 0.13)
    for _ in range(15):
        teleop.apply("forward")
    teleop.apply("left")
    setpoint = teleop.setpoint(0.0)
    assert setpoint.linear_m_s == pytest.approx(0.035) and setpoint.angular_rad_s == \
        pytest.approx(0.013)
    teleop.apply("stop")
    assert teleop.setpoint(0.0).linear_m_s == 0.0
    teleop.apply("quit")
    assert teleop.setpoint(0.0) is None


class Terminal:
    """``servicebot drive`` with a pty as its controlling terminal."""

    def __init__(self, *args: object, columns: int = 200) -> None:
        self.master, slave = pty.openpty()
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
        self.before = termios.tcgetattr(slave)
        self.slave = slave

        def controlling_terminal() -> None:
            os.setsid()
            fcntl.ioctl(0, termios.TIOCSCTTY, 0)

        self.proc = subprocess.Popen(
            [sys.executable, "-m", "servicebot_cli", "drive", *map(str, args)], cwd=REPO,
            stdin=slave, stdout=slave, stderr=slave, preexec_fn=controlling_terminal)
        self.output = b""

    def read(self) -> str:
        while select.select([self.master], [], [], 0)[0]:
            try:
                self.output += os.read(self.master, 4096)
            except OSError:
                break
        return self.output.decode(errors="replace")

    def type(self, keys: bytes) -> None:
        os.write(self.master, keys)

    def finish(self) -> int:
        deadline = time.monotonic() + PATIENCE_S
        while self.proc.poll() is None and time.monotonic() < deadline:
            self.read()
            time.sleep(0.02)
        code = self.proc.wait(timeout=1)
        self.read()
        return code

    def close(self) -> None:
        os.close(self.master)
        os.close(self.slave)


@pytest.mark.parametrize(("ending", "code"), [(b"q", 0), (b"\x03", 130)])
def test_teleop_drives_shows_status_and_restores_the_terminal(emulator, ending, code):
    emu = emulator()
    terminal = Terminal("--port", emu.path)
    try:
        wait_for(lambda: "Hz rtt" in terminal.read(), "the status line")
        terminal.type(b"www")
        wait_for(lambda: any(w["velocity_rad_s"] > 0 for w in emu.state()["wheels"]),
                 "the wheels to turn forward")
        wait_for(lambda: MEASURED_FORWARD.search(terminal.read()),
                 "the measured speed on the status line")
        terminal.type(b"a")
        terminal.type(ending)
        assert terminal.finish() == code, terminal.read()
        assert termios.tcgetattr(terminal.slave) == terminal.before  # cbreak mode undone
        text = terminal.read()
        assert MEASURED_FORWARD.search(text) and "err 0" in text and "wasd/spc/q" in text
        wait_for(lambda: emu.state()["counters"]["stops"] == 1, "the stop")
        assert not emu.state()["moving"]
    finally:
        if terminal.proc.poll() is None:
            terminal.proc.kill()
        terminal.close()


def test_the_status_line_fits_a_narrow_terminal(emulator):
    emu = emulator()
    terminal = Terminal("--port", emu.path, columns=60)
    try:
        wait_for(lambda: "Hz rtt" in terminal.read(), "the status line")
        terminal.type(b"q")
        assert terminal.finish() == 0
        lines = [part for chunk in terminal.read().split("\r\x1b[K") for part in
                 chunk.split("\r\n") if part.startswith("v+")]
        assert lines and all(len(line) < 60 for line in lines)
    finally:
        terminal.close()


def test_a_hang_up_during_teleop_stops_the_motors_and_restores_the_terminal(emulator):
    emu = emulator()
    terminal = Terminal("--port", emu.path)
    try:
        wait_for(lambda: "Hz rtt" in terminal.read(), "the status line")
        terminal.type(b"ww")
        wait_for(lambda: any(w["velocity_rad_s"] > 0 for w in emu.state()["wheels"]),
                 "the wheels to turn forward")
        os.kill(terminal.proc.pid, signal.SIGHUP)
        assert terminal.finish() == 129, terminal.read()
        assert termios.tcgetattr(terminal.slave) == terminal.before  # cbreak mode undone
        assert "Error: hung up (SIGHUP); motors stopped (the firmware confirmed)" in \
            terminal.read()
        wait_for(lambda: emu.state()["counters"]["stops"] == 1, "the stop")
        assert not emu.state()["moving"] and emu.state()["counters"]["watchdog_trips"] == 0
    finally:
        if terminal.proc.poll() is None:
            terminal.proc.kill()
        terminal.close()


def test_the_dead_man_stops_the_wheels_when_no_key_comes():
    now = [0.0]
    teleop = Teleop(0, 0.035, 0.13, deadman_s=0.6, clock=lambda: now[0])
    teleop.apply("forward")
    teleop.last_key_s = 0.0
    now[0] = 0.5  # an auto-repeated key would arrive by now
    assert teleop.setpoint(0.5).linear_m_s > 0
    now[0] = 0.61
    assert teleop.setpoint(0.61).linear_m_s == 0.0 and teleop.deadman_trips == 1
    teleop.apply("forward")
    teleop.last_key_s = now[0]
    assert teleop.setpoint(0.62).linear_m_s == pytest.approx(0.0035)  # one step again


def test_the_status_line_fits_80_columns_and_shows_the_scaled_twist(real_motors):
    from servicebot_cli.drive.protocols.events import Reading
    from servicebot_cli.drive.session.contracts import LinkStatus
    from servicebot_cli.drive.teleop.keyboard import status_line

    reading = Reading(7, (0.0,) * 4, (-0.487, 0.5, -0.487, 0.5), None)
    status = LinkStatus(12.0, (-0.5, 0.5, -0.5, 0.5), reading, 20.0, 9.812, 999, 240, 230,
                        False, True)
    line = status_line(status, real_motors)
    assert len(line) <= 79
    # turning in place at the wheel limit: 0.5 rad/s * 0.07 m / 0.27 m = 0.13 rad/s
    assert line.startswith("v+0.000 w+0.130*") and "L-0.50/-0.49 R+0.50/+0.50" in line
    assert "20Hz rtt 9812ms err 999" in line and line.endswith("wasd/spc/q")


def test_ctrl_z_stops_the_wheels_before_suspending_and_fg_resumes(emulator):
    emu = emulator()
    terminal = Terminal("--port", emu.path)
    try:
        wait_for(lambda: "Hz rtt" in terminal.read(), "the status line")
        terminal.type(b"ww")
        wait_for(lambda: any(w["velocity_rad_s"] > 0 for w in emu.state()["wheels"]),
                 "the wheels to turn forward")
        terminal.type(b"\x1a")  # Ctrl-Z
        wait_for(lambda: "suspended (Ctrl-Z): motors stopped (the firmware confirmed)"
                 in terminal.read(), "the suspension")
        wait_for(lambda: _stopped_state(terminal.proc.pid), "the process to be stopped")
        wait_for(lambda: not emu.state()["moving"], "the wheels to stop")
        assert emu.state()["counters"]["stops"] == 1  # by drive, before it was suspended
        assert termios.tcgetattr(terminal.slave)[3] & termios.ICANON  # the shell's terminal
        time.sleep(1.5)  # longer than the link timeout
        os.kill(terminal.proc.pid, signal.SIGCONT)  # fg
        terminal.type(b"w")
        wait_for(lambda: any(w["velocity_rad_s"] > 0 for w in emu.state()["wheels"]),
                 "the wheels to turn again")
        terminal.type(b"q")
        assert terminal.finish() == 0, terminal.read()
        assert "link lost" not in terminal.read()
        assert termios.tcgetattr(terminal.slave) == terminal.before
    finally:
        if terminal.proc.poll() is None:
            terminal.proc.kill()
        terminal.close()


def _stopped_state(pid: int) -> bool:
    with open(f"/proc/{pid}/stat") as stat:
        return stat.read().rsplit(")", 1)[1].split()[0] == "T"


DEADMAN_MS = 300
TICK_S = 1 / 20  # drive's default --rate
SCHEDULING_S = 0.05  # a key reaching drive, a frame reaching the tap: allowance for both


def test_the_dead_man_stops_the_wheels_within_its_time_and_one_tick(emulator):
    """Keys every 100 ms keep the wheels going; after the last one they stop in MS + a tick.

    A tap on the line timestamps every SET_WHEELS as drive sends it (the same monotonic
    clock as the keys); --max-accel 20 ramps from full speed to zero within one tick.
    """
    from servicebot_cli.drive.protocols.framing import Decoder
    from servicebot_cli.drive.protocols.messages import MsgType, decode_values
    from tests.drive.relay import Noise, Relay

    emu = emulator()
    decoder, wheels = Decoder(), []  # (monotonic s, speeds) of every SET_WHEELS

    def tap(data: bytes) -> None:
        now = time.monotonic()
        wheels.extend((now, decode_values(frame)) for frame in decoder.feed(data)
                      if frame.type == MsgType.SET_WHEELS)

    relay = Relay(emu.path, Noise(), on_host=tap)
    terminal = Terminal("--port", relay.path, "--deadman-ms", DEADMAN_MS, "--max-accel", 20)
    try:
        wait_for(lambda: "Hz rtt" in terminal.read(), "the status line")
        first_key_s = time.monotonic()
        for _ in range(12):  # as keyboard auto-repeat does, slower than it
            terminal.type(b"w")
            last_key_s = time.monotonic()
            time.sleep(0.1)
        wait_for(lambda: any(t > last_key_s and not any(v) for t, v in wheels),
                 "a stop after the last key")
        held = [v for t, v in wheels if first_key_s + 0.2 < t <= last_key_s]
        assert held and all(all(s > 0 for s in v) for v in held)  # no early trip
        stopped_s = min(t for t, v in wheels if t > last_key_s and not any(v))
        assert DEADMAN_MS / 1000 < stopped_s - last_key_s <= (DEADMAN_MS / 1000 + TICK_S
                                                              + SCHEDULING_S)
        wait_for(lambda: not emu.state()["moving"], "the emulator's wheels to stop")
        terminal.type(b"q")
        assert terminal.finish() == 0, terminal.read()
        assert emu.state()["counters"]["watchdog_trips"] == 0  # drive stopped them, not it
    finally:
        if terminal.proc.poll() is None:
            terminal.proc.kill()
        terminal.close()
        relay.close()
