"""Host side of the ROSArduinoBridge text protocol (``--protocol arduino``).

ROSArduinoBridge (the hbrobotics/ros_arduino_bridge firmware and its many forks) reads
single-letter commands with space-separated integer arguments, each ended by CR, and
answers each with one line ended by CR LF. This module speaks:

    b        ->  " <baud>"          the handshake: the firmware answers with its baud rate
    m L R    ->  "OK"               target speeds of the left and right motors, in encoder
                                    ticks per PID interval (the firmware's PID_RATE, 30 Hz)
    e        ->  "<left> <right>"   encoder counts [ticks]

One tick of the command stream is ``m L R`` then ``e``. A wheel speed maps to
``ticks = speed_rad_s / (2 pi) * ticks_per_rev / pid_rate_hz``, rounded toward zero so the
wheel never turns faster than asked, and never beyond the URDF's limit. The protocol has two
motors and no arm: the left wheels share the left motor, the right wheels the right one.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.events import Ack, Event, Hello, Reading, Refused

TWO_PI = 2.0 * math.pi
GET_BAUDRATE = b"b\r"
READ_ENCODERS = b"e\r"
MAX_LINE = 64  # longer lines are garbage: no reply of the protocol is that long
_ENCODER_REPLY_BYTES = len("-2147483648 -2147483648\r\n")
_OK_BYTES = len("OK\r\n")


@dataclass(frozen=True)
class ArduinoConfig:
    """How the firmware counts.

    Attributes:
        ticks_per_rev: Encoder ticks per wheel revolution (after any gearbox).
        pid_rate_hz: The firmware's PID loop rate (``PID_RATE``; 30 in the stock firmware).
    """

    ticks_per_rev: float
    pid_rate_hz: float = 30.0

    def ticks_per_frame(self, speed_rad_s: float) -> float:
        """Ticks per PID interval for a wheel speed [rad/s] (not rounded)."""
        return speed_rad_s / TWO_PI * self.ticks_per_rev / self.pid_rate_hz

    def speed_rad_s(self, ticks_per_frame: float) -> float:
        """Wheel speed [rad/s] for a number of ticks per PID interval."""
        return ticks_per_frame * self.pid_rate_hz / self.ticks_per_rev * TWO_PI

    def max_ticks(self, max_rad_s: float) -> int:
        """The largest ticks per interval whose speed is within ``max_rad_s``."""
        ticks = math.floor(self.ticks_per_frame(max_rad_s))
        while ticks > 0 and self.speed_rad_s(ticks) > max_rad_s:
            ticks -= 1
        return ticks

    def ticks(self, speed_rad_s: float, max_rad_s: float) -> int:
        """Ticks per interval for ``speed_rad_s``: toward zero, within ``max_rad_s``; NaN is 0."""
        if math.isnan(speed_rad_s):
            return 0
        limit = self.max_ticks(max_rad_s)
        wanted = self.ticks_per_frame(max(-max_rad_s, min(max_rad_s, speed_rad_s)))
        return max(-limit, min(limit, math.trunc(wanted)))


def motor_speeds_command(left_ticks: int, right_ticks: int) -> bytes:
    """``m LEFT RIGHT`` with its CR."""
    return f"m {left_ticks} {right_ticks}\r".encode("ascii")


class LineSplitter:
    """Splits received bytes into lines; drops overlong lines (garbage) and counts them."""

    def __init__(self) -> None:
        self._buffer = bytearray()
        self.garbage = 0

    def feed(self, data: bytes) -> list[str]:
        """Complete lines in ``data``, without their CR LF."""
        self._buffer += data
        lines = []
        while (end := self._buffer.find(b"\n")) >= 0:
            raw = bytes(self._buffer[:end]).strip(b"\r")
            del self._buffer[:end + 1]
            if len(raw) > MAX_LINE:
                self.garbage += 1
            else:
                lines.append(raw.decode("ascii", errors="replace"))
        if len(self._buffer) > MAX_LINE:
            self.garbage += 1
            self._buffer.clear()
        return lines


def side_speeds(speeds_rad_s: Sequence[float], motors: MotorMap) -> tuple[float, float]:
    """Forward-positive left and right motor speeds from wheel joint velocities [rad/s]."""
    sides: dict[str, list[float]] = {"left": [], "right": []}
    for v, side, sign in zip(speeds_rad_s, motors.wheel_sides, motors.wheel_axis_signs,
                             strict=True):
        sides[side].append(sign * v)
    return (sum(sides["left"]) / len(sides["left"]), sum(sides["right"]) / len(sides["right"]))


class ArduinoLink:
    """The ROSArduinoBridge protocol for one robot's two motor sides."""

    name = "arduino"
    has_arm = False
    reply_bytes = _OK_BYTES + _ENCODER_REPLY_BYTES

    def __init__(self, motors: MotorMap, config: ArduinoConfig) -> None:
        self.motors = motors
        self.config = config
        self._limit = config.max_ticks(motors.max_wheel_rad_s)
        self.command_bytes = len(motor_speeds_command(-self._limit, -self._limit)) + len(
            READ_ENCODERS)
        self._token = 0
        self._pending: deque[int] = deque(maxlen=64)
        self._lines = LineSplitter()
        self._last: tuple[float, int, int] | None = None
        self.refused = 0
        self.unexpected = 0

    def hello(self) -> bytes:
        """Ask for the baud rate."""
        return GET_BAUDRATE

    def side_ticks(self, speeds_rad_s: Sequence[float]) -> tuple[int, int]:
        """Left and right ticks per interval for wheel joint velocities [rad/s]."""
        left, right = side_speeds(speeds_rad_s, self.motors)
        limit = self.motors.max_wheel_rad_s
        return self.config.ticks(left, limit), self.config.ticks(right, limit)

    def wheels(self, speeds_rad_s: Sequence[float]) -> tuple[bytes, int]:
        """``m L R`` then ``e``; ``(bytes, token)``."""
        self._token += 1
        self._pending.append(self._token)
        return motor_speeds_command(*self.side_ticks(speeds_rad_s)) + READ_ENCODERS, self._token

    def quantised(self, speeds_rad_s: Sequence[float]) -> tuple[float, ...]:
        """The wheel joint speeds ``m L R`` really asks for [rad/s] (whole ticks)."""
        left, right = (self.config.speed_rad_s(t) for t in self.side_ticks(speeds_rad_s))
        return self.motors.side_speeds(left, right)

    def arm(self, targets_rad: Sequence[float]) -> tuple[bytes, int]:
        """Never possible: ROSArduinoBridge has no arm."""
        raise ValueError("the ROSArduinoBridge protocol has no arm joints")

    def stop(self) -> tuple[bytes, int]:
        """``m 0 0`` then ``e``."""
        return self.wheels([0.0] * len(self.motors.wheel_joints))

    def reset(self) -> None:
        """Forget the stream state after the port was reopened."""
        self._pending.clear()
        self._lines = LineSplitter()
        self._last = None

    def feed(self, data: bytes, now_s: float) -> list[Event]:
        """Events for the lines completed by ``data``, received at ``now_s`` [s]."""
        events: list[Event] = []
        for line in self._lines.feed(data):
            event = self._event(line.strip(), now_s)
            if event is not None:
                events.append(event)
        return events

    def _event(self, line: str, now_s: float) -> Event | None:
        if line == "OK":
            return Ack(self._pending.popleft()) if self._pending else None
        if line == "Invalid Command":
            self.refused += 1
            return Refused("firmware answered 'Invalid Command'")
        fields = line.split()
        if not fields or not all(_is_int(f) for f in fields) or len(fields) > 2:
            self.unexpected += 1
            return None
        if len(fields) == 1:
            return Hello(f"ROSArduinoBridge, firmware at {int(fields[0])} baud")
        return self._reading(int(fields[0]), int(fields[1]), now_s)

    def _reading(self, left: int, right: int, now_s: float) -> Reading:
        to_rad = TWO_PI / self.config.ticks_per_rev
        speeds = (0.0, 0.0)
        if self._last is not None and now_s > self._last[0]:
            dt = now_s - self._last[0]
            speeds = ((left - self._last[1]) * to_rad / dt, (right - self._last[2]) * to_rad / dt)
        self._last = (now_s, left, right)
        sides = {"left": (left * to_rad, speeds[0]), "right": (right * to_rad, speeds[1])}
        positions = tuple(sign * sides[side][0] for side, sign in
                          zip(self.motors.wheel_sides, self.motors.wheel_axis_signs, strict=True))
        velocities = tuple(sign * sides[side][1] for side, sign in
                           zip(self.motors.wheel_sides, self.motors.wheel_axis_signs, strict=True))
        return Reading(None, positions, velocities, None)

    @property
    def errors(self) -> int:
        """Garbage lines, unexpected replies and refusals so far."""
        return self._lines.garbage + self.unexpected + self.refused

    def describe(self, data: bytes) -> str:
        """The commands in ``data`` with the speeds they mean, for ``--dry-run``."""
        parts = []
        for command in data.decode("ascii").split("\r"):
            fields = command.split()
            if fields[:1] == ["m"] and len(fields) == 3:
                left, right = (self.config.speed_rad_s(int(f)) for f in fields[1:])
                parts.append(f"{command!r}: left {left:+.3f} rad/s, right {right:+.3f} rad/s")
            elif fields:
                parts.append(repr(command))
        return "; ".join(parts)


def _is_int(text: str) -> bool:
    return text.lstrip("+-").isdigit()
