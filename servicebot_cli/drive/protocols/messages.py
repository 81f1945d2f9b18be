"""Messages of the servicebot serial protocol: types, payloads, wire units, fault flags.

Wire units are integers in thousandths: wheel speeds in mrad/s, arm targets and positions in
mrad (mm for a prismatic joint), wheel positions in mrad modulo 2**16 (the host unwraps).
Encoding clamps to the robot's limits first, then rounds toward the inside of the range, so
no encodable command is beyond a limit. Pure: values in, bytes out, and back.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Sequence
from dataclasses import dataclass
from enum import IntEnum, IntFlag

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.framing import OVERHEAD, Frame

PROTOCOL_VERSION = 1
SLOTS = 4  # wheels per SET_WHEELS, arm joints per SET_ARM
SCALE = 1000.0  # wire counts per SI unit


class MsgType(IntEnum):
    """Message types; replies from the firmware have the high bit set."""

    PING = 0x01
    SET_WHEELS = 0x10
    SET_ARM = 0x11
    STOP = 0x12
    VERSION = 0x81
    TELEMETRY = 0x90
    NACK = 0xFF


class Fault(IntFlag):
    """Fault flags in TELEMETRY; each is cleared once reported, unless its cause remains."""

    WATCHDOG = 0x01  # the watchdog stopped the motors since the last motion command
    CRC = 0x02  # a frame failed its CRC (or its length) since the last telemetry
    LIMIT = 0x04  # a command was beyond the firmware's limits and was clamped
    MOTOR = 0x08  # motor driver fault: over-current, over-temperature
    ESTOP = 0x10  # the emergency stop is pressed
    RESET = 0x20  # the firmware started since the last telemetry


class NackReason(IntEnum):
    """Why the firmware refused a frame whose CRC was good."""

    UNKNOWN_TYPE = 1
    BAD_LENGTH = 2


class ProtocolError(ValueError):
    """A payload that does not fit its message type."""


_WHEELS = struct.Struct("<4h")
_ARM = struct.Struct("<4h")
_VERSION = struct.Struct("<BBBH")
_TELEMETRY = struct.Struct("<4h4h4hB")
_NACK = struct.Struct("<BB")

PAYLOAD_SIZE = {
    MsgType.PING: 0, MsgType.SET_WHEELS: _WHEELS.size, MsgType.SET_ARM: _ARM.size,
    MsgType.STOP: 0, MsgType.VERSION: _VERSION.size, MsgType.TELEMETRY: _TELEMETRY.size,
    MsgType.NACK: _NACK.size,
}
COMMAND_FRAME_BYTES = OVERHEAD + _WHEELS.size  # the largest frame the host streams
REPLY_FRAME_BYTES = OVERHEAD + _TELEMETRY.size  # the reply to every streamed command


@dataclass(frozen=True)
class Version:
    """The reply to PING.

    Attributes:
        protocol: Protocol version the firmware speaks.
        firmware: Firmware version ``(major, minor)``.
        watchdog_ms: The firmware's watchdog timeout [ms].
    """

    protocol: int
    firmware: tuple[int, int]
    watchdog_ms: int


@dataclass(frozen=True)
class Telemetry:
    """The reply to every command: the motors as the firmware measures them.

    Attributes:
        wheel_position_rad: Wheel angles modulo 2**16 mrad, in (-32.768, 32.767] [rad].
        wheel_velocity_rad_s: Measured wheel speeds [rad/s].
        arm_position_rad: Measured arm positions [rad].
        faults: :class:`Fault` flags.
    """

    wheel_position_rad: tuple[float, ...]
    wheel_velocity_rad_s: tuple[float, ...]
    arm_position_rad: tuple[float, ...]
    faults: Fault


def wheel_counts(speeds_rad_s: Sequence[float], motors: MotorMap) -> tuple[int, ...]:
    """Wire counts [mrad/s] for wheel speeds: clamped, then rounded toward zero."""
    counts = []
    for v, limit in zip(motors.clamp_wheels(speeds_rad_s), motors.wheel_max_rad_s, strict=True):
        count = int(v * SCALE)  # int() truncates toward zero: never faster than asked
        while abs(count) / SCALE > limit:
            count -= 1 if count > 0 else -1
        counts.append(count)
    return tuple(counts)


def arm_counts(targets_rad: Sequence[float], motors: MotorMap) -> tuple[int, ...]:
    """Wire counts [mrad] for arm targets: clamped, rounded, kept inside the range."""
    counts = []
    for v, lo, hi in zip(motors.clamp_arm(targets_rad), motors.arm_lower, motors.arm_upper,
                         strict=True):
        count = round(v * SCALE)
        while count / SCALE > hi:
            count -= 1
        while count / SCALE < lo:
            count += 1
        counts.append(count)
    return tuple(counts)


def set_wheels(seq: int, speeds_rad_s: Sequence[float], motors: MotorMap) -> Frame:
    """SET_WHEELS for every wheel's joint velocity [rad/s], wire order."""
    return Frame(seq, MsgType.SET_WHEELS, _WHEELS.pack(*wheel_counts(speeds_rad_s, motors)))


