"""A motor controller as a pure state machine: bytes and times in, reply bytes out.

:class:`MotorModel` is the hardware: wheels turn at the commanded speed (clamped to the
URDF limits), encoders integrate exactly what the wheels did, the arm moves toward its
targets at its velocity limit, and a watchdog stops everything when no motion command came
for the timeout. :class:`BinaryFirmware` speaks the servicebot protocol in front of it.
Time is passed in, so tests step it and the pty server uses the real clock.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TypeAlias

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.framing import Decoder, Frame, encode_frame

FIRMWARE_VERSION = (1, 0)
_DISTINCT_COMMANDS_KEPT = 32
_STOPS_KEPT = 16

JsonValue: TypeAlias = "str | int | float | bool | None | list[JsonValue] | dict[str, JsonValue]"
State: TypeAlias = dict[str, JsonValue]  # state for the emulator's state file, JSON-ready


@dataclass
class Counters:
    """What the controller has seen; reported in the emulator's state."""

    frames: int = 0
    commands: int = 0
    stops: int = 0
    nacks: int = 0
    limited: int = 0
    watchdog_trips: int = 0
    first_command: str | None = None
    last_stop_s: float | None = None
    recent_stops_s: list[float] = field(default_factory=list)  # the last 16, oldest first
    max_abs_wheel_command_rad_s: float = 0.0
    wheel_commands: list[list[float]] = field(default_factory=list)  # distinct, first 32


@dataclass
class MotorModel:
    """Wheels, encoders, arm and watchdog of one robot.

    Attributes:
        motors: The robot's motors and limits.
        watchdog_s: Stop when no motion command came for this long [s].
        now_s: The time the state is at [s].
        stall_at_s: From this time on the wheels do not turn, whatever is commanded (the
            emulator's ``--stall-after-s``); None: never [s].
    """

    motors: MotorMap
    watchdog_s: float
    now_s: float = 0.0
    wheel_position_rad: list[float] = field(default_factory=list)
    wheel_velocity_rad_s: list[float] = field(default_factory=list)
    arm_position_rad: list[float] = field(default_factory=list)
    arm_target_rad: list[float] = field(default_factory=list)
    last_motion_command_s: float = 0.0
    watchdog_fired: bool = False
    counters: Counters = field(default_factory=Counters)
    stall_at_s: float | None = None

    def __post_init__(self) -> None:
        n_wheels, n_arm = len(self.motors.wheel_joints), len(self.motors.arm_joints)
        self.wheel_position_rad = self.wheel_position_rad or [0.0] * n_wheels
        self.wheel_velocity_rad_s = self.wheel_velocity_rad_s or [0.0] * n_wheels
        self.arm_position_rad = self.arm_position_rad or list(self.motors.clamp_arm([0.0] * n_arm))
        self.arm_target_rad = self.arm_target_rad or list(self.arm_position_rad)
        self.last_motion_command_s = self.now_s

    @property
    def moving(self) -> bool:
        """True while a wheel turns or the arm is short of its targets."""
        return any(self.wheel_velocity_rad_s) or self.arm_target_rad != self.arm_position_rad

    def advance(self, now_s: float) -> None:
        """Move the state to ``now_s``; the watchdog stops the motors at its exact deadline."""
        deadline = self.last_motion_command_s + self.watchdog_s
        if self.moving and now_s > deadline:
            self._integrate(max(deadline, self.now_s))
            self._halt()
            self.watchdog_fired = True
            self.counters.watchdog_trips += 1
        self._integrate(now_s)

    @property
    def stalled(self) -> bool:
        """Whether the wheels no longer turn (``stall_at_s`` has passed)."""
        return self.stall_at_s is not None and self.now_s >= self.stall_at_s

    @property
    def measured_wheel_velocity_rad_s(self) -> list[float]:
        """What the encoders measure: the commanded speeds, or zeros once stalled."""
        return [0.0] * len(self.wheel_velocity_rad_s) if self.stalled \
            else list(self.wheel_velocity_rad_s)

    def _integrate(self, now_s: float) -> None:
        dt = now_s - self.now_s
        if dt <= 0.0:
            return
        turning_s = dt if self.stall_at_s is None else \
            max(0.0, min(now_s, self.stall_at_s) - self.now_s)
        for i, v in enumerate(self.wheel_velocity_rad_s):
            self.wheel_position_rad[i] += v * turning_s
        for i, (p, target) in enumerate(zip(self.arm_position_rad, self.arm_target_rad,
                                            strict=True)):
            step = self.motors.arm_max_rad_s[i] * dt
            self.arm_position_rad[i] = target if abs(target - p) <= step else (
                p + math.copysign(step, target - p))
        self.now_s = now_s

    def _halt(self) -> None:
        self.wheel_velocity_rad_s = [0.0] * len(self.wheel_velocity_rad_s)
        self.arm_target_rad = list(self.arm_position_rad)  # the arm holds where it is

    def command_wheels(self, speeds_rad_s: Sequence[float], now_s: float) -> bool:
        """Set wheel joint velocities [rad/s]; True when a value had to be clamped."""
        self.advance(now_s)
        clamped = self.motors.clamp_wheels(speeds_rad_s)
        self.wheel_velocity_rad_s = list(clamped)
        self._motion_command("SET_WHEELS", now_s)
        if list(clamped) not in self.counters.wheel_commands and len(
                self.counters.wheel_commands) < _DISTINCT_COMMANDS_KEPT:
            self.counters.wheel_commands.append(list(clamped))
        peak = max((abs(v) for v in clamped), default=0.0)
        self.counters.max_abs_wheel_command_rad_s = max(
            self.counters.max_abs_wheel_command_rad_s, peak)
        return tuple(speeds_rad_s) != clamped

    def command_arm(self, targets_rad: Sequence[float], now_s: float) -> bool:
        """Set arm targets [rad]; True when one was clamped. Not a motion command: no watchdog."""
        self.advance(now_s)
        clamped = self.motors.clamp_arm(targets_rad)
        self.arm_target_rad = list(clamped)
        self.counters.commands += 1
        self.counters.first_command = self.counters.first_command or "SET_ARM"
        return tuple(targets_rad) != clamped

    def stop(self, now_s: float) -> None:
        """Stop the wheels and hold the arm where it is."""
        self.advance(now_s)
        self._halt()
        self._motion_command("STOP", now_s)
        self.counters.stops += 1
        self.counters.last_stop_s = now_s
        self.counters.recent_stops_s = [*self.counters.recent_stops_s[-(_STOPS_KEPT - 1):], now_s]

    def _motion_command(self, name: str, now_s: float) -> None:
        self.last_motion_command_s = now_s
        self.watchdog_fired = False
        self.counters.commands += 1
        self.counters.first_command = self.counters.first_command or name


