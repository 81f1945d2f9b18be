"""A xacro part that hangs from a link it does not define: an include, not a robot.

Real packages keep parts of a robot as xacro files with a named ``<robot>`` that attach to a
link of the robot that includes them: baxter's ``rethink_ee_description`` end effectors
(every joint from ``left_hand``, sent as a URDF fragment at run time), stretch's
``stretch_gripper_with_puller.xacro`` (from ``link_wrist_yaw``). Checked alone, each would
fail with SB103 and SB104; it is checked through the files that include it (SB018).

A part has no root link of its own: every link it defines is the child of one of its joints,
and every joint that names a link it lacks names the same one, as parent. That shape alone
is no evidence: a top-level robot joined to a ``world`` it forgot to define, or whose root
link sits in an ``xacro:if`` that is false, has it too, and must fail (SB103), as
``simulate`` refuses it. So the shape counts only with evidence that the file is a part:

- another robot file of its package includes it (stretch's gripper parts; a file in no
  package: one beside it), found through :func:`files.includer_nearby`, or does so in a
  comment (stretch's ``stretch_dry_erase_marker.xacro``, an alternative tool switched in by
  moving the comment); or
- it holds no link or joint of its own, only calls of macros it includes, and the link it
  hangs from is not written in it but made by those macros (baxter's
  ``example_end_effector.urdf.xacro``: ``<xacro:null_gripper side="left"/>``, whose macro
  attaches to ``${side}_hand``). A file that passes ``world``, or that names its missing
  parent itself (``<xacro:arm parent="base"/>``), is a robot.

Only xacro input is read so: a ``.urdf`` is a robot, and a broken one still fails. A
directory walk already leaves out the files another file of the walk includes.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_OWN_CONTENT = re.compile(rb"<(?:link|joint)\b")
_MACRO_CALL = re.compile(rb"<xacro:(?!include\b|property\b|arg\b|macro\b|if\b|unless\b)[\w.-]+\b")
_ROOT_FRAMES = {"world", "map", "odom"}
ALTERNATIVE_PART = "an alternative part"
"""How :func:`part_evidence` starts when only a comment includes the part."""


def external_parent(robot: RobotDescription) -> str | None:
    """The one link outside ``robot`` that all of it hangs from, when it has that shape.

    None for a robot with a root link of its own, or with a child link it lacks, or with
    several missing parents (a broken robot, not a part).
    """
    links = {link.name for link in robot.links if link.name}
    if not links or not robot.joints:
        return None
    children = {joint.child for joint in robot.joints}
    if not links <= children or not children <= links:
        return None  # a root of its own, or a child link that is nowhere
    outside = {joint.parent for joint in robot.joints} - links
    if len(outside) != 1:
        return None
    (parent,) = outside
    return parent or None


def part_evidence(path: Path, parent: str) -> str | None:
    """Why the xacro file ``path``, hung from ``parent``, is a part; None: it is a robot."""
    from servicebot_cli.check import files

    includer = files.includer_nearby(path)
    if includer is not None:
        return f"included by {includer}"
    includer = files.includer_nearby(path, in_comments=True)
    if includer is not None:
        return f"{ALTERNATIVE_PART}: {includer} includes it in a comment"
    if parent not in _ROOT_FRAMES and _only_macro_calls(path, parent):
        return "built only by the macros it includes"
    return None


def _only_macro_calls(path: Path, parent: str) -> bool:
    """Whether ``path`` holds only macro calls and never writes ``parent`` itself."""
    from servicebot_cli.check import files

    text = files.head_without_comments(path)
    if text is None:
        return False
    outside = files.without_macros(text)
    return (_OWN_CONTENT.search(outside) is None and _MACRO_CALL.search(outside) is not None
            and parent.encode() not in text)
