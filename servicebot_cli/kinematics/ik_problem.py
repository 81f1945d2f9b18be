"""What every solve of one ``ik`` command shares: the robot, frame, start and settings.

The command (or batch mode) fills an :class:`IkProblem` from its options;
:class:`~servicebot_cli.kinematics.ik_session.IkSession` builds the solver from it. No click.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from servicebot_cli.description.loader import RobotSource
from servicebot_cli.kinematics.inverse import IkSettings


@dataclass(frozen=True)
class CollisionOptions:
    """Which answers count as collisions.

    Attributes:
        check: Refuse answers whose links intersect each other or the floor.
        srdf: An SRDF whose ``<disable_collisions>`` pairs are not checked; None: none.
    """

    check: bool = True
    srdf: str | None = None


@dataclass(frozen=True)
class IkProblem:
    """What every solve of one command shares.

    Attributes:
        robot: The description to load.
        frame: The frame to move; None: the arm's tool frame.
        start: ``(name, value)`` pairs to start from, in the user's units; other joints
            start at zero, or their nearest limit.
        seed: Seed of the random restarts; None: a fresh one each run.
        with_base: Also move a planar mobile base.
        settings: Tolerances and effort.
        deg: Angles in degrees, in and out.
        clamp: Clamp start values outside their limits instead of refusing them.
        collisions: Which answers count as collisions.
        timeout_s: Seconds a solve may search before it returns its best try; None: until
            its attempts are made.
        relative_to: The link targets are given in, where it stands at the start
            configuration; None: the root link.
    """

    robot: RobotSource
    frame: str | None = None
    start: tuple[tuple[str, float], ...] = ()
    seed: int | None = None
    with_base: bool = False
    settings: IkSettings = field(default_factory=IkSettings)
    deg: bool = False
    clamp: bool = False
    collisions: CollisionOptions = field(default_factory=CollisionOptions)
    timeout_s: float | None = None
    relative_to: str | None = None
