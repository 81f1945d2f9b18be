"""A progress bar for sweeps: runs finished out of all, and the time left.

Drawn on its stream only when that is a terminal and ``CI`` is not set (or when asked);
silent in pipes and CI logs. The time left is the mean wall time per run finished so far
(runs found done are not counted) times the runs still to go. The clock is injected.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from typing import TextIO


class SweepProgress:
    """``sweep  37/200 [#####-----------]  1m12s left``, redrawn at most ten times a second."""

    def __init__(self, total: int, stream: TextIO, *, done: int = 0,
                 enabled: bool | None = None, clock: Callable[[], float] = time.monotonic
                 ) -> None:
        self.total, self.stream, self.clock = max(total, 1), stream, clock
        self.done, self.skipped = done, done
        self.start, self.last_draw, self.width = clock(), float("-inf"), 0
        if enabled is None:
            enabled = _is_terminal(stream) and not os.environ.get("CI")
        self.enabled = enabled
        self._draw(self.start)  # at once: the first run may take a while

    def advance(self) -> None:
        """One more run finished; redraw when due."""
        self.done = min(self.total, self.done + 1)
        now = self.clock()
        if now - self.last_draw >= 0.1 or self.done == self.total:
            self._draw(now)

    def _draw(self, now: float) -> None:
        """Write the bar over the last one (padded, so a shorter line leaves nothing behind)."""
        if not self.enabled:
            return
        self.last_draw = now
        line = self.line(now)
        padded = line.ljust(self.width)
        self.width = max(self.width, len(line))  # before the write: close() after a signal
        self.stream.write("\r" + padded)  # right after it must erase all of it
        self.stream.flush()

    def line(self, now: float) -> str:
        """The bar as text at time ``now``."""
        width = 24
        filled = width * self.done // self.total
        ran = self.done - self.skipped
        left = (now - self.start) / ran * (self.total - self.done) if ran else None
        eta = f"{_duration(left)} left" if left is not None else ""
        return (f"sweep {self.done:>{len(str(self.total))}}/{self.total} "
                f"[{'#' * filled}{'-' * (width - filled)}] {eta}").rstrip()

    def close(self) -> None:
        """Erase the bar, if one was drawn."""
        if self.width:
            self.stream.write("\r" + " " * self.width + "\r")
            self.stream.flush()


def _duration(seconds: float) -> str:
    """``45s``, ``3m05s``, ``2h10m``."""
    total = round(seconds)
    if total < 60:
        return f"{total}s"
    if total < 3600:
        return f"{total // 60}m{total % 60:02d}s"
    return f"{total // 3600}h{total % 3600 // 60:02d}m"


def _is_terminal(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False
