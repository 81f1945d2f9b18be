"""A link that is the child of two joints: the one thing a URDF's tree may not have.

urdfdom leaves the check to its users: Pinocchio builds such a robot with one of the joints
silently gone, and crashes on a loop (whose links all have a parent, one of them two).
Loading refuses the first; ``check`` reports each (SB106). Pure.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint


def second_parents(joints: Iterable[Joint]) -> Iterator[tuple[Joint, Joint]]:
    """Each joint whose child an earlier joint has already, after that earlier joint.

    Joints without a child are left out.
    """
    first: dict[str, Joint] = {}
    for joint in joints:
        child = joint.child
        if not child:
            continue
        if child in first:
            yield first[child], joint
        else:
            first[child] = joint
