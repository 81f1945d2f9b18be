"""Serve an emulated motor controller on a pseudo-terminal.

The emulator owns the master side of a pty; a host opens the slave (``/dev/pts/N``) exactly
as it opens ``/dev/ttyUSB0``. The emulator keeps its own handle on the slave, so a host may
close the port and open it again (a reconnect) without the pty going away. A board that
resets on open (``--boot-s``) is told of every open the moment it is seen, before the bytes
that follow it are handed on (:mod:`~servicebot_cli.drive.emulator.port_opens`).
"""

from __future__ import annotations

import contextlib
import os
import pty
import select
import time
import tty
from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.drive.emulator.board import Board
from servicebot_cli.drive.emulator.firmware import State
from servicebot_cli.drive.emulator.port_opens import PortOpens
from servicebot_cli.drive.emulator.wire import FaultInjector, PacedQueue, byte_time_s

PTS_DIR = "/dev/pts/"
_IDLE_S = 0.02  # longest sleep: the watchdog and SIGINT are seen at least this often
_STATE_PERIOD_S = 0.1
_REPORT_PERIOD_S = 1.0


class EmulatorError(ServicebotError):
    """The emulator cannot be set up as asked (exit 2)."""


class PtyEmulator:
    """A board on a pty, with baud-rate pacing and injected faults.

    Args:
        board: What answers, and whether a host opening the port resets it.
        injector: Drops and corrupts bytes both ways.
        baud: The wire speed paced when ``pace`` is set.
        pace: Release bytes no faster than ``baud`` allows, each way.
        log: Where status lines go (stderr in the command).
        clock: Monotonic time [s]; the state's times are on this clock.
    """

    def __init__(self, board: Board, injector: FaultInjector, *, baud: int, pace: bool,
                 log: Callable[[str], None], clock: Callable[[], float] = time.monotonic) -> None:
        self.board = board
        self.injector = injector
        self.faults = injector.faults
        self.baud, self.pace = baud, pace
        self.log, self.clock = log, clock
        pacing = byte_time_s(baud) if pace else 0.0
        self._rx, self._tx = PacedQueue(pacing), PacedQueue(pacing)
        self.master = self.slave = -1
        self.path = ""
        self.link: Path | None = None
        self.muted = self._mute_done = self._booting = self._stall_told = False
        self.tx_overflow = 0
        self._opens: PortOpens | None = None
        self._start_s = clock()
        self._seen = asdict(board.model.counters)
        self._next_report_s = self._start_s + _REPORT_PERIOD_S
        self._report_frames = 0

    def open(self, link: Path | None = None) -> str:
        """Create the pty (and a symlink ``link`` to it); return the path hosts open.

        Raises:
            EmulatorError: ``link`` is a path that is not ours to replace (checked before the
                pty is made), the link cannot be made, or the opens of a board that resets
                on open cannot be watched.
        """
        if link is not None:
            problem = link_problem(link)
            if problem:
                raise EmulatorError(f"--link {link}: {problem}")
        self.master, self.slave = pty.openpty()
        tty.setraw(self.slave)  # no echo, no line editing until a host configures it
        os.set_blocking(self.master, False)
        self.path = os.ttyname(self.slave)
        if self.board.resets_on_open:
            try:
                self._opens = PortOpens(self.path)
            except OSError as exc:
                raise EmulatorError(f"--boot-s: cannot see the port open ({exc}); a board "
                                    "that resets on open needs Linux") from None
        if link is not None:
            self._symlink(link)
        return str(link) if link is not None else self.path

    def _symlink(self, link: Path) -> None:
        """Point ``link`` at the device, replacing a stale link atomically."""
        temporary = link.with_name(f".{link.name}.{os.getpid()}")
        try:
            with contextlib.suppress(FileNotFoundError):
                temporary.unlink()
            os.symlink(self.path, temporary)
            os.replace(temporary, link)
        except OSError as exc:
            raise EmulatorError(f"--link {link}: cannot make the link: "
                                f"{exc.strerror or exc}") from None
        self.link = link

    def close(self) -> None:
        """Close the pty (hosts see the port vanish) and remove the symlink if it is ours."""
        for fd in (self.master, self.slave):
            if fd >= 0:
                with contextlib.suppress(OSError):
                    os.close(fd)
        self.master = self.slave = -1
        if self._opens is not None:
            self._opens.close()
        if self.link is not None:
            with contextlib.suppress(OSError):
                if os.readlink(self.link) == self.path:
                    self.link.unlink()

    def serve(self, should_stop: Callable[[], bool],
              on_state: Callable[[State], None] | None = None) -> str:
        """Answer until ``should_stop()``; return ``"stopped"`` or ``"died"`` (--die-after-s)."""
        next_state_s = self._start_s
        while not should_stop():
            now = self.clock()
            uptime = now - self._start_s
            if self.faults.die_after_s is not None and uptime >= self.faults.die_after_s:
                self.log(f"dying now, {uptime:.1f} s after start (--die-after-s)")
                return "died"
            if (not self._mute_done and self.faults.mute_after_s is not None
                    and uptime >= self.faults.mute_after_s):
                self.muted = self._mute_done = True
                self.log(f"muted: no more answers, {uptime:.1f} s after start (--mute-after-s)")
            if (not self._stall_told and self.faults.stall_after_s is not None
                    and uptime >= self.faults.stall_after_s):
                self._stall_told = True
                self.log(f"stalled: the wheels stop turning, {uptime:.1f} s after start; "
                         "commands still answered (--stall-after-s)")
            self._pump(now)
            self._report(now)
            if on_state is not None and now >= next_state_s:
                on_state(self.state())
                next_state_s = now + _STATE_PERIOD_S
            watched = [self._opens.fileno()] if self._opens is not None else []
            select.select([self.master, *watched], [], [], self._timeout(now))
            data = self._read()
            self._watch_opens(self.clock())  # an open comes before the bytes sent after it
            if data and not self.muted:
                self._rx.push(self.injector.apply(data), self.clock())
        return "stopped"

    def _read(self) -> bytes:
        try:
            return os.read(self.master, 4096)
        except (BlockingIOError, InterruptedError):
            return b""
        except OSError:  # EIO: no host has the slave open
            time.sleep(_IDLE_S)
            return b""

    def _watch_opens(self, now: float) -> None:
        """A host opened the port: the board resets, forgets, and boots (deaf meanwhile)."""
        opens = self._opens.take() if self._opens is not None else 0
        if not opens:
            return
        for _ in range(opens):  # opens this close together are resets in a row
            self.board.reset(now)
        pacing = byte_time_s(self.baud) if self.pace else 0.0
        self._rx, self._tx = PacedQueue(pacing), PacedQueue(pacing)  # a reset empties the UART
        self.muted = False  # a hung firmware runs again after a reset
        self._seen = asdict(self.board.model.counters)
        self._report_frames = 0
        self._booting = True
        self.log(f"port opened: the board resets and boots for {self.board.boot_s:g} s "
                 f"(reset {self.board.resets}; what it receives meanwhile is lost)")

    def _pump(self, now: float) -> None:
        received = self._rx.pop(now)
        if received:
            replies = self.board.receive(received, now)
            if not self.muted:
                self._tx.push(self.injector.apply(replies), now + self.faults.latency_s)
        self.board.model.advance(now)
        outgoing = self._tx.pop(now)
        if outgoing:
            try:
                os.write(self.master, outgoing)
            except (BlockingIOError, OSError):
                self.tx_overflow += len(outgoing)  # nobody reads: a UART drops them too

    def _timeout(self, now: float) -> float:
        due = [t for t in (self._rx.next_due_s(), self._tx.next_due_s()) if t is not None]
        return max(0.0, min([now + _IDLE_S, *due]) - now)

    def _report(self, now: float) -> None:
        if self._booting and not self.board.booting(now):
            self._booting = False
            self.log("booted: the firmware runs, muted: it answers nothing (--mute-after-s)"
                     if self.muted else "booted: the firmware answers")
        counters = asdict(self.board.model.counters)
        if counters["watchdog_trips"] > self._seen["watchdog_trips"]:
            timeout_ms = round(self.board.model.watchdog_s * 1000)
            self.log(f"watchdog: no motion command for {timeout_ms} ms; motors stopped")
        if counters["stops"] > self._seen["stops"]:
            self.log("STOP received; motors stopped")
        if now >= self._next_report_s:
            frames = counters["frames"] - self._report_frames
            if frames:
                wheels = " ".join(f"{v:+.3f}" for v in self.board.model.wheel_velocity_rad_s)
                self.log(f"{frames} frames in the last second; wheels [{wheels}] rad/s; "
                         f"{_counts(self.board.state())}")
            self._report_frames = counters["frames"]
            self._next_report_s = now + _REPORT_PERIOD_S
        self._seen = counters

    def state(self) -> State:
        """Everything a test or a user may want to know, JSON-ready."""
        model = self.board.model
        motors = model.motors
        return {
            "protocol": self.board.protocol,
            "port": self.path,
            "clock_s": model.now_s,
            "uptime_s": model.now_s - self._start_s,
            "watchdog_s": model.watchdog_s,
            "moving": model.moving,
            "muted": self.muted,
            **({"board": self.board.boot_state(model.now_s)} if self.board.resets_on_open
               else {}),
            "wheels": [
                {"joint": name, "position_rad": p, "velocity_rad_s": v}
                for name, p, v in zip(motors.wheel_joints, model.wheel_position_rad,
                                      model.wheel_velocity_rad_s, strict=True)
            ],
            "arm": [
                {"joint": name, "position_rad": p, "target_rad": t}
                for name, p, t in zip(motors.arm_joints, model.arm_position_rad,
                                      model.arm_target_rad, strict=True)
            ],
            "counters": {**asdict(model.counters), **self.board.state()},
            "wire": {"dropped": self.injector.dropped, "corrupted": self.injector.corrupted,
                     "tx_overflow": self.tx_overflow,
                     "paced_baud": self.baud if self.pace else None},
        }


