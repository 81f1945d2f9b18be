"""Joints that follow another (``<mimic>``): the rules, in the order to apply them.

Pure: URDF joints in, index rules out.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.joint_space import JointSpace

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Mimics:
    """Joints that follow another (``<mimic>``): follower = multiplier * leader + offset.

    Attributes:
        follower: Indices (in the joint space) of mimicking joints.
        leader: Index of the joint each one follows.
        multiplier: Factor per follower.
        offset: Offset per follower [rad or m].
    """

    follower: tuple[int, ...] = ()
    leader: tuple[int, ...] = ()
    multiplier: tuple[float, ...] = ()
    offset: tuple[float, ...] = ()

    @classmethod
    def of(cls, joints: Sequence[Joint], space: JointSpace) -> Mimics:
        """The mimic rules among ``joints`` whose both ends are in ``space``."""
        return cls.among(joints, space.names)

    @classmethod
    def among(cls, joints: Sequence[Joint], names: Sequence[str]) -> Mimics:
        """The mimic rules of ``joints`` whose both ends are in ``names`` (indices into it).

        A follower's rule comes after its leader's when the leader follows another joint
        too, so that rules applied in order see each leader's value already set.
        """
        rules = {names.index(j.name): (names.index(j.mimic.joint), j.mimic.multiplier,
                                       j.mimic.offset)
                 for j in joints if j.mimic is not None and j.name in names
                 and j.mimic.joint in names and j.mimic.joint != j.name}
        ordered: list[tuple[int, int, float, float]] = []
        placed: set[int] = set()

        def place(follower: int, seen: frozenset[int]) -> None:
            if follower in placed or follower in seen:  # a loop: each is set once, in turn
                return
            leader, multiplier, offset = rules[follower]
            if leader in rules:
                place(leader, seen | {follower})
            placed.add(follower)
            ordered.append((follower, leader, multiplier, offset))

        for follower in rules:
            place(follower, frozenset())
        return cls(*(tuple(column) for column in zip(*ordered, strict=True))) if ordered \
            else cls()

    def applied(self, values: FloatArray) -> FloatArray:
        """``values`` (..., joints) with every follower set from its leader, in place."""
        for f, lead, k, c in zip(self.follower, self.leader, self.multiplier, self.offset,
                                 strict=True):
            values[..., f] = k * values[..., lead] + c
        return values

    def overridden(self, values: FloatArray, named: Iterable[str],
                   space: JointSpace) -> list[tuple[str, str, float]]:
        """Each follower given a value its ``<mimic>`` does not make, its leader, that value.

        Values in the joint space's units (radians, metres).
        """
        given = set(named)
        out = []
        for f, lead, k, c in zip(self.follower, self.leader, self.multiplier, self.offset,
                                 strict=True):
            made = k * values[lead] + c
            if space.names[f] in given and abs(values[f] - made) > 1e-9:
                out.append((space.names[f], space.names[lead], float(made)))
        return out

    def apply(self, values: FloatArray, named: Iterable[str], space: JointSpace) -> FloatArray:
        """``values`` with every follower the user did not name set from its leader."""
        given = set(named)
        for f, lead, k, c in zip(self.follower, self.leader, self.multiplier, self.offset,
                                 strict=True):
            if space.names[f] not in given:
                values[f] = k * values[lead] + c
        return values



def rules_of(mimics: Mimics | None, given: Collection[str],
              space: JointSpace) -> dict[int, tuple[int, float, float]]:
    """Each follower the user did not name: its root leader, and the rule from it.

    A follower of a follower is traced back to the first joint that follows none (or that
    the user gave), the rules composed: ``k2 * (k1 * x + c1) + c2``.
    """
    if mimics is None:
        return {}
    direct = {f: (lead, k, c) for f, lead, k, c in zip(mimics.follower, mimics.leader,
                                                       mimics.multiplier, mimics.offset,
                                                       strict=True)}
    rules = {}
    for follower, (lead, k, c) in direct.items():
        if space.names[follower] in given:
            continue
        seen = {follower}
        while lead in direct and lead not in seen and space.names[lead] not in given:
            seen.add(lead)
            lead, k_lead, c_lead = direct[lead]
            k, c = k * k_lead, k * c_lead + c
        rules[follower] = (lead, k, c)
    return rules


def leader_range(space: JointSpace, follower: int, factor: float,
                 offset: float) -> tuple[float, float]:
    """The leader's values that keep ``follower`` within its limits, lowest first.

    ``follower`` is ``factor * leader + offset``, with a factor other than 0.
    """
    low, high = sorted(((space.lower[follower] - offset) / factor,
                        (space.upper[follower] - offset) / factor))
    return low, high
