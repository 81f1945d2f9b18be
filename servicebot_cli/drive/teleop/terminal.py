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
from servicebot_cli.drive.session.contracts import LinkStatus
from servicebot_cli.drive.teleop.job_control import JobControl, job_control
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


@dataclass(frozen=True)
class KeyboardSession:
    """Teleop on a terminal, ready for the drive loop.

    Attributes:
        teleop: The setpoint source.
        on_tick: Draws the status line.
        job_control: Ctrl-Z and SIGCONT handling.
    """

    teleop: Teleop
    on_tick: Callable[[LinkStatus], None]
    job_control: JobControl


@contextlib.contextmanager
def keyboard_session(terminal: Terminal, motors: MotorMap,
                     deadman_s: float | None = None) -> Iterator[KeyboardSession]:
    """The keyboard in cbreak mode, its status line and its job control.

    Raises:
        NoTerminal: No terminal on stdin.
    """
    if not terminal.keys.isatty():
        raise NoTerminal("teleop needs a terminal on stdin; give --script FILE (or - for "
                         "stdin) or --linear/--angular --duration-s")
    fd = terminal.keys.fileno()
    top_m_s = motors.max_wheel_rad_s * motors.wheel_radius_m
    teleop = Teleop(fd, top_m_s, 2.0 * top_m_s / motors.track_m, deadman_s=deadman_s)
    out = terminal.status

    def on_tick(status: LinkStatus) -> None:
        if out.isatty():  # one line that rewrites itself: never wider than the terminal
            width = min(79, _columns(out.fileno()) - 1)
            out.write(f"\r\x1b[K{status_line(status, motors, width)}")
            out.flush()

    with cbreak_terminal(fd), job_control(fd, teleop, out) as control:
        try:
            yield KeyboardSession(teleop, on_tick, control)
        finally:
            with contextlib.suppress(OSError):
                out.write("\n")


def _columns(fd: int) -> int:
    """Width of the terminal on ``fd`` (80 when it does not say)."""
    try:
        return os.get_terminal_size(fd).columns or 80
    except OSError:
        return 80
