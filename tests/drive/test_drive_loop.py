"""The drive loop itself, in process, against the emulator in another process."""

from __future__ import annotations

import pytest

from servicebot_cli.drive.driving import StreamSettings, run_drive
from servicebot_cli.drive.plan import Plan, Setpoint, Step
from servicebot_cli.drive.protocols.binary import BinaryLink
from tests.drive.conftest import wait_for


class Exploding:
    """A source with a bug: it raises after a while, mid-motion."""

    fds: tuple[int, ...] = ()

    def __init__(self, after_s: float) -> None:
        self.after_s = after_s

    def setpoint(self, t_s: float) -> Setpoint:
        if t_s > self.after_s:
            raise RuntimeError("a bug in the source")
        return Setpoint(0.03, 0.0)

    def poll(self) -> None:
        pass


def settings(path, **overrides):
    values = dict(port=path, baud=9600, rate_hz=20.0, max_accel_rad_s2=1.0,
                  link_timeout_s=1.0, connect_timeout_s=2.0)
    return StreamSettings(**{**values, **overrides})


def test_an_exception_stops_the_motors_before_it_propagates(emulator, real_motors):
    emu = emulator()
    lines = []
    with pytest.raises(RuntimeError, match="a bug in the source"):
        run_drive(settings(emu.path), BinaryLink(real_motors), real_motors, Exploding(0.8),
                  log=lines.append)
    state = wait_for(lambda: (s := emu.state())["counters"]["stops"] == 1 and s, "the stop")
    assert not state["moving"] and state["counters"]["watchdog_trips"] == 0
    assert any(w["position_rad"] > 0.1 for w in state["wheels"])  # it did drive first


def test_run_returns_a_summary_and_integrates_what_it_sent(emulator, real_motors):
    emu = emulator()
    plan = Plan([Step(1.0, 0.02, 0.0), Step(0.5, 0.0, 0.0)])
    statuses = []
    driven = run_drive(settings(emu.path), BinaryLink(real_motors), real_motors, plan,
                       log=lambda line: None, on_tick=statuses.append)
    summary = driven.summary
    assert driven.failure is None and summary is not None
    assert summary.outcome == "completed" and summary.stop_confirmed
    assert summary.commands == len(statuses) > 10  # one status per command sent
    assert statuses[-1].reply_rate_hz > 0 and statuses[-1].rtt_s is not None
    state = wait_for(lambda: (s := emu.state())["counters"]["stops"] == 1 and s, "the stop")
    for wheel, reported in zip(state["wheels"], summary.wheels, strict=True):
        assert wheel["position_rad"] == pytest.approx(reported.commanded_travel_rad, abs=0.01)
