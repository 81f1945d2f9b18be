r"""``ik``'s collision check on the joints of an arm: configurations and joint-space segments.

The check is :func:`~servicebot_cli.kinematics.ik_session.collision_check` with the arm's joints as
the moving ones, so it leaves out the pairs ``ik`` leaves out (adjacent links, links fixed
together, pairs that always touch, an SRDF's ``<disable_collisions>``) and has the same
floor. Every other joint stands at its neutral position (a wheel turned about its axis is
the same cylinder).

A straight segment in joint space is checked at points so close together that no point of
the collision geometry moves more than :data:`RESOLUTION_M` from one to the next. A revolute
joint :math:`i` moves a point at most :math:`L_i |\Delta q_i|`, where the lever
:math:`L_i` bounds the distance from the joint to anything it carries: the joint offsets
down the chain plus each part's bounding sphere. A prismatic joint moves it
:math:`|\Delta q_i|` (:math:`L_i = 1`). A step then moves any point at most
:math:`\sum_i L_i |\Delta q_i|`.
Pure: a model, its check and arm values in; contacts out.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.collisions import CollisionCheck, Contact
from servicebot_cli.kinematics.ik_problem import CollisionOptions
from servicebot_cli.kinematics.ik_session import collision_check

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]

RESOLUTION_M = 0.005
"""The most any point of the geometry moves between two checks of a segment [m]."""
_PRISMATIC = re.compile(r"JointModel(P[XYZ]|PrismaticUnaligned)")


@dataclass(frozen=True)
class PathContact:
    """Where on a segment two things first intersect.

    Attributes:
        contact: The two things.
        arm_rad: The arm's values there, in the check's joint order [rad, or m].
    """

    contact: Contact
    arm_rad: tuple[float, ...]


class ArmCollisions:
    """A collision check over the values of some joints (an arm), the rest at neutral.

    Args:
        check: The check (see :func:`arm_collisions`).
        model: The model it was built on.
        joints: The arm's joint names: the order of every arm vector.
    """

    def __init__(self, check: CollisionCheck, model: pin.Model, joints: Sequence[str]) -> None:
        import pinocchio as pin

        self.check = check
        self.joints = tuple(joints)
        self._q: FloatArray = pin.neutral(model)
        ids = [model.getJointId(name) for name in self.joints]
        self._columns = [model.joints[j].idx_q for j in ids]
        self.levers_m = levers_m(model, check.geometry, ids)

    def contact(self, arm_rad: Sequence[float]) -> Contact | None:
        """The first pair that intersects with the arm at ``arm_rad``; None: none does."""
        self._q[self._columns] = arm_rad
        return self.check.contact(self._q)

    def segment_contact(self, start_rad: Sequence[float],
                        end_rad: Sequence[float]) -> PathContact | None:
        """The first contact on the straight segment from ``start_rad`` to ``end_rad``.

        ``start_rad`` itself is not checked (it ends the previous segment); ``end_rad`` is.
        """
        start, end = np.asarray(start_rad, dtype=float), np.asarray(end_rad, dtype=float)
        delta = end - start
        sweep_m = float(self.levers_m @ np.abs(delta))
        count = max(1, math.ceil(sweep_m / RESOLUTION_M))
        for k in range(1, count + 1):
            arm = start + delta * (k / count)
            contact = self.contact(arm)
            if contact is not None:
                return PathContact(contact, tuple(float(v) for v in arm))
        return None


def levers_m(model: pin.Model, geometry: pin.GeometryModel, joints: Sequence[int]) -> FloatArray:
    """Per joint, the most a point it carries moves per unit of it [m/rad, or m/m].

    For a revolute joint: the largest distance from its origin to a part it carries,
    bounded by the joint offsets between them (plus the travel of prismatic joints) and the
    part's offset and bounding sphere. 0 for a joint that carries no collision geometry.
    """
    levers = np.zeros(len(joints))
    for n, joint in enumerate(joints):
        if _PRISMATIC.fullmatch(model.joints[joint].shortname()):
            levers[n] = 1.0
            continue
        for obj in geometry.geometryObjects:
            chain = [int(j) for j in model.supports[obj.parentJoint]]
            if joint not in chain:
                continue
            levers[n] = max(levers[n], sum(_offset_m(model, k) for k in
                                           chain[chain.index(joint) + 1:])
                            + _part_radius_m(obj))
    return levers


def _offset_m(model: pin.Model, joint: int) -> float:
    """How far ``joint`` can be from its parent joint's origin [m]."""
    distance = float(np.linalg.norm(model.jointPlacements[joint].translation))
    if _PRISMATIC.fullmatch(model.joints[joint].shortname()):
        i = model.joints[joint].idx_q
        distance += max(abs(float(model.lowerPositionLimit[i])),
                        abs(float(model.upperPositionLimit[i])))
    return distance


def _part_radius_m(obj: pin.GeometryObject) -> float:
    """How far any point of ``obj`` is from its joint's origin, at most [m]."""
    shape = obj.geometry
    shape.computeLocalAABB()
    return float(np.linalg.norm(obj.placement.translation)
                 + np.linalg.norm(shape.aabb_center) + shape.aabb_radius)


def arm_collisions(robot: RobotDescription, source: RobotSource, options: CollisionOptions,
                   joints: Sequence[str]) -> ArmCollisions | None:
    """``ik``'s check of ``robot`` (fixed base) with ``joints`` moving; None when turned off.

    Raises:
        BadSrdf: An unreadable SRDF, or one that names a link the robot does not have.
        CollisionSetupError: A collision mesh that cannot be read.
    """
    model = robot.model
    check = collision_check(robot, model, source, options, tuple(joints))
    return None if check is None else ArmCollisions(check, model, joints)
