"""The board around the firmware: what a reset does, and the boot that follows it.

An Arduino Uno resets whenever a host opens its port (the USB-serial chip pulls DTR, and DTR
is wired to RESET): the firmware starts over with everything forgotten (speeds, encoder
counts, sequence numbers), and for the bootloader's time it does not run at all, so what
arrives meanwhile is lost. :class:`Board` is that, as a pure state machine: the caller says
when the port opened (:meth:`Board.reset`) and what arrived when; the firmware is built
anew by ``build`` at each reset. Time is passed in.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from servicebot_cli.drive.emulator.firmware import MotorModel, State


class Firmware(Protocol):
    """What the server needs of a firmware (binary or ROSArduinoBridge)."""

    protocol: str
    model: MotorModel

    def receive(self, data: bytes, now_s: float) -> bytes:
        """Handle received bytes; return the reply bytes."""

    def state(self) -> State:
        """Protocol-specific state for the state file."""


class Board:
    """A firmware on a board that may reset when its port opens.

    Args:
        build: Makes the firmware as it is right after a reset, at a time [s].
        now_s: The time the board is powered [s]; it is running from then on.
        boot_s: How long it is deaf after each reset [s], or None for a board that does
            not reset when its port opens (the port opening changes nothing).
    """

    def __init__(self, build: Callable[[float], Firmware], now_s: float,
                 boot_s: float | None = None) -> None:
        self.build = build
        self.boot_s = boot_s
        self.firmware = build(now_s)
        self.protocol = self.firmware.protocol
        self.model = self.firmware.model
        self.resets = 0
        self.lost_bytes = 0  # received while booting
        self.ready_s = now_s

    @property
    def resets_on_open(self) -> bool:
        """Whether a host opening the port resets the board."""
        return self.boot_s is not None

    def reset(self, now_s: float) -> None:
        """Start over at ``now_s``: a new firmware, deaf until ``now_s + boot_s``."""
        self.firmware = self.build(now_s)
        self.model = self.firmware.model
        self.resets += 1
        self.ready_s = now_s + (self.boot_s or 0.0)

    def booting(self, now_s: float) -> bool:
        """Whether the bootloader still runs at ``now_s`` (the firmware hears nothing)."""
        return now_s < self.ready_s

    def receive(self, data: bytes, now_s: float) -> bytes:
        """The firmware's replies to ``data``; nothing while booting, and ``data`` is lost."""
        if self.booting(now_s):
            self.lost_bytes += len(data)
            return b""
        return self.firmware.receive(data, now_s)

    def state(self) -> State:
        """The firmware's own state, for the state file."""
        return self.firmware.state()

    def boot_state(self, now_s: float) -> State:
        """Resets, boot and lost bytes, for the state file."""
        return {"boot_s": self.boot_s, "resets": self.resets,
                "booting": self.booting(now_s), "lost_bytes": self.lost_bytes}