def set_arm(seq: int, targets_rad: Sequence[float], motors: MotorMap) -> Frame:
    """SET_ARM for every arm joint's target [rad], wire order."""
    return Frame(seq, MsgType.SET_ARM, _ARM.pack(*arm_counts(targets_rad, motors)))


def decode_values(frame: Frame) -> tuple[float, ...]:
    """The four SI values of a SET_WHEELS [rad/s] or SET_ARM [rad] frame."""
    _check(frame)
    return tuple(c / SCALE for c in _WHEELS.unpack(frame.payload))


def encode_version(seq: int, version: Version) -> Frame:
    """VERSION, the reply to PING."""
    payload = _VERSION.pack(version.protocol, *version.firmware, version.watchdog_ms)
    return Frame(seq, MsgType.VERSION, payload)


def decode_version(frame: Frame) -> Version:
    """The content of a VERSION frame."""
    _check(frame)
    protocol, major, minor, watchdog_ms = _VERSION.unpack(frame.payload)
    return Version(protocol, (major, minor), watchdog_ms)


def encode_telemetry(seq: int, telemetry: Telemetry) -> Frame:
    """TELEMETRY; positions are wrapped to 16 bits, speeds saturate at the int16 range."""
    wheels = [_wrap16(round(p * SCALE)) for p in telemetry.wheel_position_rad]
    speeds = [_int16(v) for v in telemetry.wheel_velocity_rad_s]
    arm = [_int16(p) for p in telemetry.arm_position_rad]
    payload = _TELEMETRY.pack(*wheels, *speeds, *arm, int(telemetry.faults))
    return Frame(seq, MsgType.TELEMETRY, payload)


def decode_telemetry(frame: Frame) -> Telemetry:
    """The content of a TELEMETRY frame."""
    _check(frame)
    values = _TELEMETRY.unpack(frame.payload)
    return Telemetry(
        wheel_position_rad=tuple(c / SCALE for c in values[0:4]),
        wheel_velocity_rad_s=tuple(c / SCALE for c in values[4:8]),
        arm_position_rad=tuple(c / SCALE for c in values[8:12]),
        faults=Fault(values[12]),
    )


def encode_nack(seq: int, refused_type: int, reason: NackReason) -> Frame:
    """NACK: the firmware refused a frame (its type and why)."""
    return Frame(seq, MsgType.NACK, _NACK.pack(refused_type, reason))


def decode_nack(frame: Frame) -> tuple[int, NackReason]:
    """``(refused type, reason)`` of a NACK frame."""
    _check(frame)
    refused, reason = _NACK.unpack(frame.payload)
    return refused, NackReason(reason) if reason in NackReason._value2member_map_ else reason


def _check(frame: Frame) -> None:
    try:
        expected = PAYLOAD_SIZE[MsgType(frame.type)]
    except ValueError:
        raise ProtocolError(f"unknown message type 0x{frame.type:02X}") from None
    if len(frame.payload) != expected:
        raise ProtocolError(
            f"{MsgType(frame.type).name} needs {expected} payload bytes, got {len(frame.payload)}"
        )


def _wrap16(count: int) -> int:
    return (count + 0x8000) % 0x10000 - 0x8000


def _int16(value: float) -> int:
    if math.isnan(value):
        return 0
    return max(-0x8000, min(0x7FFF, round(value * SCALE))) if math.isfinite(value) else (
        0x7FFF if value > 0 else -0x8000)


def describe(frame: Frame) -> str:
    """One line naming the message and its values in SI units, for logs and --dry-run."""
    try:
        kind = MsgType(frame.type)
    except ValueError:
        return f"type 0x{frame.type:02X} seq={frame.seq} ({len(frame.payload)} bytes)"
    try:
        if kind in (MsgType.SET_WHEELS, MsgType.SET_ARM):
            unit = "rad/s" if kind is MsgType.SET_WHEELS else "rad"
            values = " ".join(f"{v:+.3f}" for v in decode_values(frame))
            return f"{kind.name} seq={frame.seq} [{values}] {unit}"
        if kind is MsgType.VERSION:
            return f"{kind.name} seq={frame.seq} {decode_version(frame)}"
        if kind is MsgType.TELEMETRY:
            return f"{kind.name} seq={frame.seq} {decode_telemetry(frame)}"
        if kind is MsgType.NACK:
            return f"{kind.name} seq={frame.seq} {decode_nack(frame)}"
        _check(frame)
    except ProtocolError as exc:
        return f"{kind.name} seq={frame.seq} malformed: {exc}"
    return f"{kind.name} seq={frame.seq}"
