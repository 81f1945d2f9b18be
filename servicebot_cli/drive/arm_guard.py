"""Arm targets, and the arm's way to them, that would put the robot through itself.

Checked with ``ik``'s collision check (:mod:`~servicebot_cli.kinematics.arm_collisions`:
the same pairs left out, ``--srdf``, ``--allow-collisions``, the words of ``ik``'s
``collision_hint``, except that no SRDF can disable the floor). The way is
the path the firmware takes (:mod:`~servicebot_cli.drive.arm_motion`), checked so finely
that no point of the arm moves more than 5 mm between two checks.

Which configurations are known when: a joint a plan never names holds where the firmware
reports it, which only a run on a port learns. So before the port opens, a dry run checks
everything from the start it assumes, and a run checks the targets that name every arm
joint (:meth:`ArmGuard.known_targets`); once the firmware has reported the arm, and before
the first arm target is sent, the run checks everything from there
(:meth:`ArmGuard.from_start`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.drive.arm_motion import ArmValues, arm_legs
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Step
from servicebot_cli.kinematics.collisions import Contact
from servicebot_cli.kinematics.diagnosis import ways_out

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.arm_collisions import ArmCollisions


class ArmCollision(ServicebotError):
    """An arm target, or the arm's way to it, through the robot or the floor (exit 2)."""


@dataclass(frozen=True)
class Refusal:
    """Why a plan's arm motion is refused.

    Attributes:
        where: The script line (``tour.txt:3``) or the option (``--arm``).
        reason: What would intersect, and the ways out.
    """

    where: str
    reason: str

    def __str__(self) -> str:
        return f"{self.where}: {self.reason}"


class ArmGuard:
    """The collision checks of one plan's arm targets.

    Args:
        steps: The plan's steps.
        motors: The robot's motors (arm joints, limits and speeds).
        collisions: The check, over ``motors.arm_joints``.
        where: Names the script line or option of a step with arm targets.
    """

    def __init__(self, steps: Sequence[Step], motors: MotorMap, collisions: ArmCollisions,
                 where: Callable[[Step], str]) -> None:
        self.steps, self.motors, self.collisions, self.where = steps, motors, collisions, where

    def known_targets(self) -> Refusal | None:
        """The first target that collides among those that name every arm joint."""
        named: set[str] = set()
        target: ArmValues = (0.0,) * len(self.motors.arm_joints)
        for step in self.steps:
            if not step.arm:
                continue
            named |= {name for name, _ in step.arm}
            target = self.motors.arm_targets(dict(step.arm), target)
            if len(named) == len(self.motors.arm_joints):
                contact = self.collisions.contact(target)
                if contact is not None:
                    return self._target_refusal(step, contact)
        return None

    def from_start(self, start_rad: ArmValues) -> Refusal | None:
        """The first collision of the plan's arm motion from ``start_rad``, step by step.

        At the start, each target, then the way to it.
        """
        legs = list(arm_legs(self.steps, start_rad, self.motors))
        contact = self.collisions.contact(start_rad) if legs else None
        if contact is not None:
            return Refusal(self.where(legs[0].step), (
                f"the arm starts at {self._values(start_rad)}, where {contact} already "
                f"intersect; move it clear first, or {ways_out(contact)}"))
        for leg in legs:
            contact = self.collisions.contact(leg.target_rad)
            if contact is not None:
                return self._target_refusal(leg.step, contact)
            for a, b in pairwise(leg.path_rad):
                found = self.collisions.segment_contact(a, b)
                if found is not None:
                    return self._path_refusal(leg.step, found.contact, leg.path_rad[0],
                                              leg.target_rad, found.arm_rad)
        return None

    def refuse_from(self, start_rad: ArmValues) -> None:
        """:meth:`from_start` for a run: where the firmware first reports the arm.

        Raises:
            ArmCollision: The plan's arm motion from there collides.
        """
        refusal = self.from_start(start_rad)
        if refusal is not None:
            raise ArmCollision(str(refusal))

    def _target_refusal(self, step: Step, contact: Contact) -> Refusal:
        return Refusal(self.where(step), (
            f"arm target {_typed(step)} is reachable only through a collision: {contact} "
            f"would intersect; {ways_out(contact)}"))

    def _path_refusal(self, step: Step, contact: Contact, start: ArmValues, target: ArmValues,
                      there: tuple[float, ...]) -> Refusal:
        moving = [k for k, (a, b) in enumerate(zip(start, target, strict=True)) if a != b]
        return Refusal(self.where(step), (
            f"arm target {_typed(step)}: on the way there, "
            f"at {self._values(there, moving)}, {contact} would intersect; a target in "
            f"between can steer around it, or {ways_out(contact)}"))

    def _values(self, arm: Sequence[float], joints: Sequence[int] | None = None) -> str:
        """``name=value`` for ``joints`` of ``arm`` (default: every arm joint)."""
        names = self.motors.arm_joints
        chosen = range(len(names)) if joints is None else joints
        return " ".join(f"{names[k]}={arm[k]:.3g}" for k in chosen)


def _typed(step: Step) -> str:
    """A step's arm targets as typed: ``name=value ...``."""
    return " ".join(f"{name}={value:g}" for name, value in step.arm)


def arm_guard(robot: RobotDescription, source: RobotSource, srdf: str | None,
              steps: Sequence[Step], motors: MotorMap,
              where: Callable[[Step], str]) -> ArmGuard | None:
    """The guard of ``steps``; None when they name no arm target (nothing is loaded then).

    Raises:
        BadSrdf: An unreadable SRDF, or one that names a link the robot does not have.
        CollisionSetupError: A collision mesh that cannot be read.
    """
    if not any(step.arm for step in steps):
        return None
    from servicebot_cli.kinematics.arm_collisions import arm_collisions
    from servicebot_cli.kinematics.ik_problem import CollisionOptions

    collisions = arm_collisions(robot, source, CollisionOptions(True, srdf), motors.arm_joints)
    return None if collisions is None else ArmGuard(steps, motors, collisions, where)
