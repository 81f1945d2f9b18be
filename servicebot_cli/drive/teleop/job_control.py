"""Ctrl-Z in teleop: stop the wheels, give the terminal back, suspend; resume at standstill.

The default action of SIGTSTP stops the process at once, with the wheels turning until the
firmware's watchdog notices. Here SIGTSTP only raises a flag: the drive loop sees it within
one command period, stops the motors, and calls :meth:`JobControl.suspend`, which restores
the terminal and stops the process with SIGSTOP. After ``fg`` (SIGCONT) the terminal goes
back to cbreak mode, the twist is zero and the loop restarts its link timers, so the pause
is not taken for a lost link. A SIGCONT after a SIGSTOP from elsewhere is handled alike.
"""

from __future__ import annotations

import contextlib
import os
import signal
import termios
import tty
from collections.abc import Iterator
from types import FrameType
from typing import TextIO

from servicebot_cli.drive.session.signals import SignalHandler
from servicebot_cli.drive.teleop.keyboard import Teleop


class JobControl:
    """Suspend and resume requests for the drive loop (a :class:`~..contracts.Suspender`).

    Args:
        fd: The keyboard's terminal.
        teleop: Zeroed on every resume.
        status: Where the status line is; a newline ends it before the shell prints.
    """

    def __init__(self, fd: int, teleop: Teleop, status: TextIO) -> None:
        self.fd, self.teleop, self.status = fd, teleop, status
        self.requested = False
        self.resumed = False
        self.suspensions = 0

    def suspend(self) -> None:
        """Restore the terminal and stop this process; return in cbreak mode once continued."""
        self.teleop.zero()
        with contextlib.suppress(OSError):
            self.status.write("\n")
            self.status.flush()
        with _cooked(self.fd):
            self.suspensions += 1
            os.kill(os.getpid(), signal.SIGSTOP)
        self.teleop.zero()

    def on_tstp(self, signum: int, frame: FrameType | None) -> None:
        """SIGTSTP (Ctrl-Z): ask the loop to suspend once the motors are stopped."""
        self.requested = True

    def on_cont(self, signum: int, frame: FrameType | None) -> None:
        """SIGCONT: the process went on; the loop restarts its timers from standstill."""
        self.teleop.zero()
        self.resumed = True


@contextlib.contextmanager
def job_control(fd: int, teleop: Teleop, status: TextIO) -> Iterator[JobControl]:
    """Handle SIGTSTP and SIGCONT for teleop; the previous handlers come back on exit."""
    control = JobControl(fd, teleop, status)
    previous: dict[int, SignalHandler] = {
        signal.SIGTSTP: signal.signal(signal.SIGTSTP, control.on_tstp),
        signal.SIGCONT: signal.signal(signal.SIGCONT, control.on_cont),
    }
    try:
        yield control
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


@contextlib.contextmanager
def _cooked(fd: int) -> Iterator[None]:
    """The terminal as it was before cbreak while suspended; cbreak again afterwards."""
    try:
        cbreak = termios.tcgetattr(fd)
        cooked = list(cbreak)
        cooked[3] |= termios.ICANON | termios.ECHO  # lflags: lines and echo for the shell
        termios.tcsetattr(fd, termios.TCSADRAIN, cooked)
    except (termios.error, OSError):
        cbreak = None
    try:
        yield
    finally:
        if cbreak is not None:
            with contextlib.suppress(termios.error, OSError):
                tty.setcbreak(fd, termios.TCSADRAIN)  # keep keys typed after fg
