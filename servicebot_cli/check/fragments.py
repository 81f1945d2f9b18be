"""A xacro part that hangs from a link it does not define: an include, not a robot.

Real packages keep parts of a robot as xacro files with a named ``<robot>`` that attach to a
link of the robot that includes them: baxter's ``rethink_ee_description`` end effectors
(every joint from ``left_hand``, sent as a URDF fragment at run time), stretch's
``stretch_gripper_with_puller.xacro`` (from ``link_wrist_yaw``). Checked alone, each would
fail with SB103 and SB104; it is checked through the files that include it (SB018).

A robot has a root link of its own; a part has none: every link it defines is the child of
one of its joints, and every joint that names a link it lacks names the same one, as parent.
Only xacro input is read so: a ``.urdf`` is a robot, and a broken one still fails.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def external_parent(robot: RobotDescription) -> str | None:
    """The one link outside ``robot`` that all of it hangs from, when it is such a part.

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
