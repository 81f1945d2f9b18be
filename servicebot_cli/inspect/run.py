"""One run of ``servicebot inspect``: a request in, plain values out.

Click-free: the command turns its options into an :class:`InspectRequest` (or a
:class:`DiffRequest`), calls :func:`run`, and hands the result to ``output/`` to print,
draw or compare.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, overload

from servicebot_cli.common.errors import NameNotFound, OutOfLimits, ServicebotError
from servicebot_cli.inspect.diff import DiffResult, compare
from servicebot_cli.inspect.report import Inspection, Request, inspect_robot

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.inspect.picture import PosedRobot


class JointValueError(ServicebotError):
    """A joint value the user gave: an unknown or fixed joint, or a value out of its limits."""


@dataclass(frozen=True)
class InspectRequest:
    """What to show of one description.

    Attributes:
        source: The description.
        sections: Sections to compute, in display order; empty for none.
        joints: Joint values [rad or m], for the picture and the totals; others are zero.
        clamp: Clamp values into the joint limits instead of refusing them.
        picture: Also place the robot for a picture.
        controllers: The controllers YAML for the topics, or None to look for one.
    """

    source: RobotSource
    sections: tuple[str, ...] = ()
    joints: tuple[tuple[str, float], ...] = ()
    clamp: bool = False
    picture: bool = False
    controllers: Path | None = None


@dataclass(frozen=True)
class DiffRequest:
    """Compare description :attr:`a` with description :attr:`b`."""

    a: RobotSource
    b: RobotSource


@dataclass(frozen=True)
class Clamped:
    """A joint value that ``clamp`` moved into the limits.

    Attributes:
        joint: The joint.
        given: The value given [rad or m].
        used: The limit used instead [rad or m].
        limit: ``lower`` or ``upper``.
        unit: ``rad`` or ``m``.
        because: The follower (``<mimic>``) whose limits moved it; "" for its own.
    """

    joint: str
    given: float
    used: float
    limit: str
    unit: str
    because: str = ""


@dataclass(frozen=True)
class InspectResult:
    """What one inspection found.

    Attributes:
        inspection: The sections asked for; None when none was.
        picture: The posed robot, when a picture was asked for.
        clamped: The joint values moved into their limits, in the order given.
    """

    inspection: Inspection | None
    picture: PosedRobot | None
    clamped: tuple[Clamped, ...] = ()


@overload
def run(request: InspectRequest) -> InspectResult: ...
@overload
def run(request: DiffRequest) -> DiffResult: ...
def run(request: InspectRequest | DiffRequest) -> InspectResult | DiffResult:
    """Inspect one description, or compare two.

    Raises:
        DescriptionError: A description cannot be loaded, or its joints close a loop.
        JointValueError: A ``joints`` entry names no movable joint or is out of its limits
            (without ``clamp``); nothing else has been computed yet.
    """
    from servicebot_cli.description.loader import load

    if isinstance(request, DiffRequest):  # a mimic of no joint is shown as written
        return compare(_tree(load(request.a, as_written=True)),
                       _tree(load(request.b, as_written=True)))
    robot = _tree(load(request.source, as_written=True))
    values, held = _checked(robot, request.joints, request.clamp)
    resolver = request.source.resolver()
    picture = None
    if request.picture:
        from servicebot_cli.inspect.picture import pose_robot

        picture = pose_robot(robot, values, resolver)
    inspection = None
    if request.sections:
        inspection = inspect_robot(robot, Request(request.sections, values, request.clamp,
                                                  resolver, request.controllers))
    return InspectResult(inspection, picture, _clamped(robot, request.joints, values, held))


def _tree(robot: RobotDescription) -> RobotDescription:
    """``robot``, once its joints are known to form a tree.

    Raises:
        DescriptionError: A joint loop that Pinocchio's model would leave out.
    """
    from servicebot_cli.kinematics.frames import require_tree

    require_tree(robot)
    return robot


def _checked(robot: RobotDescription, joints: tuple[tuple[str, float], ...],
             clamp: bool) -> tuple[dict[str, float], dict[str, str]]:
    """The joint values after fk's checks (clamped with ``clamp``), and held leaders.

    The leaders a follower's limits held are those of :func:`~.poses.checked_and_held`.

    Raises:
        JointValueError: A fixed or unknown joint, or a value out of limits.
    """
    from servicebot_cli.inspect.poses import checked_and_held

    fixed = {j.name for j in robot.joints if not j.movable}
    try:
        for name, _ in joints:
            if name in fixed:
                raise OutOfLimits(f"joint '{name}' is fixed; only movable joints take a value "
                                  f"({', '.join(robot.joint_space.names)})")
        return checked_and_held(robot, dict(joints), clamp=clamp)
    except (NameNotFound, OutOfLimits) as exc:
        raise JointValueError(str(exc)) from None


def _clamped(robot: RobotDescription, joints: tuple[tuple[str, float], ...],
             used: dict[str, float], held: dict[str, str]) -> tuple[Clamped, ...]:
    """The values that clamping changed, with the limit used (or the follower that held it)."""
    space = robot.joint_space
    moved = []
    for name, given in joints:
        if used[name] != given:
            unit = "m" if space.types[space.index(name)] == "prismatic" else "rad"
            limit = "upper" if given > used[name] else "lower"
            moved.append(Clamped(name, given, used[name], limit, unit, held.get(name, "")))
    return tuple(moved)