class BinaryFirmware:
    """The servicebot protocol in front of a :class:`MotorModel`.

    Every valid frame gets exactly one reply with the same SEQ: VERSION for PING, TELEMETRY
    for SET_WHEELS, SET_ARM and STOP, NACK for anything else. A frame with a bad CRC gets no
    reply and changes nothing; the next TELEMETRY reports it with the CRC fault flag.
    """

    protocol = "servicebot"

    def __init__(self, model: MotorModel) -> None:
        self.model = model
        self.decoder = Decoder()
        self._errors_reported = 0
        self._faults = msg.Fault.RESET

    def receive(self, data: bytes, now_s: float) -> bytes:
        """Handle the bytes received at ``now_s``; return the replies to send."""
        replies = [encode_frame(self._handle(frame, now_s)) for frame in self.decoder.feed(data)]
        self.model.advance(now_s)
        return b"".join(replies)

    def _handle(self, frame: Frame, now_s: float) -> Frame:
        self.model.counters.frames += 1
        kind = frame.type
        if kind not in (msg.MsgType.PING, msg.MsgType.SET_WHEELS, msg.MsgType.SET_ARM,
                        msg.MsgType.STOP):
            return self._nack(frame, msg.NackReason.UNKNOWN_TYPE)
        if len(frame.payload) != msg.PAYLOAD_SIZE[msg.MsgType(kind)]:
            return self._nack(frame, msg.NackReason.BAD_LENGTH)
        if kind == msg.MsgType.PING:
            watchdog_ms = round(self.model.watchdog_s * 1000)
            version = msg.Version(msg.PROTOCOL_VERSION, FIRMWARE_VERSION, watchdog_ms)
            return msg.encode_version(frame.seq, version)
        limited = False
        if kind == msg.MsgType.SET_WHEELS:
            limited = self.model.command_wheels(msg.decode_values(frame), now_s)
        elif kind == msg.MsgType.SET_ARM:
            limited = self.model.command_arm(msg.decode_values(frame), now_s)
        else:
            self.model.stop(now_s)
        if limited:
            self.model.counters.limited += 1
            self._faults |= msg.Fault.LIMIT
        return self.telemetry(frame.seq)

    def _nack(self, frame: Frame, reason: msg.NackReason) -> Frame:
        self.model.counters.nacks += 1
        return msg.encode_nack(frame.seq, frame.type, reason)

    def telemetry(self, seq: int) -> Frame:
        """TELEMETRY answering ``seq``; reports and clears the one-shot fault flags."""
        faults = self._faults
        if self.decoder.stats.errors > self._errors_reported:
            faults |= msg.Fault.CRC
            self._errors_reported = self.decoder.stats.errors
        if self.model.watchdog_fired:
            faults |= msg.Fault.WATCHDOG
        self._faults = msg.Fault(0)
        model = self.model
        return msg.encode_telemetry(seq, msg.Telemetry(
            tuple(model.wheel_position_rad), tuple(model.measured_wheel_velocity_rad_s),
            tuple(model.arm_position_rad), faults))

    def state(self) -> State:
        """The decoder's counts, for the emulator's state file."""
        stats = self.decoder.stats
        return {"crc_errors": stats.crc_errors, "bad_length": stats.bad_length,
                "discarded_bytes": stats.discarded_bytes}
