"""Keyboard teleoperation: keys step the twist, a status line shows the link.

Keys (arrows or WASD): forward / back change the forward speed by a tenth of its maximum,
left / right the turn rate; space or x stops; q, Esc or Ctrl-D quits (the motors stop).
The terminal is in cbreak mode (keys arrive at once, Ctrl-C still interrupts) and is
restored on every way out.
"""

from __future__ import annotations

import contextlib
import os
import termios
import tty
from collections.abc import Iterator

from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.session.loop import LinkStatus

STEPS = 10  # key presses from stop to full speed
HELP = "arrows/wasd drive, space stops, q quits"

_KEYS = {
    b"\x1b[A": "forward", b"w": "forward", b"\x1b[B": "back", b"s": "back",
    b"\x1b[D": "left", b"a": "left", b"\x1b[C": "right", b"d": "right",
    b" ": "stop", b"x": "stop", b"q": "quit", b"\x1b": "quit", b"\x04": "quit",
}


@contextlib.contextmanager
def cbreak_terminal(fd: int) -> Iterator[None]:
    """Put the terminal on ``fd`` in cbreak mode; restore its settings on exit.

    A terminal that hung up cannot be restored, and needs not be: that failure is ignored.
    """
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)
        yield
    finally:
        with contextlib.suppress(termios.error, OSError):
            termios.tcsetattr(fd, termios.TCSADRAIN, saved)


def parse_keys(data: bytes) -> list[str]:
    """Actions for the bytes read from the keyboard; unknown keys are ignored."""
    actions = []
    i = 0
    while i < len(data):
        for size in (3, 1):
            action = _KEYS.get(data[i:i + size])
            if action is not None and (size == 3 or data[i:i + 2] != b"\x1b["):
                actions.append(action)
                i += size
                break
        else:
            i += 1
    return actions


class Teleop:
    """A setpoint source driven by keys read from ``fd``.

    Args:
        fd: The terminal's file descriptor.
        max_linear_m_s: Forward speed at full stick [m/s].
        max_angular_rad_s: Turn rate at full stick [rad/s].
    """

    def __init__(self, fd: int, max_linear_m_s: float, max_angular_rad_s: float) -> None:
        self.fds: tuple[int, ...] = (fd,)
        self.linear_step = max_linear_m_s / STEPS
        self.angular_step = max_angular_rad_s / STEPS
        self.linear = 0  # in steps
        self.angular = 0
        self.done = False

    def poll(self) -> None:
        """Read and apply the keys that have arrived."""
        try:
            data = os.read(self.fds[0], 64)
        except (BlockingIOError, InterruptedError):
            return
        if not data:
            self.done = True  # end of input
        for action in parse_keys(data):
            self.apply(action)

    def apply(self, action: str) -> None:
        """Change the twist for one key action."""
        if action == "forward":
            self.linear = min(STEPS, self.linear + 1)
        elif action == "back":
            self.linear = max(-STEPS, self.linear - 1)
        elif action == "left":
            self.angular = min(STEPS, self.angular + 1)
        elif action == "right":
            self.angular = max(-STEPS, self.angular - 1)
        elif action == "stop":
            self.linear = self.angular = 0
        elif action == "quit":
            self.done = True

    def setpoint(self, t_s: float) -> Setpoint | None:
        """The twist the keys asked for, or None after quit."""
        if self.done:
            return None
        return Setpoint(self.linear * self.linear_step, self.angular * self.angular_step)


def status_line(status: LinkStatus, teleop: Teleop, sides: tuple[str, ...],
                width: int = 1000) -> str:
    """One line, at most ``width`` characters: twist, side speeds, link rate, errors, keys."""
    if status.reconnecting:
        link = "RECONNECTING (motors at zero)"
    else:
        rtt = f" rtt {status.rtt_s * 1000:.0f} ms" if status.rtt_s is not None else ""
        link = f"link {status.reply_rate_hz:4.1f} Hz{rtt}"
    commanded = _by_side(status.commanded_rad_s, sides)
    measured = (_by_side(status.reading.wheel_velocity_rad_s, sides)
                if status.reading is not None else "-")
    linear = teleop.linear * teleop.linear_step
    angular = teleop.angular * teleop.angular_step
    return (f"v {linear:+.3f} m/s w {angular:+.3f} rad/s | cmd {commanded} | "
            f"meas {measured} rad/s | {link} | errors {status.errors} | {HELP}")[:width]


def _by_side(values: tuple[float, ...], sides: tuple[str, ...]) -> str:
    left = [v for v, s in zip(values, sides, strict=True) if s == "left"]
    right = [v for v, s in zip(values, sides, strict=True) if s == "right"]
    return f"L{sum(left) / len(left):+.3f} R{sum(right) / len(right):+.3f}"
