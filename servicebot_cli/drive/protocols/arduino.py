"""Host side of the ROSArduinoBridge text protocol (``--protocol arduino``).

ROSArduinoBridge (the hbrobotics/ros_arduino_bridge firmware and its many forks) reads
single-letter commands with space-separated integer arguments, each ended by CR, and
answers each with one line ended by CR LF. This module speaks:

    b        ->  " <baud>"          the handshake: the firmware answers with its baud rate
    m L R    ->  "OK"               target speeds of the left and right motors, in encoder
                                    ticks per PID interval (the firmware's PID_RATE, 30 Hz)
    e        ->  "<left> <right>"   encoder counts [ticks]

One tick of the command stream is ``m L R`` then ``e``. The firmware runs its PID every
``PID_INTERVAL = 1000 / PID_RATE`` milliseconds in integer arithmetic (33 ms for 30 Hz), so a
wheel speed maps to ``ticks = speed_rad_s / (2 pi) * ticks_per_rev * interval_s``, rounded
toward zero so the wheel never turns faster than asked, and never beyond the URDF's limit.
The protocol has two motors and no arm: the left wheels share the left motor, the right
wheels the right one.

Without a checksum, a reply may be garbled: see :mod:`.arduino_replies` for how lines are
read and matched. Encoder counts that jump further than the wheels can turn at their limit
are rejected, and a stop is confirmed only by counts that stop changing.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.arduino_replies import (
    Line,
    LineSplitter,
    ReplyMatcher,
    classify,
)
from servicebot_cli.drive.protocols.events import Ack, Event, Hello, Reading, Refused

TWO_PI = 2.0 * math.pi
GET_BAUDRATE = b"b\r"
READ_ENCODERS = b"e\r"
AUTO_STOP_NOTE = ("ROSArduinoBridge's auto-stop stops the motors AUTO_STOP_INTERVAL after the "
                  "last m command (2000 ms in the stock firmware)")
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

    @property
    def pid_interval_s(self) -> float:
        """The firmware's real PID interval: ``1000 / PID_RATE`` whole milliseconds [s]."""
        return max(1, math.floor(1000.0 / self.pid_rate_hz)) / 1000.0

    @property
    def ticks_per_rad(self) -> float:
        """Encoder ticks per radian of the wheel."""
        return self.ticks_per_rev / TWO_PI

    def ticks_per_frame(self, speed_rad_s: float) -> float:
        """Ticks per PID interval for a wheel speed [rad/s] (not rounded)."""
        return speed_rad_s * self.ticks_per_rad * self.pid_interval_s

    def speed_rad_s(self, ticks_per_frame: float) -> float:
        """Wheel speed [rad/s] for a number of ticks per PID interval."""
        return ticks_per_frame / self.pid_interval_s / self.ticks_per_rad

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


def side_speeds(speeds_rad_s: Sequence[float], motors: MotorMap) -> tuple[float, float]:
    """Forward-positive left and right motor speeds from wheel joint velocities [rad/s]."""
    sides: dict[str, list[float]] = {"left": [], "right": []}
    for v, side, sign in zip(speeds_rad_s, motors.wheel_sides, motors.wheel_axis_signs,
                             strict=True):
        sides[side].append(sign * v)
    return (sum(sides["left"]) / len(sides["left"]), sum(sides["right"]) / len(sides["right"]))




REBUILD = ("the firmware on {where} answers 'Invalid Command' to m and e: it was built without "
           "its base controller; rebuild ROSArduinoBridge with USE_BASE defined and the motor "
           "driver and encoder of your board selected (or use --protocol servicebot firmware)")
JUMP_MARGIN = 1.5  # a PID overshoots its target a little; a garbled digit does not stay small
JUMP_SLACK_S = 0.1  # replies arrive in bursts: the host's clock sees them closer than they were
STILL_WINDOW_S = 0.15  # counts unchanged this long after a stop: the wheels have stopped
STILL_TICKS = 1  # a stopped wheel may rock on an encoder edge
_REBASE_AFTER = 3  # consecutive rejected but mutually consistent readings: a new baseline


