"""SIGTERM, SIGHUP and SIGQUIT as exceptions, so every ``finally`` runs before the exit.

A CI job cancelled (SIGTERM) or a terminal closed (SIGHUP) must leave no temporary file
behind, exactly as Ctrl-C does: :class:`EndedBySignal` unwinds the stack like
:class:`KeyboardInterrupt`, so the atomic writers' clean-up runs. It derives from
:class:`BaseException` for the same reason ``KeyboardInterrupt`` does: an ``except
Exception`` in library code must not swallow it.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator
from types import FrameType

ENDING_SIGNALS = (signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT)


class EndedBySignal(BaseException):
    """A signal ended the run; the exit code is 128 plus the signal's number."""

    def __init__(self, signum: int) -> None:
        self.signum = signum
        self.exit_code = 128 + signum
        super().__init__(f"{signal.Signals(signum).name.lower().removeprefix('sig')}: "
                         f"ended by {signal.Signals(signum).name}")

    @property
    def description(self) -> str:
        """What happened, for the one stderr line: ``terminated (SIGTERM)``."""
        what = {signal.SIGTERM: "terminated", signal.SIGHUP: "hung up",
                signal.SIGQUIT: "quit"}.get(signal.Signals(self.signum), "ended")
        return f"{what} ({signal.Signals(self.signum).name})"


def _raise(signum: int, frame: FrameType | None) -> None:
    raise EndedBySignal(signum)


@contextlib.contextmanager
def signals_as_exceptions() -> Iterator[None]:
    """Within the block, SIGTERM, SIGHUP and SIGQUIT raise :class:`EndedBySignal`.

    Only the main thread can install handlers; elsewhere the block runs unchanged.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {signum: signal.signal(signum, _raise) for signum in ENDING_SIGNALS}
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
