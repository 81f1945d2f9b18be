"""What a host-side protocol adapter makes of the bytes the firmware sends back.

Both protocols (``servicebot`` binary frames and ROSArduinoBridge text lines) produce these,
so the drive loop never looks at bytes.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Hello:
    """The firmware answered the handshake.

    Attributes:
        description: What the firmware says it is, for people.
        watchdog_ms: Its watchdog timeout [ms], when it says.
        compatible: False when it speaks another version of the protocol.
        baud: The baud rate it says it runs at, when it says (ROSArduinoBridge's ``b``).
    """

    description: str
    watchdog_ms: int | None = None
    compatible: bool = True
    baud: int | None = None


@dataclass(frozen=True)
class Reading:
    """Telemetry in the robot's joint coordinates.

    Attributes:
        ack: Token of the command this reply answers, when the protocol says.
        wheel_position_rad: Wheel joint angles, unwrapped (continuous since the start) [rad].
        wheel_velocity_rad_s: Wheel joint velocities [rad/s].
        arm_position_rad: Arm joint positions [rad], or None when the protocol has no arm.
        faults: Names of the fault flags set.
    """

    ack: int | None
    wheel_position_rad: tuple[float, ...]
    wheel_velocity_rad_s: tuple[float, ...]
    arm_position_rad: tuple[float, ...] | None
    faults: tuple[str, ...] = ()


@dataclass(frozen=True)
class Ack:
    """The firmware accepted the command with token ``token`` (no telemetry in the reply)."""

    token: int


@dataclass(frozen=True)
class Refused:
    """The firmware refused a command (valid bytes, wrong content)."""

    reason: str


Event = Hello | Reading | Ack | Refused
