"""Ctrl-C and the ending signals during a drive: end the run once, never interrupt the stop.

The first SIGINT, SIGTERM, SIGHUP or SIGQUIT raises :class:`Interrupted`,
:class:`Terminated`, :class:`HungUp` or :class:`Quit` in the main thread, wherever the loop
is; the caller's ``finally`` then stops the motors. Signals that arrive while the stop is
being sent are noted and ignored: a second Ctrl-C must not leave the robot driving.
"""

from __future__ import annotations

import signal
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import TypeAlias

from servicebot_cli.common.errors import ExitCode, ServicebotError

SignalHandler: TypeAlias = Callable[[int, FrameType | None], object] | int | None


class Interrupted(ServicebotError):
    """Ctrl-C (SIGINT) ended the run."""

    exit_code = ExitCode.INTERRUPTED


class Terminated(ServicebotError):
    """SIGTERM ended the run."""

    exit_code = ExitCode.TERMINATED


class HungUp(ServicebotError):
    """SIGHUP (the terminal closed) ended the run."""

    exit_code = ExitCode.HANGUP


class Quit(ServicebotError):
    """SIGQUIT ended the run."""

    exit_code = ExitCode.QUIT


# What each signal raises, with its message (the words cli.py uses for the same signals).
ENDINGS: dict[int, tuple[type[ServicebotError], str]] = {
    signal.SIGINT: (Interrupted, "interrupted (Ctrl-C)"),
    signal.SIGTERM: (Terminated, "terminated (SIGTERM)"),
    signal.SIGHUP: (HungUp, "hung up (SIGHUP)"),
    signal.SIGQUIT: (Quit, "quit (SIGQUIT)"),
}
# The ``outcome`` of a run each of them ended, in the summary.
OUTCOMES: tuple[tuple[type[ServicebotError], str], ...] = (
    (Interrupted, "interrupted"), (Terminated, "terminated"), (HungUp, "hung_up"),
    (Quit, "quit"),
)


class StopSignals:
    """Context manager: the ending signals raise once; after :meth:`stopping`, they are ignored."""

    def __init__(self) -> None:
        self.received: int | None = None
        self._stopping = False
        self._previous: dict[int, SignalHandler] = {}

    def __enter__(self) -> StopSignals:
        for signum in ENDINGS:
            self._previous[signum] = signal.signal(signum, self._handle)
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None,
                 traceback: TracebackType | None) -> None:
        for signum, handler in self._previous.items():
            signal.signal(signum, handler)

    def stopping(self) -> None:
        """From now on, signals are only remembered: the motors are being stopped."""
        self._stopping = True

    def _handle(self, signum: int, frame: FrameType | None) -> None:
        first = self.received is None
        if first:
            self.received = signum
        if first and not self._stopping:
            error, message = ENDINGS[signum]
            raise error(message)
