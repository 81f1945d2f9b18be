"""Where a plan takes the arm: each joint toward its target at its velocity limit.

``drive`` does not interpolate arm motion: it sends each new set of targets once (SET_ARM),
and the firmware moves every joint toward its target no faster than the joint's URDF
velocity limit (docs/serial-protocol.md; the emulator moves each at exactly that limit).
So between two targets the arm does not follow the straight line in joint space: all joints
start together, each at its own speed, and each stops when it arrives. The path is a
polyline whose corners are those arrival times. A new target before the arm arrived starts a
new polyline from where it is. Each way is taken whole, to its target, even when the plan
moves on or ends (the stop holds the arm) before the arm arrives: when the arm stops, or
turns, depends on ticks and replies, not only on the plan. A joint without a velocity limit
jumps at once (that is the first corner). A firmware that moves the joints otherwise (all
arriving together, on the straight line) takes another way, which this does not check.
Pure: steps, a start and the motors in; polylines out.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Step

ArmValues = tuple[float, ...]
"""One value per arm joint, in the motors' order [rad, or m]."""


@dataclass(frozen=True)
class ArmLeg:
    """The arm's way to one target.

    Attributes:
        step: The step that sets the target.
        target_rad: The arm's targets from that step on.
        path_rad: The way from where the arm is when the step begins to the target, whole
            (even when the plan moves on or ends before the arm arrives): a polyline whose
            first corner is where the arm is.
    """

    step: Step
    target_rad: ArmValues
    path_rad: tuple[ArmValues, ...]


def arm_legs(steps: Sequence[Step], start_rad: ArmValues, motors: MotorMap) -> Iterator[ArmLeg]:
    """The arm's way to each target of ``steps``, from ``start_rad``, in order.

    Raises:
        JointNotFound, OutOfLimits: A target the motors do not have (checked when parsed).
    """
    here, target = start_rad, start_rad
    speeds = motors.arm_max_rad_s
    for step in steps:
        if step.arm:
            target = motors.arm_targets(dict(step.arm), target)
            yield ArmLeg(step, target, polyline(here, target, speeds))
        here = _at(here, target, speeds, step.duration_s)


def polyline(start_rad: ArmValues, target_rad: ArmValues,
             speeds_rad_s: Sequence[float]) -> tuple[ArmValues, ...]:
    """The corners of the way from ``start_rad`` to ``target_rad``, both included.

    Joint :math:`i` is at :math:`s_i + \\operatorname{sign}(d_i) \\min(|d_i|, v_i t)` at
    time :math:`t`, with :math:`d = target - start`; the corners are the times joints arrive.
    """
    arrivals = sorted({_arrival_s(s, t, v) for s, t, v in
                       zip(start_rad, target_rad, speeds_rad_s, strict=True) if s != t})
    corners = [start_rad]
    for t_s in arrivals:
        here = _at(start_rad, target_rad, speeds_rad_s, t_s)
        if here != corners[-1]:
            corners.append(here)
    return tuple(corners)


def _arrival_s(start: float, target: float, speed: float) -> float:
    return 0.0 if math.isinf(speed) else abs(target - start) / speed


def _at(start_rad: ArmValues, target_rad: ArmValues, speeds_rad_s: Sequence[float],
        t_s: float) -> ArmValues:
    """Where the arm is ``t_s`` after it set off from ``start_rad``."""
    return tuple(
        t if _arrival_s(s, t, v) <= t_s else s + math.copysign(v * t_s, t - s)
        for s, t, v in zip(start_rad, target_rad, speeds_rad_s, strict=True))