def link_problem(link: Path) -> str:
    """Why ``link`` may not become the emulator's symlink; empty when it may.

    A free path may, and so may a stale link an emulator left behind: a symlink to a
    pseudo-terminal that no longer exists (its emulator was killed), or to one made after the
    link, which another program got with the dead emulator's number. Anything else is not
    ours: a file, a directory, another symlink, or a link to the pty it was made for, in use.
    """
    if not os.path.lexists(link):
        return ""
    if os.path.islink(link):
        target = os.readlink(link)
        if target.startswith(PTS_DIR) and not _made_before(target, link):
            return ""
        if target.startswith(PTS_DIR):
            return (f"links to {target}, which is in use (another emulator?); stop that "
                    f"emulator or give another path")
        return f"is a symlink to {target}, not an emulator's device; give another path"
    if os.path.isdir(link):
        return "is a directory; give the path of a link to make"
    return "already exists and is not an emulator's link; give another path (it is left as is)"


def _made_before(device: str, link: Path) -> bool:
    """Whether the pseudo-terminal ``device`` exists and was made before ``link`` was.

    An emulator makes its pty, then the link. A pty whose inode is newer than the link
    (its change time is set when the kernel makes it) is another's that got a freed number.
    """
    try:
        made_ns, linked_ns = os.stat(device).st_ctime_ns, os.lstat(link).st_mtime_ns
    except OSError:  # no such pty (or the link went meanwhile): nothing in use
        return False
    return made_ns <= linked_ns


def _counts(state: State) -> str:
    parts = []
    for key, value in state.items():
        if isinstance(value, dict):
            value = " ".join(f"{k} {v}" for k, v in value.items())
        parts.append(f"{key.replace('_', ' ')} {value}")
    return ", ".join(parts)