class ArduinoLink:
    """The ROSArduinoBridge protocol for one robot's two motor sides.

    Attributes:
        jumps: Encoder readings rejected because they moved faster than the wheels can.
        refused: ``Invalid Command`` replies.
    """

    name = "arduino"
    has_arm = False
    reply_bytes = _OK_BYTES + _ENCODER_REPLY_BYTES
    stop_timeout_s = 2.0
    stop_resend_s = 0.05

    def __init__(self, motors: MotorMap, config: ArduinoConfig) -> None:
        self.motors = motors
        self.config = config
        self.count_rad = TWO_PI / config.ticks_per_rev
        self._limit = config.max_ticks(motors.max_wheel_rad_s)
        self.command_bytes = len(motor_speeds_command(-self._limit, -self._limit)) + len(
            READ_ENCODERS)
        self._token = 0
        self._lines = LineSplitter()
        self._matcher = ReplyMatcher()
        self._greeted = False
        self._last: tuple[float, int, int] | None = None  # time, left, right [ticks]
        self._offset = (0, 0)
        self._rejected: list[tuple[float, int, int]] = []
        self._counts: deque[tuple[int, float, int, int]] = deque(maxlen=64)
        self.refused = self.garbled = self.jumps = 0

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
        self._matcher.expect(self._token, "ok", "counts")
        return motor_speeds_command(*self.side_ticks(speeds_rad_s)) + READ_ENCODERS, self._token

    def quantised(self, speeds_rad_s: Sequence[float]) -> tuple[float, ...]:
        """The wheel joint speeds ``m L R`` really asks for [rad/s] (whole ticks)."""
        left, right = (self.config.speed_rad_s(t) for t in self.side_ticks(speeds_rad_s))
        return self.motors.side_speeds(left, right)

    def arm(self, targets_rad: Sequence[float]) -> tuple[bytes, int]:
        """Never possible: ROSArduinoBridge has no arm."""
        raise ValueError("the ROSArduinoBridge protocol has no arm joints")

    def stop(self) -> tuple[bytes, int]:
        """``m 0 0`` then ``e`` (whose counts show whether the wheels stopped)."""
        return self.wheels([0.0] * len(self.motors.wheel_joints))

    def reset(self) -> None:
        """Forget the stream state after the port was reopened (the board may have reset)."""
        self._lines = LineSplitter()
        self._matcher.clear()
        self._greeted = False
        self._last = None
        self._rejected.clear()
        self._counts.clear()

    def feed(self, data: bytes, now_s: float) -> list[Event]:
        """Events for the lines completed by ``data``, received at ``now_s``; never raises."""
        events: list[Event] = []
        for raw in self._lines.feed(data):
            event = self._event(classify(raw), now_s)
            if event is not None:
                events.append(event)
        return events

    def _event(self, line: Line, now_s: float) -> Event | None:
        if line.kind == "ok":
            token = self._matcher.match("ok")
            return Ack(token) if token is not None else None
        if line.kind == "counts":
            token = self._matcher.match("counts")
            return None if token is None else self._reading(
                token, line.values[0], line.values[1], now_s)
        if line.kind == "refused":
            self.refused += 1
            refused = self._matcher.refuse()
            what = {"ok": "m", "counts": "e"}[refused[1]] if refused else "a command"
            return Refused(f"firmware answered 'Invalid Command' to {what}")
        if line.kind == "baud" and not self._greeted:
            self._greeted = True
            return Hello(f"ROSArduinoBridge, firmware at {line.values[0]} baud",
                         baud=line.values[0])
        self.garbled += 1
        return None

    def _reading(self, token: int, left: int, right: int, now_s: float) -> Reading | None:
        if not self._plausible(left, right, now_s):
            return None
        self._counts.append((token, now_s, left - self._offset[0], right - self._offset[1]))
        to_rad = 1.0 / self.config.ticks_per_rad
        speeds = (0.0, 0.0)
        if self._last is not None and now_s > self._last[0]:
            dt = now_s - self._last[0]
            speeds = ((left - self._last[1]) * to_rad / dt, (right - self._last[2]) * to_rad / dt)
        self._last = (now_s, left, right)
        sides = {"left": ((left - self._offset[0]) * to_rad, speeds[0]),
                 "right": ((right - self._offset[1]) * to_rad, speeds[1])}
        return Reading(token, self._per_wheel(sides, 0), self._per_wheel(sides, 1), None)

    def _per_wheel(self, sides: dict[str, tuple[float, float]], i: int) -> tuple[float, ...]:
        return tuple(sign * sides[side][i] for side, sign in
                     zip(self.motors.wheel_sides, self.motors.wheel_axis_signs, strict=True))

    def _plausible(self, left: int, right: int, now_s: float) -> bool:
        """Whether counts moved no further than the wheels can; rebase after a real jump."""
        if self._last is None or _within(self._last, (now_s, left, right), self._max_rate()):
            self._rejected.clear()
            return True
        self.jumps += 1
        self._rejected.append((now_s, left, right))
        run = self._rejected[-_REBASE_AFTER:]
        if len(run) == _REBASE_AFTER and all(
                _within(a, b, self._max_rate()) for a, b in zip(run, run[1:], strict=False)):
            # the firmware restarted its counts (a reset): go on from here, without a jump
            _, last_left, last_right = self._last
            self._offset = (self._offset[0] + left - last_left,
                            self._offset[1] + right - last_right)
            self._last = (now_s, left, right)
            self._rejected.clear()
        return False

    def _max_rate(self) -> float:
        return self.motors.max_wheel_rad_s * self.config.ticks_per_rad * JUMP_MARGIN

    def still(self, stop_tokens: set[int], now_s: float) -> bool:
        """Whether counts read after a stop stayed put for :data:`STILL_WINDOW_S`."""
        after = [c for c in self._counts if c[0] in stop_tokens]
        if not after:
            return False
        _, newest_s, left, right = after[-1]
        oldest_s = newest_s
        for _, t, lc, rc in reversed(after):
            if abs(lc - left) > STILL_TICKS or abs(rc - right) > STILL_TICKS:
                break
            oldest_s = t
        return newest_s - oldest_s >= STILL_WINDOW_S

    def refusal_advice(self, where: str) -> str:
        """What to rebuild when the firmware refuses every command."""
        return REBUILD.format(where=where)

    def auto_stop_note(self, hello: Hello | None) -> str:
        """Who stops the motors when drive could not."""
        return AUTO_STOP_NOTE

    @property
    def errors(self) -> int:
        """Garbled and lost lines, rejected counts and refusals so far."""
        return (self._lines.garbage + self.garbled + self._matcher.lost
                + self._matcher.unmatched + self.jumps + self.refused)

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


def _within(a: tuple[float, int, int], b: tuple[float, int, int], rate_ticks_s: float) -> bool:
    """Whether counts ``b`` are reachable from ``a`` at ``rate_ticks_s`` (with slack)."""
    allowed = rate_ticks_s * (abs(b[0] - a[0]) + JUMP_SLACK_S) + 2
    return abs(b[1] - a[1]) <= allowed and abs(b[2] - a[2]) <= allowed
