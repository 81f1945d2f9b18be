"""``--dry-run``: the frames a run would send, with their meaning, and no port.

The same commander builds the same bytes as a real run, on a virtual clock at the command
rate, so what is printed is what would go on the wire (the handshake, every tick, the stop).
"""

from __future__ import annotations

from collections.abc import Iterator

from servicebot_cli.link.commander import Commander, HostLink
from servicebot_cli.link.motors import MotorMap
from servicebot_cli.link.plan import Plan
from servicebot_cli.link.shaping import WheelShaper


def dry_run_lines(plan: Plan, link: HostLink, motors: MotorMap,
                  max_accel_rad_s2: float, rate_hz: float) -> Iterator[str]:
    """Lines ``t_s  hex bytes  meaning``, one per frame, after a short header."""
    commander = Commander(link, WheelShaper(motors, max_accel_rad_s2), motors)
    commander.observe_arm(motors.clamp_arm([0.0] * len(motors.arm_joints)))
    yield (f"# {link.name} protocol, {rate_hz:g} Hz, {plan.duration_s:g} s; the frames a run "
           "would send (no port opened)")
    if link.has_arm:
        yield "# arm joints a plan does not name hold 0 rad here (a real run: where they are)"
    yield "# t_s  bytes  meaning"
    yield _line(0.0, link.hello(), link)
    period = 1.0 / rate_hz
    tick = 0
    t_s = 0.0
    while (setpoint := plan.setpoint(tick * period)) is not None:
        t_s = tick * period
        data, _, _ = commander.command(setpoint, t_s, period)
        yield _line(t_s, data, link)
        tick += 1
    data, _ = commander.stop(tick * period)
    yield _line(tick * period, data, link)


def _line(t_s: float, data: bytes, link: HostLink) -> str:
    return f"{t_s:7.3f}  {data.hex(' ')}  {link.describe(data)}"
