"""What emulate tells the user of itself: the baud rate it assumed, and a muted boot.

Through real processes and pseudo-terminals: ``servicebot emulate`` serving, ``servicebot
drive`` or drive's own transport opening the port.
"""

from __future__ import annotations

from servicebot_cli.drive.transport import open_port
from tests.conftest import REPO
from tests.drive.conftest import finish, servicebot
from tests.drive.test_drive_pty import state_when


def test_a_description_without_a_baud_rate_says_what_drive_needs(emulator, tmp_path):
    real = (REPO / "robots" / "service_robot_real.urdf.xml").read_text()
    assert '<param name="baud_rate">9600</param>' in real
    robot = tmp_path / "no_baud.urdf"
    robot.write_text(real.replace('<param name="baud_rate">9600</param>', ""))
    emu = emulator(robot)
    without = finish(servicebot("drive", robot, "--port", emu.path, "--linear", "0.02",
                                "--duration-s", "0.3"))
    assert without[0] == 2 and "names no baud_rate" in without[2] and "--baud" in without[2]
    code, _, stderr = finish(servicebot("drive", robot, "--port", emu.path, "--baud", "9600",
                                        "--linear", "0.02", "--duration-s", "0.3"))
    assert code == 0, stderr
    assert "the firmware says it runs at" not in stderr  # the baud rates agree
    _, said = emu.stop()
    lines = said.splitlines()
    assert "motor controller" in lines[0]  # the banner stays the first line
    assert ("no_baud.urdf names no baud_rate in <ros2_control><hardware>: the firmware runs "
            "at 9600 baud; give drive --baud 9600") in lines[1]


def test_a_description_with_a_baud_rate_gets_no_note(emulator):
    emu = emulator()
    _, said = emu.stop()
    assert "baud_rate" not in said


def test_a_board_muted_while_it_boots_does_not_claim_to_answer(emulator):
    emu = emulator("--boot-s", "1.0", "--mute-after-s", "0.3")
    port = open_port(emu.path, 9600)  # the board resets and boots for a second
    state_when(emu, lambda s: s["muted"] and not s["board"]["booting"] and s["board"]["resets"],
               "a muted board to boot")
    port.close()
    _, said = emu.stop()
    booted = [line for line in said.splitlines() if "booted" in line]
    assert len(booted) == 1, said
    assert "muted: it answers nothing (--mute-after-s)" in booted[0]
    assert "the firmware answers" not in said
