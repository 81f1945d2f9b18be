"""Keyboard teleoperation: keys step the twist, a status line shows the link.

Keys (arrows or WASD): forward / back change the forward speed by a tenth of its maximum,
left / right the turn rate; space or x stops; q, Esc or Ctrl-D quits (the motors stop).
With a dead-man (``--deadman-ms``), the wheels stop when no key arrives for that long.
The terminal is in cbreak mode (keys arrive at once, Ctrl-C still interrupts) and is
restored on every way out.
"""

from __future__ import annotations

import contextlib
import os
import termios
import time
import tty
from collections.abc import Callable, Iterator

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.session.contracts import LinkStatus
from servicebot_cli.kinematics.diff_drive import body_twist

STEPS = 10  # key presses from stop to full speed
HELP = "wasd/spc/q"

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
        deadman_s: With a value, the twist drops to zero when no key arrived for this long
            (hold a key: the keyboard's auto-repeat keeps it alive) [s].
        clock: Monotonic time [s].
    """

    def __init__(self, fd: int, max_linear_m_s: float, max_angular_rad_s: float, *,
                 deadman_s: float | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.fds: tuple[int, ...] = (fd,)
        self.linear_step = max_linear_m_s / STEPS
        self.angular_step = max_angular_rad_s / STEPS
        self.linear = 0  # in steps
        self.angular = 0
        self.done = False
        self.deadman_s = deadman_s
        self.clock = clock
        self.last_key_s = clock()
        self.deadman_trips = 0

    def poll(self) -> None:
        """Read and apply the keys that have arrived."""
        try:
            data = os.read(self.fds[0], 64)
        except (BlockingIOError, InterruptedError):
            return
        if not data:
            self.done = True  # end of input
        self.last_key_s = self.clock()
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
            self.zero()
        elif action == "quit":
            self.done = True

    def zero(self) -> None:
        """Back to standstill: the next key starts from one step."""
        self.linear = self.angular = 0

    def setpoint(self, t_s: float) -> Setpoint | None:
        """The twist the keys asked for (zero once the dead-man let go), or None after quit."""
        if self.done:
            return None
        if (self.deadman_s is not None and (self.linear or self.angular)
                and self.clock() - self.last_key_s > self.deadman_s):
            self.zero()
            self.deadman_trips += 1
        return Setpoint(self.linear * self.linear_step, self.angular * self.angular_step)


def status_line(status: LinkStatus, motors: MotorMap, width: int = 79) -> str:
    """One line of at most ``width`` (79) characters: what the wheels are really sent.

    ``v`` [m/s] and ``w`` [rad/s] are the twist of the commanded wheel speeds (after
    scaling to the limits and ramping; ``*`` when scaled); ``L`` and ``R`` are each side's
    commanded/measured speed [rad/s]; then the reply rate, round trip, link errors and keys.
    """
    left, right = _sides(status.commanded_rad_s, motors)
    linear, angular = body_twist(left, right, wheel_radius_m=motors.wheel_radius_m,
                                 track_m=motors.track_m)
    twist = f"v{linear:+.3f} w{angular:+.3f}{'*' if status.scaled else ' '}"
    measured = ("", "") if status.reading is None else tuple(
        f"{v:+.2f}" for v in _sides(status.reading.wheel_velocity_rad_s, motors))
    wheels = f"L{left:+.2f}/{measured[0] or '-'} R{right:+.2f}/{measured[1] or '-'}"
    if status.reconnecting:
        link = "RECONNECTING, motors at 0"
    else:
        rtt = "-" if status.rtt_s is None else f"{min(status.rtt_s * 1000, 9999):.0f}ms"
        link = f"{status.reply_rate_hz:.0f}Hz rtt {rtt} err {status.errors}"
    return f"{twist} {wheels}  {link}  {HELP}"[:width]


def _sides(values: tuple[float, ...], motors: MotorMap) -> tuple[float, float]:
    """Forward-positive mean speed of each side's wheels."""
    sums = {"left": [0.0, 0], "right": [0.0, 0]}
    for v, side, sign in zip(values, motors.wheel_sides, motors.wheel_axis_signs, strict=True):
        sums[side][0] += sign * v
        sums[side][1] += 1
    return (sums["left"][0] / max(1, sums["left"][1]),
            sums["right"][0] / max(1, sums["right"][1]))
