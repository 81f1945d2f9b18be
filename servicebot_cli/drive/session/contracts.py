"""What the drive loop is given and gives back: setpoint sources, job control, status.

Kept apart from the loop so that teleop, plans and the status line depend on these
contracts, not on the loop itself.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from servicebot_cli.common.errors import LinkError
from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.protocols.events import Reading


class FirmwareRefuses(LinkError):
    """The firmware answers, but refuses every motion command (exit 4)."""


class Suspender(Protocol):
    """Job control for teleop: Ctrl-Z asks to suspend, SIGCONT says the process went on."""

    requested: bool
    resumed: bool

    def suspend(self) -> None:
        """Give the terminal back and stop the process; returns once it is continued."""


class Source(Protocol):
    """Where setpoints come from: a plan or the keyboard."""

    fds: tuple[int, ...]

    def setpoint(self, t_s: float) -> Setpoint | None:
        """The setpoint at ``t_s`` after the start, or None when done."""

    def poll(self) -> None:
        """Consume input that made one of :attr:`fds` readable."""


@dataclass(frozen=True)
class LinkStatus:
    """A snapshot of the run, for the status line and the summary."""

    t_s: float
    commanded_rad_s: tuple[float, ...]
    reading: Reading | None
    reply_rate_hz: float
    rtt_s: float | None
    errors: int
    commands: int
    replies: int
    reconnecting: bool
    scaled: bool
