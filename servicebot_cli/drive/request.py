"""What ``servicebot drive`` is asked to do, as plain values (no Click).

The command turns its options into a :class:`DriveRequest`; :func:`servicebot_cli.drive.run.
drive` does the rest. A value that only the robot description shows to be wrong (a rate the
link cannot carry, an arm joint it does not have) is a :class:`BadOption`, which names the
option so the command can report it as Click reports a bad value.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, TypeAlias

from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.drive.session.reconnect import DEFAULT_ATTEMPTS

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig


class BadOption(ServicebotError):
    """An option's value that the robot or the link rules out (exit 2).

    Attributes:
        option: The option as the user types it, e.g. ``--rate``.
    """

    exit_code = ExitCode.USAGE

    def __init__(self, option: str, message: str) -> None:
        super().__init__(message)
        self.option = option


@dataclass(frozen=True)
class OneShot:
    """``--linear/--angular/--duration-s/--arm``: one timed twist with arm targets.

    Attributes:
        linear_m_s: Forward speed [m/s].
        angular_rad_s: Yaw rate [rad/s].
        duration_s: How long [s].
        arm: Arm targets, ``(joint, rad)`` pairs.
    """

    linear_m_s: float
    angular_rad_s: float
    duration_s: float
    arm: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class ScriptFile:
    """``--script FILE``: timed steps from a file, or from stdin when ``path`` is ``-``."""

    path: str


@dataclass(frozen=True)
class Keyboard:
    """No mode option: teleop from the keyboard on stdin.

    Attributes:
        deadman_s: Stop the wheels when no key arrived for this long, or None [s].
    """

    deadman_s: float | None = None


Mode: TypeAlias = OneShot | ScriptFile | Keyboard


@dataclass(frozen=True)
class DriveRequest:
    """One ``drive`` invocation.

    Attributes:
        robot: The robot description to take kinematics and limits from.
        mode: What to drive.
        protocol: ``servicebot`` or ``arduino``.
        arduino: How the ROSArduinoBridge firmware counts (``arduino`` only).
        port: Serial device, or None for the description's.
        baud: Baud rate, or None for the description's.
        rate_hz: Commands per second.
        max_accel_rad_s2: Wheel acceleration limit [rad/s^2].
        link_timeout_s: No reply for this long is a lost link [s].
        connect_timeout_s: How long the firmware may take to answer at first [s].
        reconnect: Reopen the port after a lost link.
        log: CSV telemetry log, or None.
        dry_run: Plan the frames only; no port.
        boot_s: Time the board needs to boot after the port opens [s].
        max_wheel_rad_s: A wheel speed cap below the URDF's limit (``--max-speed``) [rad/s].
        reconnect_attempts: Reconnect attempts before a lost link ends the run.
        check_collisions: Refuse arm targets, and ways to them, that put links of the robot
            into each other or the floor (``ik``'s check); False: ``--allow-collisions``.
        srdf: An SRDF whose ``<disable_collisions>`` pairs are not checked, or None.
    """

    robot: RobotSource
    mode: Mode
    protocol: str
    arduino: ArduinoConfig | None
    port: str | None
    baud: int | None
    rate_hz: float
    max_accel_rad_s2: float
    link_timeout_s: float
    connect_timeout_s: float
    reconnect: bool = False
    log: Path | None = None
    dry_run: bool = False
    boot_s: float = 0.0
    max_wheel_rad_s: float | None = None
    reconnect_attempts: int = DEFAULT_ATTEMPTS
    check_collisions: bool = True
    srdf: str | None = None
