"""A board that resets when its port opens (``emulate --boot-s``), and drive reconnecting to it.

Everything goes over real pseudo-terminals: the emulator in its own process, the port opened
by drive's own transport or by ``servicebot drive`` itself. A replugged board is a symlink
(``--link``, as udev's /dev/serial/by-id names) moved to another emulator's device.
"""

from __future__ import annotations

import json
import os

from servicebot_cli.drive.session.reconnect import DEFAULT_ATTEMPTS, ReconnectPolicy
from servicebot_cli.drive.transport import Port, open_port
from tests.conftest import assert_one_line_error
from tests.drive.conftest import finish, servicebot, wait_for
from tests.drive.test_drive_pty import moving, state_when

ARDUINO = ("--protocol", "arduino", "--ticks-per-rev", "3436")


def ask(port: Port, command: str) -> str:
    """Send one ROSArduinoBridge command; its reply line."""
    port.write(command.encode() + b"\r")
    reply = bytearray()

    def line() -> bool:
        reply.extend(port.read_available())
        return reply.endswith(b"\r\n")

    wait_for(line, f"the reply to {command!r}")
    return reply.decode().strip()


def booted(emu, resets):
    return state_when(emu, lambda s: s["board"]["resets"] == resets and not s["board"]["booting"],
                      f"boot {resets}")


def test_each_open_resets_the_board_which_loses_what_it_hears_while_booting(emulator):
    emu = emulator(*ARDUINO, "--boot-s", "0.5")
    port = open_port(emu.path, 9600)
    port.write(b"e\r")  # to the bootloader: lost
    assert booted(emu, 1)["board"]["lost_bytes"] == 2
    assert ask(port, "m 100 100") == "OK"  # the first reply: "e" was never answered
    wait_for(moving(emu), "the wheels to turn")
    assert ask(port, "e") != "0 0"
    port.close()
    port = open_port(emu.path, 9600)
    state = booted(emu, 2)
    assert ask(port, "e") == "0 0"  # the encoder counts are forgotten
    assert not state["moving"] and state["counters"]["frames"] == 0  # a new firmware
    port.close()


def test_every_open_is_seen_however_quick(emulator):
    """Reopening within microseconds, as drive's reconnect does, is a reset every time."""
    emu = emulator("--boot-s", "0")
    for _ in range(20):
        open_port(emu.path, 9600).close()
    state = state_when(emu, lambda s: s["board"]["resets"] >= 20, "20 resets")
    assert state["board"]["resets"] == 20


def replug(link, old, new):
    """Point ``link`` at ``new``'s device (as udev does on a replug), then kill ``old``."""
    spare = link.with_name(link.name + ".new")
    os.symlink(new.state()["port"], spare)
    os.replace(spare, link)
    old.proc.kill()
    old.proc.communicate()


def test_drive_waits_out_the_boot_on_every_open_and_goes_on(emulator, tmp_path):
    link = tmp_path / "ttyACM0"
    first = emulator("--boot-s", "0.6", "--link", link)
    second = emulator("--boot-s", "0.6", "--link", tmp_path / "other")
    drive = servicebot("drive", "--port", link, "--reconnect", "--boot-time-s", "0.8",
                       "--linear", "0.02", "--duration-s", "5", "--format", "json")
    wait_for(moving(first), "the wheels to turn")
    assert first.state()["board"] == {"boot_s": 0.6, "resets": 1, "booting": False,
                                      "lost_bytes": 0}  # drive spoke only after the boot
    replug(link, first, second)
    code, stdout, stderr = finish(drive)
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["reconnects"] == 1 and summary["outcome"] == "completed"
    assert summary["stop_confirmed"]
    state = state_when(second, lambda s: s["counters"]["stops"] >= 2, "the final stop")
    assert state["board"]["resets"] == 1  # one open: no reset storm
    assert state["board"]["lost_bytes"] == 0  # the reconnect, too, waited out the boot
    assert state["counters"]["first_command"] == "STOP"  # zero first, then on
    assert all(w["position_rad"] > 0.05 for w in state["wheels"])
    assert "link back on" in stderr


def test_drive_gives_up_on_a_board_that_boots_longer_than_it_waits(emulator, tmp_path):
    link = tmp_path / "ttyACM0"
    first = emulator("--link", link)
    slow = emulator("--boot-s", "60", "--link", tmp_path / "other")
    drive = servicebot("drive", "--port", link, "--reconnect", "--reconnect-attempts", "3",
                       "--boot-time-s", "0.2", "--connect-timeout-s", "1",
                       "--linear", "0.02", "--duration-s", "60", "--format", "json")
    wait_for(moving(first), "the wheels to turn")
    replug(link, first, slow)
    code, stdout, stderr = finish(drive)
    assert code == 5, stderr
    errors = [line for line in stderr.splitlines() if line.startswith("Error:")]
    assert len(errors) == 1 and errors[0] == stderr.splitlines()[-1]
    assert "gave up reconnecting after 3 attempts" in errors[0]
    assert "waited 0.2 s for the board to boot and got no answer within 1 s" in errors[0]
    assert "needs --boot-time-s of at least its boot time" in errors[0]
    summary = json.loads(stdout)
    assert summary["outcome"] == "link_lost" and summary["reconnects"] == 0
    state = state_when(slow, lambda s: s["board"]["resets"] >= 3, "three resets")
    assert state["board"]["resets"] == 3  # one per attempt, and no more after the last
    assert state["counters"]["frames"] == 0  # it never got to answer


def test_reconnect_pauses_double_up_to_their_cap():
    policy = ReconnectPolicy()
    assert [policy.pause_s(n) for n in range(1, 6)] == [0.5, 1.0, 2.0, 4.0, 4.0]
    assert policy.attempts == DEFAULT_ATTEMPTS


def test_reconnect_attempts_need_reconnect(run):
    assert_one_line_error(run("drive", "--reconnect-attempts", "3", "--linear", "0.02",
                              "--duration-s", "1"), 2,
                          "--reconnect-attempts has no effect without --reconnect")
    assert_one_line_error(run("drive", "--reconnect", "--reconnect-attempts", "0"), 2,
                          "'--reconnect-attempts'")


def test_the_help_states_the_default_attempts(run):
    text = " ".join(run("drive", "--help").stdout.split())
    assert f"--reconnect-attempts N With --reconnect: attempts before a lost link ends the " \
           f"run (exit 5). [default: {DEFAULT_ATTEMPTS}" in text


def test_emulate_refuses_a_negative_boot(run):
    assert_one_line_error(run("emulate", "--boot-s", "-1"), 2, "'--boot-s'", "negative")
