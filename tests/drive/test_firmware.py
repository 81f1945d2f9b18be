"""firmware/: the C++ servicebot firmware, built for this host and driven by drive.

The host build runs the board-independent controller (framing, CRC, sequence numbers,
replies, watchdog, telemetry) on a pseudo-terminal with simulated motors; `servicebot drive`
talks to it exactly as to the board. The Uno build proves the same code fits an ATmega328P.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from tests.drive.conftest import PATIENCE_S, finish, servicebot, wait_for
from tests.drive.firmware_build import avr_missing, build_host, build_uno
from tests.drive.relay import Noise, Relay

FLASH_BYTES, RAM_BYTES = 32768, 2048
BOOTLOADER_BYTES = 512  # optiboot, at the top of the Uno's flash


@pytest.fixture(scope="module")
def host_firmware(tmp_path_factory) -> Path:
    if shutil.which("g++") is None:
        pytest.skip("building the host firmware needs g++ (apt-get install g++)")
    return build_host(tmp_path_factory.mktemp("firmware"))


class Board:
    """The host firmware running in another process, its state in a JSON file."""

    def __init__(self, binary: Path, state_file: Path) -> None:
        self.state_file = state_file
        self.proc = subprocess.Popen([binary, state_file], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
        assert self.proc.stdout is not None
        self.path = self.proc.stdout.readline().strip()
        wait_for(state_file.exists, "the firmware's first state")

    def state(self) -> dict:
        return json.loads(self.state_file.read_text())

    def after(self, t_s: float) -> dict:
        """The first state written after ``t_s`` (monotonic clock, as the firmware's)."""
        return wait_for(lambda: (lambda s: s if s["clock_s"] > t_s else None)(self.state()),
                        "a newer firmware state")

    def stop(self) -> dict:
        self.proc.terminate()
        stdout, _ = self.proc.communicate(timeout=PATIENCE_S)
        assert self.proc.returncode == 0
        return json.loads(stdout.strip().splitlines()[-1])


@pytest.fixture
def board(host_firmware, tmp_path):
    started: list[Board] = []

    def start() -> Board:
        started.append(Board(host_firmware, tmp_path / f"board{len(started)}.json"))
        return started[-1]

    yield start
    for b in started:
        if b.proc.poll() is None:
            b.proc.kill()
        b.proc.communicate()


def test_drive_runs_a_script_on_the_cpp_firmware(board, tmp_path):
    fw = board()
    script = tmp_path / "tour.txt"
    script.write_text("twist 0.03 0 1.0\ntwist 0 0.2 0.8\narm arm_base_to_link1=0.3\n"
                      "stop 0.5\n")
    code, stdout, stderr = finish(servicebot("drive", "--port", fw.path, "--script", script,
                                             "--format", "json"))
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["firmware"] == "servicebot protocol v1, firmware 1.0, watchdog 500 ms"
    assert summary["stop_confirmed"] and summary["errors"] == 0
    state = fw.after(time.monotonic())
    assert not state["moving"] and state["stops"] == 1 and state["watchdog_trips"] == 0
    assert state["max_abs_wheel_command_mrad_s"] <= 500
    for wheel, reported in zip(state["wheels_rad"], summary["wheels"], strict=True):
        assert reported["measured_travel_rad"] == pytest.approx(wheel, abs=0.002)
        assert reported["commanded_travel_rad"] == pytest.approx(wheel, rel=0.05, abs=0.01)
    assert state["arm_rad"][0] == pytest.approx(0.3, abs=0.002)
    assert state["wheels_rad"][1] - state["wheels_rad"][0] > 0.2  # the turn in place


def test_the_cpp_watchdog_stops_the_motors_when_drive_is_killed(board):
    fw = board()
    drive = servicebot("drive", "--port", fw.path, "--linear", "0.03", "--duration-s", "60")
    wait_for(lambda: fw.state()["moving"], "the wheels to turn")
    drive.kill()
    drive.communicate()
    state = wait_for(lambda: (lambda s: s if s["watchdog_trips"] else None)(fw.state()),
                     "the firmware's watchdog")
    assert not state["moving"] and state["stops"] == 0


@pytest.mark.parametrize("rate", [0.001, 0.01, 0.03])
def test_the_cpp_firmware_never_executes_a_wrong_command_on_a_noisy_line(board, rate):
    fw = board()
    line = Relay(fw.path, Noise(rate / 3, rate / 3, rate / 3, seed=7))
    try:
        code, stdout, stderr = finish(servicebot(
            "drive", "--port", line.path, "--linear", "0.02", "--duration-s", "1.5",
            "--max-accel", "100", "--connect-timeout-s", "10", "--link-timeout-s", "2",
            "--format", "json"))
    finally:
        line.close()
    assert code in (0, 4, 5) and "Traceback" not in stderr, stderr
    final = fw.stop()
    assert all(c in ([0] * 4, [285] * 4) for c in final["wheel_commands_mrad_s"]), final
    if rate >= 0.01:
        assert final["crc_errors"] > 0
    if json.loads(stdout)["stop_confirmed"]:
        assert not final["moving"]


def test_the_firmware_fits_an_arduino_uno(tmp_path):
    missing = avr_missing()
    if missing:
        pytest.skip(missing)
    flash, ram = build_uno(tmp_path)
    print(f"ATmega328P: flash {flash} of {FLASH_BYTES} bytes, RAM {ram} of {RAM_BYTES} bytes")
    assert flash <= FLASH_BYTES - BOOTLOADER_BYTES
    assert ram <= RAM_BYTES * 3 // 4  # a quarter left for the stack
