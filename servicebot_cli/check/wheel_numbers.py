"""How far a drive's wheel radius or separation may be from what the URDF's wheels imply.

One measure for a diff_drive_controller's parameters (SB603, SB604) and a Gazebo drive
plugin's (SB516): within 1 % the same wheels; up to 10 %, odometry calibrated to the floor
(a warning); on a base with two or more wheels a side, which skid when it turns, a wider
track up to twice the wheels' is its effective one (a warning); else an error. Pure.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Severity

if TYPE_CHECKING:
    from servicebot_cli.kinematics.drive_geometry import DriveGeometry
    from servicebot_cli.kinematics.wheel_joints import Wheel

TOLERANCE = 0.01
"""Relative difference allowed between a drive's and the URDF's wheel numbers."""
CALIBRATED = 0.10
"""Within this, a wheel value off the URDF's may be odometry calibrated to the floor: a warning."""
SKID_TRACK = 2.0
"""A skid-steer base's effective track may be up to this times its wheels' (a warning)."""


@dataclass(frozen=True)
class Mismatch:
    """A wheel number off the URDF's: why it may be on purpose, and the severity.

    Attributes:
        purpose: `` (a calibration ...)`` or `` (a skid-steer ...)``, or empty.
        severity: WARNING where it may be on purpose; None: the rule's own (an error).
    """

    purpose: str
    severity: Severity | None


def mismatch(values: Sequence[float], expected: float, skid: bool = False) -> Mismatch | None:
    """None when one of ``values`` (as written, and multiplied) is the URDF's ``expected``.

    ``skid``: the robot has two or more wheels a side.
    """
    off = min(abs(value - expected) for value in values)
    if off <= TOLERANCE * abs(expected):
        return None
    # A few per cent is how teams calibrate odometry to the floor (limo's 0.172 m on its
    # wheels' 0.175 m); past that, the wrong wheels or the wrong unit.
    if off <= CALIBRATED * abs(expected):
        return Mismatch(" (a calibration to the floor, if on purpose)", Severity.WARNING)
    if skid and expected < max(values) <= SKID_TRACK * expected:
        return Mismatch(" (a skid-steer base's effective track, if on purpose)",
                        Severity.WARNING)
    return Mismatch("", None)


def track_m(wheels: Sequence[Wheel]) -> float | None:
    """The distance between the mean left and mean right wheel centres.

    None unless there are wheels on both sides.
    """
    sides = [[w.position_m[1] for w in wheels if w.side == side] for side in ("left", "right")]
    if not all(sides):
        return None
    return sum(sides[0]) / len(sides[0]) - sum(sides[1]) / len(sides[1])


def driven(geometry: DriveGeometry, named: Collection[str]
           ) -> tuple[float, float, tuple[Wheel, ...]]:
    """Radius and track of the wheels a drive names, and those wheels.

    A drive uses its numbers for its own wheels only: passive casters that also turn freely
    (ball casters off the centre line) are no part of them. Without a named wheel on each
    side, the URDF's drive wheels, all of them.
    """
    wheels = tuple(w for w in geometry.wheels if w.joint in named)
    track = track_m(wheels)
    if track is None:
        return geometry.wheel_radius_m, geometry.track_m, geometry.wheels
    return sum(w.radius_m for w in wheels) / len(wheels), track, wheels
