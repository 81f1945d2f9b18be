"""Setpoints to the bytes of one tick, shared by the drive loop and ``--dry-run``.

Each tick sends one frame: wheel speeds, or, when the arm targets changed, the arm targets
instead (never twice in a row, so the wheel stream keeps the watchdog fed). The commander
also integrates the commanded wheel speeds over time: the travel the encoders should show.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.protocols.events import Event, Hello
from servicebot_cli.drive.shaping import WheelShaper


class HostLink(Protocol):
    """A host-side protocol adapter (binary.BinaryLink or arduino.ArduinoLink)."""

    name: str
    has_arm: bool
    command_bytes: int
    reply_bytes: int
    stop_timeout_s: float
    stop_resend_s: float
    count_rad: float
    """The wheel angle of one encoder count the firmware reports [rad]; 0: continuous."""

    def hello(self) -> bytes:
        """The handshake request."""

    def wheels(self, speeds_rad_s: Sequence[float]) -> tuple[bytes, int]:
        """Bytes and token for wheel joint velocities."""

    def quantised(self, speeds_rad_s: Sequence[float]) -> tuple[float, ...]:
        """The speeds the wire really carries for ``speeds_rad_s``."""

    def arm(self, targets_rad: Sequence[float]) -> tuple[bytes, int]:
        """Bytes and token for arm targets."""

    def stop(self) -> tuple[bytes, int]:
        """Bytes and token for a stop."""

    def feed(self, data: bytes, now_s: float) -> list[Event]:
        """Events for the bytes received at ``now_s``."""

    def reset(self) -> None:
        """Forget the stream state (the port was reopened)."""

    def describe(self, data: bytes) -> str:
        """What ``data`` means, for people."""

    def still(self, stop_tokens: set[int], now_s: float) -> bool:
        """Whether what the firmware reported since a stop in ``stop_tokens`` shows it stopped."""

    def refusal_advice(self, where: str) -> str:
        """One line: what to rebuild or configure when the firmware refuses every command."""

    def auto_stop_note(self, hello: Hello | None) -> str:
        """Who stops the motors, and when, if drive could not."""

    @property
    def errors(self) -> int:
        """Rejected input so far."""


class Commander:
    """Builds each tick's command from a setpoint.

    Args:
        link: The protocol adapter.
        shaper: Twist to limited wheel speeds.
        motors: The robot's motors.
        arm_guard: Called once with where the firmware first reports the arm, before any
            arm target is sent; it raises to refuse the plan's arm motion from there.
    """

    def __init__(self, link: HostLink, shaper: WheelShaper, motors: MotorMap,
                 arm_guard: Callable[[tuple[float, ...]], None] | None = None) -> None:
        self.link, self.shaper, self.motors = link, shaper, motors
        self._arm_guard = arm_guard
        self.commanded_rad_s: tuple[float, ...] = (0.0,) * len(motors.wheel_joints)
        self.travel_rad = [0.0] * len(motors.wheel_joints)
        self.arm_base: tuple[float, ...] | None = None
        self.arm_sent: tuple[float, ...] | None = None
        self._since_s: float | None = None
        self._last_was_arm = False

    def observe_arm(self, positions_rad: Sequence[float] | None) -> None:
        """Arm positions the firmware reports; the first become the targets of unnamed joints."""
        if self.arm_base is None and positions_rad is not None:
            self.arm_base = self.motors.clamp_arm(positions_rad)

    def arm_targets(self, setpoint: Setpoint) -> tuple[float, ...] | None:
        """Full arm targets for ``setpoint``, or None when it names none or the base is unknown."""
        if not setpoint.arm or self.arm_base is None:
            return None
        base = self.arm_sent if self.arm_sent is not None else self.arm_base
        return self.motors.arm_targets(dict(setpoint.arm), base)

    def command(self, setpoint: Setpoint, now_s: float, dt_s: float) -> tuple[bytes, int, str]:
        """``(bytes, token, kind)`` for this tick; kind is ``"wheels"`` or ``"arm"``.

        Raises:
            ServicebotError: What the arm guard raises, the first tick the arm is known.
        """
        if self._arm_guard is not None and self.arm_base is not None:
            guard, self._arm_guard = self._arm_guard, None
            guard(self.arm_base)
        arm = self.arm_targets(setpoint)
        if arm is not None and arm != self.arm_sent and not self._last_was_arm:
            self._last_was_arm = True
            self.arm_sent = arm
            data, token = self.link.arm(arm)
            return data, token, "arm"
        self._last_was_arm = False
        speeds = self.shaper.step(setpoint.linear_m_s, setpoint.angular_rad_s, dt_s)
        self._account(now_s, self.link.quantised(speeds))
        data, token = self.link.wheels(speeds)
        return data, token, "wheels"

    def stop(self, now_s: float) -> tuple[bytes, int]:
        """The stop command; the wheels ramp from zero afterwards."""
        self._account(now_s, (0.0,) * len(self.commanded_rad_s))
        self.shaper.reset()
        return self.link.stop()

    def _account(self, now_s: float, speeds: tuple[float, ...]) -> None:
        if self._since_s is not None:
            elapsed = max(0.0, now_s - self._since_s)
            for i, v in enumerate(self.commanded_rad_s):
                self.travel_rad[i] += v * elapsed
        self._since_s = now_s
        self.commanded_rad_s = speeds

    def link_lost(self, now_s: float) -> None:
        """The link went down: the wheels ramp from zero and the arm targets are sent again."""
        self._account(now_s, (0.0,) * len(self.commanded_rad_s))
        self.shaper.reset()
        self._last_was_arm = False
        self.arm_sent = None
