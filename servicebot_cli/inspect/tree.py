"""The kinematic tree: links as nodes, joints as edges, walked without recursion.

The loader only accepts what Pinocchio accepts, which is a tree, but this module does not
rely on it: several roots each start a tree, a link reached twice is shown once, and links no
root reaches (a cycle, a joint naming a missing parent) are listed apart instead of lost.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from servicebot_cli.description.elements import Joint


@dataclass(frozen=True)
class TreeRow:
    """One line of the tree: a link and the joint that attaches it to its parent.

    Attributes:
        link: The link.
        depth: 0 for a root.
        joint: The joint from the parent; None for a root.
        last: True when this link is its parent's last child (for drawing).
        open_levels: For each level above this one, whether a sibling still follows there.
    """

    link: str
    depth: int
    joint: Joint | None
    last: bool
    open_levels: tuple[bool, ...]


@dataclass(frozen=True)
class KinematicTree:
    """Links and the joints between them, in URDF order.

    Attributes:
        roots: Links that are no joint's child, in URDF order.
        children: For each link, the joints whose parent it is, in URDF order.
        unreachable: Links no root reaches, in URDF order.
    """

    roots: tuple[str, ...]
    children: dict[str, tuple[Joint, ...]]
    unreachable: tuple[str, ...]

    def rows(self) -> Iterator[TreeRow]:
        """Every reachable link once, depth first, children in URDF order."""
        seen: set[str] = set()
        stack = [TreeRow(root, 0, None, i == len(self.roots) - 1, ())
                 for i, root in reversed(list(enumerate(self.roots)))]
        while stack:
            row = stack.pop()
            if row.link in seen:
                continue
            seen.add(row.link)
            yield row
            joints = [j for j in self.children.get(row.link, ()) if j.child not in seen]
            levels = (*row.open_levels, not row.last) if row.depth else ()
            for i in reversed(range(len(joints))):
                joint = joints[i]
                stack.append(TreeRow(joint.child or "", row.depth + 1, joint,
                                     i == len(joints) - 1, levels))

    @property
    def edges(self) -> tuple[Joint, ...]:
        """Every joint between two known links, in tree order."""
        return tuple(row.joint for row in self.rows() if row.joint is not None)


def kinematic_tree(link_names: tuple[str, ...], joints: tuple[Joint, ...]) -> KinematicTree:
    """The tree of ``link_names`` joined by ``joints`` (both in URDF order)."""
    known = set(link_names)
    children: dict[str, list[Joint]] = {}
    child_links = set()
    for joint in joints:
        if joint.parent in known and joint.child in known:
            children.setdefault(joint.parent or "", []).append(joint)
            child_links.add(joint.child)
    roots = tuple(name for name in link_names if name not in child_links)
    tree = KinematicTree(roots, {k: tuple(v) for k, v in children.items()}, ())
    reached = {row.link for row in tree.rows()}
    unreachable = tuple(name for name in link_names if name not in reached)
    return KinematicTree(roots, tree.children, unreachable)


def descendants(tree: KinematicTree, link: str) -> list[tuple[str, int]]:
    """Links below ``link`` with their distance from it in joints, depth first."""
    found: list[tuple[str, int]] = []
    seen = {link}
    stack = [(link, 0)]
    while stack:
        name, depth = stack.pop()
        for joint in reversed(tree.children.get(name, ())):
            if joint.child and joint.child not in seen:
                seen.add(joint.child)
                found.append((joint.child, depth + 1))
                stack.append((joint.child, depth + 1))
    return found
