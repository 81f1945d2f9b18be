"""One drive run on a port: open it, stream, always stop, and say how it went.

This is where the pieces meet: the port is opened here (the only place), handed to the
loop, and whatever ends the run (the end of the plan, quit, Ctrl-C, SIGTERM, SIGHUP,
SIGQUIT, a lost link, a bug) the stop is sent before the run is reported.
"""

from __future__ import annotations

import contextlib
import statistics
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import LinkError, LinkLost, ServicebotError
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.session.commander import Commander, HostLink
from servicebot_cli.drive.session.contracts import LinkStatus, Source, Suspender
from servicebot_cli.drive.session.loop import DriveLoop
from servicebot_cli.drive.session.reconnect import DEFAULT_ATTEMPTS, ReconnectPolicy
from servicebot_cli.drive.session.signals import OUTCOMES, StopSignals
from servicebot_cli.drive.session.stall import WheelsStill
from servicebot_cli.drive.shaping import WheelShaper

if TYPE_CHECKING:
    from servicebot_cli.drive.session.telemetry_log import TelemetryCsv


@dataclass(frozen=True)
class StreamSettings:
    """How to stream to an open port.

    Attributes:
        port: Serial device path.
        baud: Baud rate.
        rate_hz: Commands per second.
        max_accel_rad_s2: Wheel acceleration limit [rad/s^2].
        link_timeout_s: No reply for this long ends the run with LinkLost [s].
        connect_timeout_s: How long the handshake may take [s].
        reconnect: Reopen the port after a lost link instead of giving up.
        log: CSV telemetry log, or None.
        boot_s: Time the board needs to boot after the port opens [s]; waited after every
            open, the first and each reconnect's.
        reconnect_attempts: Reconnect attempts before a lost link ends the run.
    """

    port: str
    baud: int
    rate_hz: float
    max_accel_rad_s2: float
    link_timeout_s: float
    connect_timeout_s: float
    reconnect: bool = False
    log: Path | None = None
    boot_s: float = 0.0
    reconnect_attempts: int = DEFAULT_ATTEMPTS


class StopUnconfirmed(LinkError):
    """The run ended, but the firmware never reported the wheels stopped (exit 4)."""


@dataclass(frozen=True)
class WheelTravel:
    """How far one wheel turned.

    Attributes:
        joint: The wheel joint.
        commanded_travel_rad: The commanded speeds integrated over the run [rad].
        measured_travel_rad: What its encoder reported, or None without telemetry [rad].
    """

    joint: str
    commanded_travel_rad: float
    measured_travel_rad: float | None


@dataclass(frozen=True)
class ArmJointEnd:
    """Where one arm joint was sent and where it was at the end.

    Attributes:
        joint: The arm joint.
        target_rad: The last target sent, or None when none was [rad].
        measured_position_rad: The last position reported, or None [rad].
    """

    joint: str
    target_rad: float | None
    measured_position_rad: float | None


@dataclass(frozen=True)
class Summary:
    """What a run did, for the last stderr line and ``--format json``.

    ``outcome`` is ``completed``, ``stop_unconfirmed``, ``interrupted``, ``terminated``,
    ``hung_up``, ``quit``, ``link_lost``, ``link_error`` or ``error``.
    """

    protocol: str
    port: str
    baud: int
    firmware: str
    outcome: str
    duration_s: float
    rate_hz: float
    commands: int
    replies: int
    median_rtt_s: float | None
    errors: int
    reconnects: int
    stop_confirmed: bool
    wheels: tuple[WheelTravel, ...]
    arm: tuple[ArmJointEnd, ...]


@dataclass(frozen=True)
class Driven:
    """How a run on a port ended.

    Attributes:
        summary: What it did; None when the firmware never answered.
        failure: What ended it early (its message says whether the stop was confirmed), or
            None when the source was done.
    """

    summary: Summary | None
    failure: ServicebotError | None


def run_drive(settings: StreamSettings, link: HostLink, motors: MotorMap,
              source: Source, *, log: Callable[[str], None],
              on_tick: Callable[[LinkStatus], None] | None = None,
              suspender: Suspender | None = None,
              arm_guard: Callable[[tuple[float, ...]], None] | None = None) -> Driven:
    """Drive until ``source`` is done; stop the motors on every way out.

    Whatever ends the run once the port is open (Ctrl-C, a signal, a lost link, the
    ``arm_guard`` refusing the arm's motion from where the firmware reports it) is in the
    result, after the stop was sent. Any other exception (a bug) propagates, after the stop.

    Raises:
        LinkError: The port cannot be opened (exit 4).
        OutputError: The ``--log`` file cannot be written.
    """
    from servicebot_cli.drive.transport import open_port

    commander = Commander(link, WheelShaper(motors, settings.max_accel_rad_s2), motors,
                          arm_guard)
    with StopSignals() as signals, _telemetry_log(settings.log, motors,
                                                  link.has_arm) as csv_log:
        port = open_port(settings.port, settings.baud)
        reopen = (lambda: open_port(settings.port, settings.baud)) if settings.reconnect \
            else None
        loop = DriveLoop(port, link, commander, rate_hz=settings.rate_hz,
                         where=f"{settings.port} at {settings.baud} baud",
                         link_timeout_s=settings.link_timeout_s, reopen=reopen,
                         policy=ReconnectPolicy(settings.reconnect_attempts), log=log,
                         on_tick=on_tick, on_reading=csv_log.row if csv_log else None,
                         boot_s=settings.boot_s, connect_timeout_s=settings.connect_timeout_s,
                         suspender=suspender)
        failure, confirmed = _drive_then_stop(loop, settings, source, signals, log)
    summary = _summary(loop, settings, link, motors, failure, confirmed)
    if failure is not None:
        failure = _with_stop_note(failure, loop, confirmed)
    return Driven(summary if loop.inbox.hello is not None else None, failure)


