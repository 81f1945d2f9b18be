"""One drive run from start to stop: choose the protocol, open the port, stream, always stop.

This is where the pieces meet: the port is opened here (the only place), handed to the
loop, and whatever ends the run (the end of the plan, quit, Ctrl-C, SIGTERM, a lost link,
a bug) the stop is sent before the run is reported.
"""

from __future__ import annotations

import contextlib
import statistics
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

from servicebot_cli.common.errors import DescriptionError, LinkError, LinkLost, ServicebotError
from servicebot_cli.drive.emulator.wire import BITS_PER_BYTE
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.arduino import ArduinoConfig, ArduinoLink
from servicebot_cli.drive.protocols.binary import BinaryLink
from servicebot_cli.drive.session.commander import Commander, HostLink
from servicebot_cli.drive.session.loop import DriveLoop, LinkStatus, Source
from servicebot_cli.drive.session.signals import Interrupted, StopSignals, Terminated
from servicebot_cli.drive.shaping import WheelShaper

MIN_RATE_HZ = 4.0  # at least two commands per 500 ms watchdog period
COMFORT = 0.8  # above this share of the link, warn: no room left for retries and noise


@dataclass(frozen=True)
class DriveRequest:
    """How to drive.

    Attributes:
        port: Serial device path.
        baud: Baud rate.
        rate_hz: Commands per second.
        max_accel_rad_s2: Wheel acceleration limit [rad/s^2].
        link_timeout_s: No reply for this long ends the run with LinkLost [s].
        connect_timeout_s: How long the handshake may take [s].
        reconnect: Reopen the port after a lost link instead of giving up.
        log: CSV telemetry log, or None.
    """

    port: str
    baud: int
    rate_hz: float
    max_accel_rad_s2: float
    link_timeout_s: float
    connect_timeout_s: float
    reconnect: bool = False
    log: Path | None = None


@dataclass(frozen=True)
class Summary:
    """What a run did, for the last stderr line and ``--format json``."""

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
    wheels: list[dict[str, object]]
    arm: list[dict[str, object]]


def serial_defaults(robot: object) -> tuple[str | None, int | None]:
    """``port`` and ``baud_rate`` of the description's ros2_control hardware, if it names them.

    Raises:
        DescriptionError: A baud_rate that is not a whole number.
    """
    for block in getattr(robot, "ros2_control", ()):
        port, baud = block.hardware_param("port"), block.hardware_param("baud_rate")
        if port or baud:
            try:
                return port, int(baud) if baud else None
            except ValueError:
                raise DescriptionError(
                    f"{robot.display}: <param name=\"baud_rate\">{baud}</param> is not a whole "  # type: ignore[attr-defined]
                    "number; fix the URDF or give --baud"
                ) from None
    return None, None


def make_link(protocol: str, motors: MotorMap, arduino: ArduinoConfig | None) -> HostLink:
    """The host-side adapter for ``protocol`` (``servicebot`` or ``arduino``)."""
    if protocol == "arduino":
        assert arduino is not None
        return ArduinoLink(motors, arduino)
    return BinaryLink(motors)


def link_capacity_hz(link: HostLink, baud: int) -> float:
    """Most commands per second the link carries: the busier direction decides [Hz].

    A UART is full duplex: commands and replies each have ``baud / 10`` bytes a second.
    """
    return baud / BITS_PER_BYTE / max(link.command_bytes, link.reply_bytes)


