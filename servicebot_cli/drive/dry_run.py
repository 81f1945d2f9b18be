"""``--dry-run``: the frames a run would send, with their meaning, and no port.

The same commander builds the same bytes as a real run, on a virtual clock at the command
rate, so what is printed is what would go on the wire (the handshake, every tick, the stop).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Plan
from servicebot_cli.drive.request import BadOption
from servicebot_cli.drive.session.commander import Commander, HostLink
from servicebot_cli.drive.shaping import WheelShaper


@dataclass(frozen=True)
class PlannedFrame:
    """One frame a run would send.

    Attributes:
        t_s: When, after the start [s].
        bytes_hex: The bytes, in hex.
        meaning: What they say, decoded.
    """

    t_s: float
    bytes_hex: str
    meaning: str


def planned_frames(plan: Plan, link: HostLink, motors: MotorMap, max_accel_rad_s2: float,
                   rate_hz: float) -> Iterator[PlannedFrame]:
    """The handshake, every tick of ``plan`` at ``rate_hz`` and the stop, in order."""
    commander = Commander(link, WheelShaper(motors, max_accel_rad_s2), motors)
    commander.observe_arm(assumed_arm(motors))
    yield _frame(0.0, link.hello(), link)
    period = 1.0 / rate_hz
    tick = 0
    while (setpoint := plan.setpoint(tick * period)) is not None:
        data, _, _ = commander.command(setpoint, tick * period, period)
        yield _frame(tick * period, data, link)
        tick += 1
    data, _ = commander.stop(tick * period)
    yield _frame(tick * period, data, link)


def assumed_arm(motors: MotorMap) -> tuple[float, ...]:
    """Where a dry run takes the arm to start: 0 rad, or the nearest limit [rad]."""
    return motors.clamp_arm([0.0] * len(motors.arm_joints))


@dataclass(frozen=True)
class DryRun:
    """What a run would send, with what it needs to be read.

    Attributes:
        protocol: The protocol's name.
        rate_hz: Commands per second.
        duration_s: How long the plan lasts [s].
        has_arm: Whether the protocol carries arm targets (unnamed joints then hold 0 rad).
        frames: The handshake, every tick and the stop, in order.
    """

    protocol: str
    rate_hz: float
    duration_s: float
    has_arm: bool
    frames: tuple[PlannedFrame, ...]


MAX_FRAMES = 1_000_000
"""Most frames a dry run lists (14 hours at 20 Hz): each is held, then printed."""


def dry_run(plan: Plan, link: HostLink, motors: MotorMap, max_accel_rad_s2: float,
            rate_hz: float) -> DryRun:
    """The frames a run of ``plan`` at ``rate_hz`` would send.

    Raises:
        BadOption: The plan has more than :data:`MAX_FRAMES` frames.
    """
    ticks = plan.duration_s * rate_hz
    if ticks > MAX_FRAMES:
        raise BadOption("--dry-run", f"the plan lasts {plan.duration_s:g} s, {ticks:.3g} frames "
                        f"at {rate_hz:g} Hz, over the {MAX_FRAMES} a dry run lists; shorten "
                        "its durations")
    frames = tuple(planned_frames(plan, link, motors, max_accel_rad_s2, rate_hz))
    return DryRun(link.name, rate_hz, plan.duration_s, link.has_arm, frames)


def _frame(t_s: float, data: bytes, link: HostLink) -> PlannedFrame:
    return PlannedFrame(round(t_s, 6), data.hex(" "), link.describe(data))
