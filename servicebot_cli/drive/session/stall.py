"""Wheels commanded to turn whose encoders do not move: a stop, not a run that "completed".

With an encoder cable pulled or the motor power off, ROSArduinoBridge's PID sees no ticks and
raises the PWM towards full power, while the host streams on and, at the end, reads counts
that never changed as a confirmed stop. A wheel whose measured angle has not changed at all
while it was commanded to turn for :data:`WINDOW_S`, through at least :data:`COUNTS` of its
encoder's counts (and :data:`LEAST_TRAVEL_RAD`), is stalled; the loop then stops the motors
and says which wheel. Pure.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from servicebot_cli.common.errors import LinkError

WINDOW_S = 1.0
"""How long a wheel must be commanded and still before it counts as stalled [s]."""
COUNTS = 8
"""How many encoder counts the commands must have turned it through meanwhile."""
LEAST_TRAVEL_RAD = 0.05
"""And how far, at least, for telemetry in continuous angles [rad]."""
_TURNING_RAD_S = 1e-6


class WheelsStill(LinkError):
    """Wheels commanded to turn whose encoders do not count (exit 4); the motors are stopped."""


@dataclass
class _Streak:
    since_s: float
    position_rad: float
    commanded_rad: float = 0.0


class StallWatch:
    """Watches each wheel's commanded speed against its measured angle, reading by reading."""

    def __init__(self, wheel_names: Sequence[str], count_rad: float = 0.0) -> None:
        self.names = tuple(wheel_names)
        self.least_travel_rad = max(LEAST_TRAVEL_RAD, COUNTS * count_rad)
        """Commanded travel that no encoder misses [rad]."""
        self._streaks: list[_Streak | None] = [None] * len(self.names)
        self._last_s: float | None = None
        self.stalled: str | None = None
        """Why the wheels count as stalled (a message), once they do."""
        self.moved = [False] * len(self.names)
        """Whether each wheel's measured angle ever changed."""
        self._first: list[float | None] = [None] * len(self.names)

    def observe(self, t_s: float, positions_rad: Sequence[float],
                commanded_rad_s: Sequence[float]) -> None:
        """A reading at ``t_s``: each wheel's angle, and the speed it was commanded then."""
        dt = 0.0 if self._last_s is None else max(0.0, t_s - self._last_s)
        self._last_s = t_s
        for i, (position, speed) in enumerate(zip(positions_rad, commanded_rad_s,
                                                  strict=False)):
            first = self._first[i]
            if first is None:
                self._first[i] = position
            elif position != first:
                self.moved[i] = True
            streak = self._streaks[i]
            if abs(speed) <= _TURNING_RAD_S or (streak is not None
                                                 and position != streak.position_rad):
                self._streaks[i] = None
                streak = None
            if abs(speed) <= _TURNING_RAD_S:
                continue
            if streak is None:
                self._streaks[i] = _Streak(t_s, position)
                continue
            streak.commanded_rad += abs(speed) * dt
            if self.stalled is None and t_s - streak.since_s >= WINDOW_S \
                    and streak.commanded_rad >= self.least_travel_rad:
                self.stalled = (f"wheel '{self.names[i]}' was commanded to turn "
                                f"{streak.commanded_rad:.2g} rad over {t_s - streak.since_s:.1f} s "
                                "and its encoder did not count once: an encoder cable pulled, "
                                "the motor power off or the wheel blocked (ROSArduinoBridge's PID "
                                "then drives the motor towards full power)")

    def restart(self) -> None:
        """A gap in the readings (a reconnect, a suspension): no streak spans it.

        The motors were at zero meanwhile (stopped, or by the firmware's watchdog), so that
        time is no time commanded; and a board that reset on reconnect counts from zero again,
        so its angles are no continuation of the old ones. What moved stays moved.
        """
        self._streaks = [None] * len(self.names)
        self._first = [None] * len(self.names)
        self._last_s = None

    def never_moved(self) -> bool:
        """Whether no wheel's measured angle ever changed."""
        return not any(self.moved)
