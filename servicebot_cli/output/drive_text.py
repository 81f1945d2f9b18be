"""What ``drive`` and ``emulate`` print: status lines on stderr, results on stdout.

``drive``: the frames of a dry run (text or JSON), the summary of a run (JSON on stdout, or
one ``done:`` line on stderr), and every progress line prefixed ``drive:``. ``emulate``: the
device path on stdout (scripts read the first line), status lines with the time since start.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterator

import click

from servicebot_cli.common.jsonable import dumps
from servicebot_cli.drive.driving import Summary
from servicebot_cli.drive.dry_run import DryRun
from servicebot_cli.drive.emulator.session import EmulateResult
from servicebot_cli.drive.run import DriveResult


def drive_log(line: str) -> None:
    """One ``drive:`` line on stderr; on a terminal it first clears teleop's status line."""
    clear = "\r\x1b[K" if sys.stderr.isatty() else ""
    click.echo(f"{clear}drive: {line}", err=True)


def dry_run_lines(dry: DryRun) -> Iterator[str]:
    """Lines ``t_s  hex bytes  meaning``, one per frame, after a short header."""
    yield (f"# {dry.protocol} protocol, {dry.rate_hz:g} Hz, {dry.duration_s:g} s; the frames a "
           "run would send (no port opened)")
    if dry.has_arm:
        yield "# arm joints a plan does not name hold 0 rad here (a real run: where they are)"
    yield "# t_s  bytes  meaning"
    for frame in dry.frames:
        yield f"{frame.t_s:7.3f}  {frame.bytes_hex}  {frame.meaning}"


def done_line(summary: Summary) -> str:
    """The last line of a run that completed."""
    confirmed = " (the firmware confirmed)" if summary.stop_confirmed else ""
    return (f"done: {summary.commands} commands and {summary.replies} replies in "
            f"{summary.duration_s:.1f} s, {summary.errors} errors, {summary.reconnects} "
            f"reconnects; motors stopped{confirmed}")


def show_drive(result: DriveResult, fmt: str) -> None:
    """Print a dry run's frames, or a run's summary (JSON on stdout, text on stderr).

    A run that ended early still shows its JSON summary once the firmware had answered; the
    error line that follows is the caller's.
    """
    if isinstance(result, DryRun):
        if fmt == "json":
            click.echo(dumps(list(result.frames)), nl=False)
        else:
            for line in dry_run_lines(result):
                click.echo(line)
        return
    if result.summary is None:
        return
    if fmt == "json":
        click.echo(dumps(result.summary), nl=False)
    elif result.failure is None:
        drive_log(done_line(result.summary))


def emulate_log(clock: Callable[[], float] = time.monotonic) -> Callable[[str], None]:
    """A logger for ``emulate``: ``emulate   1.23s: line`` on stderr, timed from now."""
    start_s = clock()

    def log(line: str) -> None:
        click.echo(f"emulate {clock() - start_s:7.2f}s: {line}", err=True)

    return log


def announce_device(device: str) -> None:
    """The device hosts open, alone on stdout's first line, flushed at once."""
    click.echo(device)
    sys.stdout.flush()


def emulate_end_line(result: EmulateResult) -> str:
    """The last status line of an emulator."""
    return "port closed" if result.ending == "died" else "stopped; port closed"
