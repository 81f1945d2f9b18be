"""What to drive: timed steps of twists and arm targets, asked for by time.

A :class:`Plan` is the drive loop's source for a script or a one-shot command. Arm
assignments are cumulative: a joint keeps the last target it was given, and joints never
named hold the position the firmware reported when the run began.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass


@dataclass(frozen=True)
class Setpoint:
    """What the robot should do now.

    Attributes:
        linear_m_s: Forward speed [m/s].
        angular_rad_s: Yaw rate, counter-clockwise positive [rad/s].
        arm: Arm targets given so far, ``(joint, rad)`` pairs; empty leaves the arm alone.
    """

    linear_m_s: float
    angular_rad_s: float
    arm: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class Step:
    """One timed step.

    Attributes:
        duration_s: How long it lasts [s].
        linear_m_s: Forward speed [m/s].
        angular_rad_s: Yaw rate [rad/s].
        arm: Arm targets that start with this step, ``(joint, rad)`` pairs.
        line: Line of the script it came from (0 for a one-shot command).
        arm_line: Line of the first ``arm`` line among ``arm`` (0 when none).
    """

    duration_s: float
    linear_m_s: float
    angular_rad_s: float
    arm: tuple[tuple[str, float], ...] = ()
    line: int = 0
    arm_line: int = 0


class Plan:
    """Timed steps in order; ``setpoint(t)`` is None once they are over."""

    fds: tuple[int, ...] = ()

    def __init__(self, steps: list[Step]) -> None:
        self.steps = steps
        self.duration_s = sum(step.duration_s for step in steps)
        # each step's end and the arm targets set so far, once: a tick looks its step up
        # (a 16,000-line script was rescanned from its start at every tick)
        self._ends: list[float] = []
        self._arms: list[tuple[tuple[str, float], ...]] = []
        end, arm = 0.0, dict[str, float]()
        for step in steps:
            arm.update(step.arm)
            end += step.duration_s
            self._ends.append(end)
            self._arms.append(tuple(arm.items()))

    def setpoint(self, t_s: float) -> Setpoint | None:
        """The setpoint ``t_s`` seconds after the start, or None when the plan is over."""
        index = bisect.bisect_right(self._ends, t_s)
        if index >= len(self.steps):
            return None
        step = self.steps[index]
        return Setpoint(step.linear_m_s, step.angular_rad_s, self._arms[index])

    def poll(self) -> None:
        """Nothing to read: a plan has no input (it watches no file descriptors)."""
