"""drive over a relay that flips, drops and inserts bytes, against the emulator.

With the servicebot protocol the CRC must keep every wrong command from being executed;
with ROSArduinoBridge (no checksum) drive must never crash, hang, or claim a stop that the
encoders did not show.
"""

from __future__ import annotations

import json
import time

import pytest

from tests.drive.conftest import finish, servicebot, wait_for
from tests.drive.relay import Noise, Relay

RATES = (0.001, 0.01, 0.03)  # per byte, all faults together, each way
EXITS = {0: "completed", 4: "link error or stop unconfirmed", 5: "link lost"}


def run_through(relay_path: str, *args: object) -> tuple[int, dict | None, str]:
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", relay_path, "--linear", "0.02", "--duration-s", "1.5",
        "--max-accel", "100", "--connect-timeout-s", "10", "--link-timeout-s", "2",
        "--format", "json", *args))
    assert "Traceback" not in stderr and "internal error" not in stderr, stderr
    assert code in EXITS, stderr
    return code, json.loads(stdout) if stdout.strip() else None, stderr


@pytest.fixture
def relay():
    made: list[Relay] = []

    def make(device: str, rate: float, seed: int) -> Relay:
        made.append(Relay(device, Noise(rate / 3, rate / 3, rate / 3, seed)))
        return made[-1]

    yield make
    for r in made:
        r.close()


@pytest.mark.parametrize("rate", RATES)
def test_servicebot_protocol_never_executes_a_wrong_command(emulator, relay, rate):
    emu = emulator()
    line = relay(emu.path, rate, seed=int(rate * 1000))
    code, summary, stderr = run_through(line.path)
    assert summary is not None, stderr
    state = wait_for(lambda: _with_commands(emu.state()), "the commands")
    sent = [[0.0] * 4, [0.285] * 4]  # 0.02 m/s / 0.07 m, rounded toward zero to mrad/s
    assert all(command in sent for command in state["counters"]["wheel_commands"]), state
    if rate >= 0.01:
        assert sum(line.noise.counts.values()) > 0
    if summary["stop_confirmed"]:
        assert code == 0
        assert not state_after_drive(emu)["moving"]


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("seed", [1, 2])
def test_arduino_protocol_never_crashes_hangs_or_claims_an_unseen_stop(emulator, relay,
                                                                       rate, seed):
    emu = emulator("--protocol", "arduino", "--ticks-per-rev", "3436")
    line = relay(emu.path, rate, seed=seed)
    code, summary, stderr = run_through(line.path, "--protocol", "arduino",
                                        "--ticks-per-rev", "3436")
    if summary is None:
        assert code == 4 and "no answer" in stderr or "answers, but" in stderr, stderr
        return
    if summary["stop_confirmed"]:
        assert code == 0 and summary["outcome"] == "completed", stderr
        assert not state_after_drive(emu)["moving"], "drive claimed a stop it did not see"
    else:
        assert code != 0 and "(the firmware confirmed)" not in stderr


def state_after_drive(emu) -> dict:
    """The emulator's first state written after drive exited (both use the monotonic clock)."""
    ended_s = time.monotonic()
    return wait_for(lambda: (lambda s: s if s["clock_s"] > ended_s else None)(emu.state()),
                    "a state written after drive ended")


def _with_commands(state: dict) -> dict | None:
    return state if state["counters"]["commands"] else None
