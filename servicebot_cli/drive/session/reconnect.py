"""Finding a lost link again: reopen, let the board boot, ask; back off; give up at the limit.

Each attempt opens the port once. On a board that resets when its port opens, that open is
a reset, so an attempt must wait out the whole boot before it asks (``--boot-time-s``): an
attempt that asks too early fails, and the next one resets the board again. Between failed
attempts the pause doubles from :attr:`ReconnectPolicy.first_pause_s` up to
:attr:`ReconnectPolicy.max_pause_s`; after :attr:`ReconnectPolicy.attempts` failures the run
ends with :class:`~servicebot_cli.common.errors.LinkLost` (exit 5) and one line that says
what the last attempt met and what to change.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from servicebot_cli.common.errors import LinkError, LinkLost
from servicebot_cli.drive.session.probe import NoAnswer

DEFAULT_ATTEMPTS = 8


@dataclass(frozen=True)
class ReconnectPolicy:
    """How hard to try to get a lost link back.

    Attributes:
        attempts: Opens to try before giving up.
        first_pause_s: The pause after the first failed attempt [s]; it doubles from there.
        max_pause_s: The longest pause between attempts [s].
    """

    attempts: int = DEFAULT_ATTEMPTS
    first_pause_s: float = 0.5
    max_pause_s: float = 4.0

    def pause_s(self, failed: int) -> float:
        """The pause after ``failed`` failed attempts, ``min(max, first * 2^(failed-1))`` [s]."""
        return min(self.max_pause_s, self.first_pause_s * 2.0 ** (failed - 1))

    def describe(self) -> str:
        """The policy in words, for the line that says the link is lost."""
        return (f"up to {self.attempts} attempts, backing off from {self.first_pause_s:g} s "
                f"to {self.max_pause_s:g} s")


class Reconnectable(Protocol):
    """What the attempts need of the run."""

    def wanted(self) -> bool:
        """Whether the run still has setpoints to send (False: it ended meanwhile)."""

    def reopen_port(self) -> None:
        """Open the port, wait for the boot, handshake, send a stop; raises LinkError."""

    def drop_port(self) -> None:
        """Close the port of a failed attempt."""

    def idle(self, duration_s: float) -> None:
        """Wait between attempts (still reading the keyboard)."""


def reconnect(run: Reconnectable, policy: ReconnectPolicy, lost: LinkLost, *,
              boot_s: float, clock: Callable[[], float]) -> int:
    """Try to get the link back; the number of attempts it took.

    Args:
        run: Opens, waits and asks, once per attempt.
        policy: How many attempts, and the pauses between them.
        lost: What lost the link.
        boot_s: What each attempt waits after opening, for the message [s].
        clock: Monotonic time [s].

    Raises:
        LinkLost: The run ended before the link came back, or every attempt failed; the
            message starts with ``lost`` and says what the last attempt met.
    """
    start_s = clock()
    failure: LinkError | None = None
    for attempt in range(1, policy.attempts + 1):
        if attempt > 1:
            run.idle(policy.pause_s(attempt - 1))
        if not run.wanted():
            raise LinkLost(f"{lost}; the run ended before the link came back")
        try:
            run.reopen_port()
            return attempt
        except LinkError as exc:  # the port is missing, or died again, or nothing answered
            run.drop_port()
            failure = exc
    raise LinkLost(gave_up(lost, policy.attempts, clock() - start_s, failure, boot_s))


def gave_up(lost: LinkLost, attempts: int, elapsed_s: float, failure: LinkError | None,
            boot_s: float) -> str:
    """One line: the loss, how long drive tried, what the last attempt met, what to change."""
    line = (f"{lost}; gave up reconnecting after {attempts} attempts in {elapsed_s:.1f} s "
            "(--reconnect-attempts)")
    if isinstance(failure, NoAnswer):
        within = f" within {failure.timeout_s:g} s" if failure.timeout_s is not None else ""
        return line + (f"; the last one opened the port, waited {boot_s:g} s for the board to "
                       f"boot and got no answer{within}: a board that resets when its port "
                       "opens needs --boot-time-s of at least its boot time")
    return line + (f"; the last one: {failure}" if failure is not None else "")
