"""Teleop on the user's terminal: keys from stdin in cbreak mode, a status line on stderr.

The terminal is restored on every way out, including a hang-up (SIGHUP), when writing to it
or restoring it may fail: the motors were stopped before, so nothing more is owed to it.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TextIO

from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.session.loop import LinkStatus
from servicebot_cli.drive.teleop.keyboard import Teleop, cbreak_terminal, status_line


class NoTerminal(ServicebotError):
    """Teleop asked for without a terminal on stdin."""

    exit_code = ExitCode.USAGE


@dataclass(frozen=True)
class Terminal:
    """Where teleop reads keys and shows its status line.

    Attributes:
        keys: The keyboard (stdin).
        status: Where the one-line status goes (stderr); shown only on a terminal.
    """

    keys: TextIO
    status: TextIO


@contextlib.contextmanager
def keyboard_session(terminal: Terminal, motors: MotorMap
                     ) -> Iterator[tuple[Teleop, Callable[[LinkStatus], None]]]:
    """``(source, on_tick)``: the keyboard in cbreak mode and its status line.

    Raises:
        NoTerminal: No terminal on stdin.
    """
    if not terminal.keys.isatty():
        raise NoTerminal("teleop needs a terminal on stdin; give --script FILE (or - for "
                         "stdin) or --linear/--angular --duration-s")
    fd = terminal.keys.fileno()
    teleop = Teleop(fd, motors.geometry.max_linear_m_s, motors.geometry.max_angular_rad_s)
    out = terminal.status

    def on_tick(status: LinkStatus) -> None:
        if out.isatty():  # one line that rewrites itself: never wider than the terminal
            width = _columns(out.fileno()) - 1
            out.write(f"\r\x1b[K{status_line(status, teleop, motors.wheel_sides, width)}")
            out.flush()

    with cbreak_terminal(fd):
        try:
            yield teleop, on_tick
        finally:
            with contextlib.suppress(OSError):
                out.write("\n")


def _columns(fd: int) -> int:
    """Width of the terminal on ``fd`` (80 when it does not say)."""
    try:
        return os.get_terminal_size(fd).columns or 80
    except OSError:
        return 80
