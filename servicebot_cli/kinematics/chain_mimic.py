"""Joints that follow another (``<mimic>``) in an IK chain: one value moves them all.

A chain may hold a follower: a parallel linkage's levelling joint, a gripper's second finger.
Solved as a free joint, it would give an answer no robot can take. Each group of coupled
joints (a leader and every joint that follows it, directly or through another follower) is
solved as one value: that of the member Pinocchio orders first among those that move the
frame. The other members that move it become Pinocchio mimic joints of that one
(``pin.transformJointIntoMimic``), so every Jacobian the solvers take carries the coupling.
The value's limits keep every member of the group, moving the frame or not, within its own;
the answer sets every member from it. Pure: models in, arrays out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.mimics import leader_range

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.joint_space import JointSpace
    from servicebot_cli.kinematics.mimics import Mimics

FloatArray = npt.NDArray[np.float64]


class CannotCouple(ServicebotError):
    """Followers a chain cannot solve with their leader.

    A continuous joint among them, or limits that no value of the group meets.
    """


@dataclass(frozen=True)
class Groups:
    """Each joint of a joint space as ``factor * value of its root + offset``.

    Attributes:
        root: Per joint (joint-space index), the joint its group follows; itself if it
            follows none.
        factor: Per joint, its value per unit of the root's.
        offset: Per joint, its value when the root's is 0 [rad or m].
    """

    root: tuple[int, ...]
    factor: FloatArray
    offset: FloatArray

    @classmethod
    def of(cls, mimics: Mimics, size: int) -> Groups:
        """The groups of ``mimics`` over a joint space of ``size`` joints.

        A loop of followers (which check reports as SB211) is cut where it closes.
        """
        root = list(range(size))
        factor, offset = np.ones(size), np.zeros(size)
        for follower, leader, multiplier, shift in zip(mimics.follower, mimics.leader,
                                                       mimics.multiplier, mimics.offset,
                                                       strict=True):
            if root[leader] == follower:
                continue
            root[follower] = root[leader]
            factor[follower] = multiplier * factor[leader]
            offset[follower] = multiplier * offset[leader] + shift
        return cls(tuple(root), factor, offset)

    def members(self, joint: int) -> list[int]:
        """The joints of ``joint``'s group, itself included."""
        return [k for k, r in enumerate(self.root) if r == self.root[joint]]


@dataclass(frozen=True)
class Coupling:
    """How a chain's followers move with the value it solves for.

    Attributes:
        model: The full model with each follower that moves the frame a mimic joint.
        keep: Pinocchio joints of :attr:`model` the chain keeps (followers fixed by a
            multiplier of 0 left out: they stand at their offset).
        reference: Full ``q`` the locked joints stand at.
        driver: Per coupled group moving the frame, ``(root, joint solved for)`` (joint-space
            indices).
        groups: Every joint as a function of its root.
    """

    model: pin.Model
    keep: frozenset[int]
    reference: FloatArray
    driver: tuple[tuple[int, int], ...]
    groups: Groups

    def limits(self, space: JointSpace, lower: FloatArray, upper: FloatArray,
               index_of: dict[int, int]) -> None:
        """Narrow each driver's limits, in place, to where its whole group is within limits.

        ``lower`` and ``upper`` are per entry of the chain's ``q``; ``index_of`` finds a
        driver's entry from its joint-space index.

        Raises:
            CannotCouple: No value keeps every member of a group within its limits.
        """
        for _, drive in self.driver:
            i = index_of[drive]
            low, high = lower[i], upper[i]
            for k in self.groups.members(drive):
                if math.isnan(space.lower[k]):
                    continue
                # k = ratio * drive + shift, from both as functions of the root
                ratio = self.groups.factor[k] / self.groups.factor[drive]
                shift = self.groups.offset[k] - ratio * self.groups.offset[drive]
                if ratio == 0.0:
                    continue
                ends = leader_range(space, k, ratio, shift)
                low, high = max(low, ends[0]), min(high, ends[1])
            if low > high:
                raise CannotCouple(
                    f"joint '{space.names[drive]}' and the joints that mimic it, or that it "
                    "mimics, have limits no value of it meets; correct the <limit> or "
                    "<mimic> elements")
            lower[i], upper[i] = low + 0.0, high + 0.0  # numpy draws in nothing like [0.0, -0.0]

    def seeded(self, space: JointSpace, q_full: FloatArray) -> FloatArray:
        """``q_full`` with each driver set from its group's root (a new array).

        A start names the leader (``--start panda_finger_joint1=0.03``); the chain solves for
        the follower that moves the frame, which starts where the leader puts it.
        """
        values = space.from_q(q_full)
        for root, drive in self.driver:
            values[drive] = self.groups.factor[drive] * values[root] + self.groups.offset[drive]
        return space.to_q(values, q_full)

    def follow(self, space: JointSpace, q_full: FloatArray) -> FloatArray:
        """``q_full`` with every member of every group set from its driver (a new array).

        ``q_full`` is of the model the chain came from. A group no member of which moves the
        frame follows its root.
        """
        values = space.from_q(q_full)
        root_value = values.copy()
        for root, drive in self.driver:
            root_value[root] = (values[drive] - self.groups.offset[drive]) \
                / self.groups.factor[drive]
        roots = np.array(self.groups.root, dtype=np.intp)
        followed = self.groups.factor * root_value[roots] + self.groups.offset
        plain = roots != np.arange(len(roots))
        for root, _ in self.driver:
            plain[root] = True
        values[plain] = followed[plain]
        return space.to_q(values, q_full)


