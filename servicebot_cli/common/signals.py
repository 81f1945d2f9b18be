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
import sys
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

    def __reduce__(self) -> tuple[type[EndedBySignal], tuple[int]]:
        """Rebuilt from its signal number when unpickled.

        A worker process sends it back to its parent (sweep's pool), which otherwise fails
        to rebuild it from the message and hangs.
        """
        return EndedBySignal, (self.signum,)

    @property
    def description(self) -> str:
        """What happened, for the one stderr line: ``terminated (SIGTERM)``."""
        what = {signal.SIGTERM: "terminated", signal.SIGHUP: "hung up",
                signal.SIGQUIT: "quit"}.get(signal.Signals(self.signum), "ended")
        return f"{what} ({signal.Signals(self.signum).name})"


class _Deferral:
    """Signals held back and raised.

    How many blocks hold signals back now, the first signal that came meanwhile, and the
    signal last raised as an exception (until the exception is seen leaving the block).
    """

    depth = 0
    pending: int | None = None
    raised: int | None = None


def _raise(signum: int, frame: FrameType | None) -> None:
    if _Deferral.depth:
        _Deferral.pending = _Deferral.pending or signum
        return
    _raise_for(signum)


def _raise_for(signum: int) -> None:
    _Deferral.raised = signum
    if signum == signal.SIGINT:
        raise KeyboardInterrupt
    raise EndedBySignal(signum)


def raise_lost() -> None:
    """Raise again a signal whose exception never left :func:`signals_as_exceptions`' block.

    A handler's exception raised while numpy runs Python code inside one of its loops can
    be cleared there, and the run would go on as if no signal had come. Outputs call this
    before they go in place, so such a run still ends by its signal and leaves nothing.
    While an exception is on its way out (the signal's own, or another), nothing is raised:
    what a clean-up writes then (``sweep``'s table of the finished runs) is its to write.
    """
    if _Deferral.raised is not None and sys.exc_info()[1] is None:
        _raise_for(_Deferral.raised)


class SignalsHeld:
    """Signals that end a run held back until :meth:`release` (the ``finally`` of a clean-up).

    A process-directed signal may be delivered to any thread (numpy's BLAS threads among
    them), and CPython then runs the handler in the main thread at once: blocking it in the
    main thread's signal mask does not hold it back. The handlers that
    :func:`signals_as_exceptions` installs check this instead: while a hold is on, a signal is
    kept and raised by :meth:`release` (once, by the outermost hold).
    """

    def __init__(self) -> None:
        _Deferral.depth += 1
        self._held = True

    def release(self) -> None:
        """End the hold; raise the signal that came meanwhile, if this was the last hold."""
        if not self._held:
            return
        self._held = False
        _Deferral.depth -= 1
        if _Deferral.depth == 0 and _Deferral.pending is not None:
            signum, _Deferral.pending = _Deferral.pending, None
            _raise_for(signum)


@contextlib.contextmanager
def signals_as_exceptions() -> Iterator[None]:
    """Within the block, SIGTERM, SIGHUP and SIGQUIT raise :class:`EndedBySignal`.

    SIGINT raises KeyboardInterrupt, as Python's own handler does; both wait while a
    :class:`SignalsHeld` is on.

    Only the main thread can install handlers; elsewhere the block runs unchanged.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {signum: signal.signal(signum, _raise)
                for signum in (signal.SIGINT, *ENDING_SIGNALS)}
    _Deferral.raised = None
    try:
        yield
    except BaseException:
        _Deferral.raised = None  # it left the block: seen
        raise
    else:
        lost, _Deferral.raised = _Deferral.raised, None
        if lost is not None:  # a library swallowed it: the run still ends by it
            _raise_for(lost)
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
