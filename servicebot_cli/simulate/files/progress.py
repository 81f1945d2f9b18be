"""A progress bar on stderr for long runs, silent for short ones, in CI and in pipes.

It draws nothing until ``delay_s`` of wall time has passed (so quick runs stay quiet) and only
when its stream is a terminal and ``CI`` is not set. The clock is injected for tests.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from typing import TextIO


class Progress:
    """Counts work done out of ``total`` and redraws one line at most ten times a second."""

    def __init__(self, total: int, stream: TextIO, *, label: str = "simulating",
                 delay_s: float = 1.5, clock: Callable[[], float] = time.monotonic,
                 enabled: bool | None = None) -> None:
        self.total, self.stream, self.label, self.clock = max(total, 1), stream, label, clock
        self.start, self.delay_s, self.done, self.last_draw = clock(), delay_s, 0, 0.0
        self.drawn = False
        if enabled is None:
            enabled = _is_terminal(stream) and not os.environ.get("CI")
        self.enabled = enabled

    def advance(self, amount: int = 1) -> None:
        """Record ``amount`` more units of work; redraw when due."""
        self.done = min(self.total, self.done + amount)
        if not self.enabled:
            return
        now = self.clock()
        if now - self.start < self.delay_s or now - self.last_draw < 0.1:
            return
        self.last_draw = now
        self._draw()

    def _draw(self) -> None:
        width = 30
        filled = int(width * self.done / self.total)
        percent = 100 * self.done // self.total
        self.drawn = True  # before the write: a signal right after it must still erase the bar
        self.stream.write(f"\r{self.label:<14} [{'#' * filled}{'-' * (width - filled)}] "
                          f"{percent:3d}%")
        self.stream.flush()

    def close(self) -> None:
        """Erase the bar, if one was drawn."""
        if self.drawn:
            self.stream.write("\r" + " " * 60 + "\r")
            self.stream.flush()


def _is_terminal(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False