def coupling(model: pin.Model, space: JointSpace, mimics: Mimics,
             keep: Sequence[int]) -> Coupling | None:
    """The coupling of a chain that keeps the Pinocchio joints ``keep`` of ``model``.

    None when no follower, and no leader of one, moves the frame.

    Raises:
        CannotCouple: A follower or its driver is a continuous joint.
    """
    import pinocchio as pin

    if not mimics.follower:
        return None
    groups = Groups.of(mimics, len(space.names))
    joint_of = {k: int(model.getJointId(name)) for k, name in enumerate(space.names)}
    kept_members: dict[int, list[int]] = {}
    for k, joint in joint_of.items():
        if joint in keep:
            kept_members.setdefault(groups.root[k], []).append(k)
    coupled = {root: sorted(ks, key=joint_of.__getitem__) for root, ks in kept_members.items()
               if len(groups.members(root)) > 1}
    if not coupled:
        return None
    out, kept = pin.Model(model), set(keep)
    standing: list[int] = []  # a multiplier of 0: the joint stands at its offset
    driver = []
    for root, members in coupled.items():
        moving = [k for k in members if groups.factor[k] != 0.0]
        standing += [k for k in members if groups.factor[k] == 0.0]
        if not moving:
            continue
        drive = moving[0]
        driver.append((root, drive))
        bounded = [k for k in groups.members(root) if k != drive and not math.isnan(
            space.lower[k])]
        if space.types[drive] == "continuous" and bounded:
            raise CannotCouple(
                f"joint '{space.names[bounded[0]]}' follows continuous joint "
                f"'{space.names[drive]}' (<mimic>) and has limits: ik keeps the limits of "
                "coupled revolute and prismatic joints only")
        for k in moving[1:]:
            if "continuous" in (space.types[k], space.types[drive]):
                raise CannotCouple(
                    f"joint '{space.names[k]}' mimics '{space.names[drive]}' (or they follow "
                    "one joint) and one is continuous: ik solves coupled revolute and "
                    "prismatic joints only")
            ratio = groups.factor[k] / groups.factor[drive]
            shift = groups.offset[k] - ratio * groups.offset[drive]
            out = pin.transformJointIntoMimic(out, joint_of[drive], joint_of[k], ratio, shift)
    reference: FloatArray = pin.neutral(out)  # mimic joints have no entries: a new layout
    for k in standing:
        kept.discard(joint_of[k])
        at = out.joints[joint_of[k]].idx_q
        if space.types[k] == "continuous":
            reference[at:at + 2] = math.cos(groups.offset[k]), math.sin(groups.offset[k])
        else:
            reference[at] = groups.offset[k]
    return Coupling(out, frozenset(kept), reference, tuple(driver), groups)
