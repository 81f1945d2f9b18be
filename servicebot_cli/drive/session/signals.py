"""Ctrl-C and SIGTERM during a drive: end the run once, never interrupt the stop.

The first SIGINT or SIGTERM raises :class:`Interrupted` or :class:`Terminated` in the main
thread, wherever the loop is; the caller's ``finally`` then stops the motors. Signals that
arrive while the stop is being sent are noted and ignored: a second Ctrl-C must not leave
the robot driving.
"""

from __future__ import annotations

import signal
from types import FrameType, TracebackType
from typing import Any

from servicebot_cli.common.errors import ExitCode, ServicebotError


class Interrupted(ServicebotError):
    """Ctrl-C (SIGINT) ended the run."""

    exit_code = ExitCode.INTERRUPTED


class Terminated(ServicebotError):
    """SIGTERM ended the run."""

    exit_code = ExitCode.TERMINATED


class StopSignals:
    """Context manager: SIGINT/SIGTERM raise once; after :meth:`stopping`, they are ignored."""

    def __init__(self) -> None:
        self.received: int | None = None
        self._stopping = False
        self._previous: dict[int, Any] = {}

    def __enter__(self) -> StopSignals:
        for signum in (signal.SIGINT, signal.SIGTERM):
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
            if signum == signal.SIGINT:
                raise Interrupted("interrupted (Ctrl-C)")
            raise Terminated("terminated (SIGTERM)")
