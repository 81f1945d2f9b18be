"""The kinematic tree as text, like check_urdf's, with each joint's motion and limits.

Very deep trees keep their lines short: past :data:`MAX_LEVELS` the drawing shows only the
innermost levels, prefixed by the depth.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from servicebot_cli.inspect.joints import joint_info
from servicebot_cli.output import describe as d
from servicebot_cli.output.blocks import Table

if TYPE_CHECKING:
    from servicebot_cli.inspect.report import TreeInfo
    from servicebot_cli.inspect.tree import TreeRow

MAX_LEVELS = 5


def branch(row: TreeRow) -> str:
    """The drawing before a link's name: ``│  └─ `` and so on."""
    if row.depth == 0:
        return ""
    levels, lead = row.open_levels, ""
    if len(levels) > MAX_LEVELS:
        lead, levels = f"{row.depth}… ", levels[-MAX_LEVELS:]
    return lead + "".join("│  " if more else "   " for more in levels) + (
        "└─ " if row.last else "├─ ")


def tree_table(tree: TreeInfo) -> Table:
    """One row per link: the drawing, then the joint from its parent."""
    links, joints = len(tree.edges) + len(tree.roots), len(tree.edges)
    table = Table(f"Kinematic tree ({links} link{'s' * (links != 1)}, "
                  f"{joints} joint{'s' * (joints != 1)})", ("link", "joint", "motion", "limits"))
    for row in tree.tree.rows():
        name = branch(row) + row.link
        if row.joint is None:
            table.rows.append((name, "", "", ""))
            continue
        info = joint_info(row.joint)
        table.rows.append((name, info.name, d.joint_motion(info.type, info.axis),
                           d.joint_limits(info.limits) if info.limits else ""))
    notes = ["joint efforts and origins: --section joints; fixed frames: --section frames"]
    if len(tree.roots) > 1:
        notes.append(f"{len(tree.roots)} roots: {', '.join(tree.roots)} (a URDF has one)")
    if tree.unreachable:
        notes.append(f"not reachable from a root: {', '.join(tree.unreachable)}")
    return Table(table.title, table.headers, table.rows, tuple(notes), whole=(0,))