def run_drive(request: DriveRequest, link: HostLink, motors: MotorMap,
              source: Source, *, log: Callable[[str], None],
              on_tick: Callable[[LinkStatus], None] | None = None,
              on_summary: Callable[[Summary], None] | None = None) -> Summary:
    """Drive until ``source`` is done; stop the motors on every way out.

    Raises:
        LinkError: The port cannot be opened or the firmware does not answer (exit 4).
        LinkLost: The link went silent (exit 5), after the stop was sent.
        Interrupted: Ctrl-C (exit 130), after the stop. Terminated: SIGTERM (exit 143).
    """
    from servicebot_cli.drive.session.telemetry_log import telemetry_csv
    from servicebot_cli.drive.transport import open_port

    commander = Commander(link, WheelShaper(motors, request.max_accel_rad_s2), motors)
    with StopSignals() as signals, _csv(request.log, telemetry_csv, motors,
                                         link.has_arm) as csv_log:
        port = open_port(request.port, request.baud)
        reopen = (lambda: open_port(request.port, request.baud)) if request.reconnect else None
        loop = DriveLoop(port, link, commander, rate_hz=request.rate_hz,
                         where=f"{request.port} at {request.baud} baud",
                         link_timeout_s=request.link_timeout_s, reopen=reopen, log=log,
                         on_tick=on_tick, on_reading=csv_log.row if csv_log else None)
        failure, confirmed = _drive_then_stop(loop, request, source, signals, log)
    summary = _summary(loop, request, link, motors, failure, confirmed)
    if loop.hello is not None and on_summary is not None:
        on_summary(summary)
    if failure is not None:
        raise _with_stop_note(failure, loop, confirmed)
    return summary


def _drive_then_stop(loop: DriveLoop, request: DriveRequest, source: Source,
                     signals: StopSignals, log: Callable[[str], None]
                     ) -> tuple[ServicebotError | None, bool]:
    """Connect and stream; whatever happens, stop. ``(what ended the run, stop confirmed)``."""
    failure: ServicebotError | None = None
    try:
        hello = loop.connect(request.connect_timeout_s)
        log(f"connected to {loop.where}: {hello.description}")
        loop.run(source)
    except ServicebotError as exc:  # Ctrl-C, SIGTERM and lost links arrive here too
        failure = exc
    finally:  # and any other exception (a bug) passes through here on its way out
        signals.stopping()
        confirmed = loop.stop_motors()
        if loop.port is not None:
            loop.port.close()
    return failure, confirmed


@contextlib.contextmanager
def _csv(path: Path | None, opener: Callable[..., contextlib.AbstractContextManager[object]],
         motors: MotorMap, has_arm: bool) -> Iterator[object]:
    if path is None:
        yield None
    else:
        with opener(path, motors, has_arm) as log:
            yield log


def _with_stop_note(failure: ServicebotError, loop: DriveLoop, confirmed: bool) -> ServicebotError:
    if loop.hello is None:
        return failure
    watchdog = f"{loop.hello.watchdog_ms} ms" if loop.hello.watchdog_ms else "its timeout"
    note = ("motors stopped (the firmware confirmed)" if confirmed else
            f"stop sent but not confirmed; the firmware's watchdog stops the motors within "
            f"{watchdog}")
    return type(failure)(f"{failure}; {note}")


def _outcome(failure: ServicebotError | None) -> str:
    if failure is None:
        return "completed"
    for kind, name in ((Interrupted, "interrupted"), (Terminated, "terminated"),
                       (LinkLost, "link_lost")):
        if isinstance(failure, kind):
            return name
    return "link_error" if isinstance(failure, LinkError) else "error"


def _summary(loop: DriveLoop, request: DriveRequest, link: HostLink,
             motors: MotorMap, failure: ServicebotError | None, confirmed: bool) -> Summary:
    reading = loop.reading
    wheels = [
        {"joint": name, "commanded_travel_rad": round(commanded, 4),
         "measured_travel_rad": round(measured, 4) if reading else None}
        for name, commanded, measured in zip(motors.wheel_joints, loop.commander.travel_rad,
                                             loop.measured_travel_rad, strict=True)
    ]
    arm_sent = loop.commander.arm_sent
    measured = reading.arm_position_rad if reading is not None else None
    arm = [
        {"joint": name, "target_rad": arm_sent[i] if arm_sent else None,
         "measured_position_rad": measured[i] if measured else None}
        for i, name in enumerate(motors.arm_joints)
    ] if link.has_arm else []
    return Summary(
        protocol=link.name, port=request.port, baud=request.baud,
        firmware=loop.hello.description if loop.hello else "", outcome=_outcome(failure),
        duration_s=round(max(0.0, loop.end_s - loop.t0_s), 3), rate_hz=request.rate_hz,
        commands=loop.commands, replies=loop.replies,
        median_rtt_s=round(statistics.median(loop.rtts_s), 4) if loop.rtts_s else None,
        errors=link.errors, reconnects=loop.reconnects, stop_confirmed=confirmed,
        wheels=wheels, arm=arm,
    )
