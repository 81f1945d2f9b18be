"""SB701's Pinocchio model built by a forked process while one file's other rules run.

Importing Pinocchio is a quarter of a one-file check from a cold process. On a machine where
the process may run on a second core, a child forked once the file is read builds the model
(only Pinocchio's verdict comes back: built, or the error line) while the parent reads the
meshes. The parent uses the verdict only where a serial run would build the model (no error
found before); otherwise it stops the child. A child that ends without a verdict (killed, a
crash in a library) makes the parent build the model itself, as a serial run does.
"""

from __future__ import annotations

import os
import signal
import sys
import threading

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.signals import ENDING_SIGNALS, SignalsHeld

_BUILT = b"built"
_REFUSED = b"refused:"


def worth_forking(cores: int) -> bool:
    """A child would save time, and fork safely.

    A second core, fork available, Pinocchio not yet imported, and no other Python thread
    (whose locks the child would copy, perhaps held).
    """
    return (cores >= 2 and hasattr(os, "fork") and "pinocchio" not in sys.modules
            and threading.active_count() == 1)


class ModelAhead:
    """A child building the fixed-base model of one URDF; ask :meth:`verdict` or :meth:`stop`."""

    def __init__(self, pid: int, reader: int) -> None:
        self._pid, self._reader = pid, reader

    @classmethod
    def start(cls, xml_text: str, display: str) -> ModelAhead | None:
        """Fork the child building ``xml_text``'s model; None when the fork fails."""
        reader, writer = os.pipe()
        held = SignalsHeld()  # no signal between the fork and the parent knowing the child
        ahead = None
        try:
            try:
                pid = os.fork()
            except OSError:
                os.close(reader)
                os.close(writer)
                return None
            if pid == 0:  # the child: never returns into the parent's code
                _child(xml_text, display, reader, writer)
            os.close(writer)
            ahead = cls(pid, reader)
        finally:
            try:
                held.release()  # raises a signal that came meanwhile
            except BaseException:
                if ahead is not None:
                    ahead.stop()
                raise
        return ahead

    def verdict(self) -> str | None:
        """None when Pinocchio built the model, else its error line (the ``DescriptionError``).

        Raises:
            ChildProcessError: The child ended without a verdict; build in this process.
        """
        chunks = []
        try:
            while chunk := os.read(self._reader, 65536):
                chunks.append(chunk)
        finally:
            self._close()
        answer = b"".join(chunks)
        if answer == _BUILT:
            return None
        if answer.startswith(_REFUSED):
            return answer[len(_REFUSED):].decode("utf-8", "replace")
        raise ChildProcessError("the model's process ended without a verdict")

    def stop(self) -> None:
        """End the child without waiting for its verdict (the model is not needed)."""
        self._close()

    def _close(self) -> None:
        """Close the pipe, end the child and reap it.

        Not reaped yet, the child's pid is still its own to kill; no signal ending the run
        then waits for a model being built.
        """
        if self._reader < 0:
            return
        os.close(self._reader)
        self._reader = -1
        try:
            os.kill(self._pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        try:
            os.waitpid(self._pid, 0)
        except ChildProcessError:  # SIGCHLD ignored: the system reaped it
            pass


def _child(xml_text: str, display: str, reader: int, writer: int) -> None:  # pragma: no cover
    """Build the model, write the verdict, exit: no clean-up of the parent's runs here."""
    code = 1
    try:
        os.close(reader)
        signal.signal(signal.SIGINT, signal.SIG_DFL)  # Ctrl-C ends it with the parent
        for ending in ENDING_SIGNALS:  # not the parent's handlers, which unwind its stack
            signal.signal(ending, signal.SIG_DFL)
        from servicebot_cli.description.model import build_model

        try:
            build_model(xml_text, display)
            answer = _BUILT
        except DescriptionError as exc:
            answer = _REFUSED + str(exc).encode("utf-8", "replace")
        view = memoryview(answer)
        while view:
            view = view[os.write(writer, view):]
        code = 0
    finally:
        os._exit(code)