def _drive_then_stop(loop: DriveLoop, settings: StreamSettings, source: Source,
                     signals: StopSignals, log: Callable[[str], None]
                     ) -> tuple[ServicebotError | None, bool]:
    """Connect and stream; whatever happens, stop. ``(what ended the run, stop confirmed)``."""
    failure: ServicebotError | None = None
    try:
        try:
            hello = loop.connect(settings.connect_timeout_s)
        except LinkLost as exc:  # a port that fails before any answer: no link was had
            raise LinkError(str(exc).replace("link lost: ", "no link: ", 1)) from None
        log(f"connected to {loop.where}: {hello.description}")
        if hello.baud is not None and hello.baud != settings.baud:
            log(f"warning: the firmware says it runs at {hello.baud} baud, the port at "
                f"{settings.baud}: a reply garbled on the way, or a board on native USB, where "
                "the baud rate means nothing; check the firmware's BAUDRATE and --baud")
        loop.run(source)
    except ServicebotError as exc:  # Ctrl-C, the signals and lost links arrive here too
        failure = exc
    finally:  # and any other exception (a bug) passes through here on its way out
        signals.stopping()
        confirmed = loop.stop_motors()
        if loop.port is not None:
            loop.port.close()
    travel_rad = max(map(abs, loop.commander.travel_rad), default=0.0)
    if isinstance(failure, WheelsStill):
        confirmed = False  # counts that froze with the wheels show nothing stopping
    elif confirmed and loop.stall.never_moved() and travel_rad >= loop.stall.least_travel_rad:
        confirmed = False  # counts that never changed show nothing stopping
        if failure is None:
            failure = StopUnconfirmed(
                f"stop not confirmed: no encoder on {loop.where} counted once while the wheels "
                f"were commanded to turn up to {travel_rad:.2g} rad, so nothing shows them "
                "stopped (an encoder cable pulled, or the motor power off?)")
    if failure is None and not confirmed and loop.inbox.hello is not None:
        failure = StopUnconfirmed(
            f"stop not confirmed: the firmware on {loop.where} did not report the wheels "
            f"stopped within {loop.link.stop_timeout_s:g} s of the first of "
            f"{loop.stops_sent} stops ({_stop_evidence(loop.link.name)})")
    return failure, confirmed


def _stop_evidence(protocol: str) -> str:
    if protocol == "arduino":
        return "ROSArduinoBridge: encoder counts that stop changing"
    return "TELEMETRY with every wheel at zero"


@contextlib.contextmanager
def _telemetry_log(path: Path | None, motors: MotorMap,
                   has_arm: bool) -> Iterator[TelemetryCsv | None]:
    if path is None:
        yield None
        return
    from servicebot_cli.drive.session.telemetry_log import telemetry_csv

    with telemetry_csv(path, motors, has_arm) as csv_log:
        yield csv_log


def _with_stop_note(failure: ServicebotError, loop: DriveLoop, confirmed: bool) -> ServicebotError:
    if loop.inbox.hello is None:
        return failure
    auto_stop = loop.link.auto_stop_note(loop.inbox.hello)
    note = ("motors stopped (the firmware confirmed)" if confirmed else
            f"stop sent but not confirmed; {auto_stop}")
    if isinstance(failure, StopUnconfirmed):
        note = auto_stop
    return type(failure)(f"{failure}; {note}")


def _outcome(failure: ServicebotError | None) -> str:
    if failure is None:
        return "completed"
    outcomes: tuple[tuple[type[ServicebotError], str], ...] = (
        *OUTCOMES, (LinkLost, "link_lost"), (StopUnconfirmed, "stop_unconfirmed"),
        (WheelsStill, "wheels_stalled"))
    for kind, name in outcomes:
        if isinstance(failure, kind):
            return name
    return "link_error" if isinstance(failure, LinkError) else "error"


def _summary(loop: DriveLoop, settings: StreamSettings, link: HostLink,
             motors: MotorMap, failure: ServicebotError | None, confirmed: bool) -> Summary:
    reading, rtts_s = loop.inbox.reading, loop.inbox.rtts_s
    wheels = tuple(
        WheelTravel(name, round(commanded, 4), round(measured, 4) if reading else None)
        for name, commanded, measured in zip(motors.wheel_joints, loop.commander.travel_rad,
                                             loop.inbox.measured_travel_rad, strict=True)
    )
    arm_sent = loop.commander.arm_sent
    measured_arm = reading.arm_position_rad if reading is not None else None
    arm = tuple(
        ArmJointEnd(name, arm_sent[i] if arm_sent else None,
                    measured_arm[i] if measured_arm else None)
        for i, name in enumerate(motors.arm_joints)
    ) if link.has_arm else ()
    return Summary(
        protocol=link.name, port=settings.port, baud=settings.baud,
        firmware=loop.inbox.hello.description if loop.inbox.hello else "",
        outcome=_outcome(failure),
        duration_s=round(max(0.0, loop.end_s - loop.t0_s), 3), rate_hz=settings.rate_hz,
        commands=loop.commands, replies=loop.inbox.replies,
        median_rtt_s=round(statistics.median(rtts_s), 4) if rtts_s else None,
        errors=link.errors, reconnects=loop.reconnects, stop_confirmed=confirmed,
        wheels=wheels, arm=arm,
    )
