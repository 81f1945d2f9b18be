"""Which protocol, port, baud rate and command rate a run uses, checked before the port opens.

The port and baud rate default to the robot description's ``<ros2_control><hardware>``
parameters. The command rate must fit the link: a UART carries ``baud / 10`` bytes a second
each way (8N1), and the busier direction decides.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.drive.emulator.wire import BITS_PER_BYTE
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.arduino import ArduinoConfig, ArduinoLink
from servicebot_cli.drive.protocols.binary import BinaryLink
from servicebot_cli.drive.request import BadOption
from servicebot_cli.drive.session.commander import HostLink

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

MIN_RATE_HZ = 4.0  # at least two commands per 500 ms watchdog period
COMFORT = 0.8  # above this share of the link, warn: no room left for retries and noise


def serial_defaults(robot: RobotDescription) -> tuple[str | None, int | None]:
    """``port`` and ``baud_rate`` of the description's ros2_control hardware, if it names them.

    Raises:
        DescriptionError: A baud_rate that is not a whole number.
    """
    for block in robot.ros2_control:
        port, baud = block.hardware_param("port"), block.hardware_param("baud_rate")
        if port or baud:
            try:
                return port, int(baud) if baud else None
            except ValueError:
                raise DescriptionError(
                    f"{robot.display}: <param name=\"baud_rate\">{baud}</param> is not a whole "
                    "number; fix the URDF or give --baud"
                ) from None
    return None, None


ARDUINO_INT_MAX = 32_767
"""An AVR's int: the largest speed ROSArduinoBridge's ``m`` carries [ticks per PID frame]."""


def make_link(protocol: str, motors: MotorMap, arduino: ArduinoConfig | None) -> HostLink:
    """The host-side adapter for ``protocol`` (``servicebot`` or ``arduino``).

    Raises:
        DescriptionError: A robot the binary protocol cannot carry.
        ValueError: ``arduino`` without its configuration (a bug in the caller).
    """
    if protocol == "arduino":
        if arduino is None:
            raise ValueError("the arduino protocol needs an ArduinoConfig")
        top = arduino.max_ticks(motors.max_wheel_rad_s)
        if top > ARDUINO_INT_MAX:
            raise BadOption("--ticks-per-rev",
                f"{arduino.ticks_per_rev:g} at --pid-rate "
                f"{arduino.pid_rate_hz:g} makes the wheels' top speed {top} ticks a PID frame: "
                f"ROSArduinoBridge reads 'm' with atoi into an int, at most {ARDUINO_INT_MAX} "
                "on an Uno or Mega, and a larger number wraps to another speed; check "
                "--ticks-per-rev (ticks per wheel revolution, after the gearbox)")
        return ArduinoLink(motors, arduino)
    return BinaryLink(motors)


def link_capacity_hz(link: HostLink, baud: int) -> float:
    """Most commands per second the link carries: the busier direction decides [Hz].

    A UART is full duplex: commands and replies each have ``baud / 10`` bytes a second.
    """
    return baud / BITS_PER_BYTE / max(link.command_bytes, link.reply_bytes)


def port_and_baud(robot: RobotDescription, port: str | None, baud: int | None, *,
                  need_port: bool) -> tuple[str, int]:
    """The port and baud rate to use: the options', else the description's.

    Raises:
        BadOption: No port (when ``need_port``) or no baud rate anywhere.
    """
    default_port, default_baud = serial_defaults(robot)
    port = port or default_port
    baud = baud or default_baud
    if port is None and need_port:
        raise BadOption("--port", f"{robot.display} names no serial port in "
                        "<ros2_control><hardware>; give --port (`servicebot emulate` makes a "
                        "test port)")
    if baud is None:
        raise BadOption("--baud", f"{robot.display} names no baud_rate in "
                        "<ros2_control><hardware>; give --baud")
    return port or "(none)", baud


def check_rate(rate_hz: float, link: HostLink, baud: int, link_timeout_s: float | None,
               warn: Callable[[str], None]) -> None:
    """Refuse a command rate the link cannot carry or the watchdog would starve at.

    Args:
        rate_hz: Commands per second.
        link: The protocol adapter (its frame sizes).
        baud: The baud rate.
        link_timeout_s: The lost-link timeout, or None for a dry run [s].
        warn: Told when the rate leaves little room on the link.

    Raises:
        BadOption: Too fast for the link, too slow for the watchdog, or a link timeout
            shorter than two command periods.
    """
    capacity = link_capacity_hz(link, baud)
    frame = max(link.command_bytes, link.reply_bytes)
    if capacity < MIN_RATE_HZ:  # no rate both fits the link and feeds the watchdog
        raise BadOption("--baud", f"{baud} baud carries {capacity:.1f} commands a second "
                        f"({frame}-byte frames), fewer than the {MIN_RATE_HZ:g} Hz that keep "
                        "the firmware's watchdog fed; give the firmware's faster baud rate")
    if rate_hz > capacity:
        needs = rate_hz * frame
        shown = f"{needs:.0f}" if needs < 1e12 else f"{needs:.3g}"  # not 300 digits of 1e300
        raise BadOption("--rate", f"{rate_hz:g} Hz needs {shown} bytes/s one way "
                        f"({frame}-byte frames) but {baud} baud carries {baud / 10:.0f}; at "
                        f"most {capacity:.1f} Hz")
    if rate_hz < MIN_RATE_HZ:
        raise BadOption("--rate", f"{rate_hz:g} Hz is too slow to keep the firmware's watchdog "
                        f"fed; give at least {MIN_RATE_HZ:g} Hz")
    if rate_hz > COMFORT * capacity:
        warn(f"warning: {rate_hz:g} Hz uses {rate_hz / capacity:.0%} of the {baud}-baud link; "
             f"below {COMFORT * capacity:.0f} Hz leaves room for retries")
    if link_timeout_s is not None and link_timeout_s < 2.0 / rate_hz:
        raise BadOption("--link-timeout-s", f"{link_timeout_s:g} s is shorter than two command "
                        f"periods at {rate_hz:g} Hz")
