"""Steered wheels: a car-like base that the differential-drive simulator must not drive.

A wheel that a revolute joint turns about the vertical is steered (ros2_control_demos'
carlikebot, an Ackermann base). Its rear wheels still look like a differential drive, but
the base cannot turn in place, so a run of it as one would be wrong, not approximate.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_VERTICAL = 0.99  # |cos| between an axis and the root's z that counts as vertical
_LEVEL = 0.1  # |cos| between a cylinder's axis and the root's z that counts as horizontal


def refuse_steered_wheels(robot: RobotDescription) -> None:
    """Refuse a base whose wheels a revolute joint steers about the vertical.

    A steering joint is revolute, turns about the root link's z (at the zero configuration)
    and carries a cylinder lying on its side, a wheel, on its link or the next one (a
    steering hinge and its wheel joint, as pybullet's racecar has them).

    Raises:
        DescriptionError: Naming the first steering joint and its wheel.
    """
    world = link_transforms(robot)
    for joint in robot.joints:
        if joint.type != "revolute" or joint.child not in world:
            continue
        axis = np.array(joint.axis, dtype=float)
        norm = float(np.linalg.norm(axis))
        if not np.isfinite(norm) or norm == 0:
            continue
        rotation = world[joint.child][:3, :3]
        if abs(float((rotation @ axis)[2])) / norm < _VERTICAL:
            continue
        below = [joint.child, *(j.child for j in robot.joints if j.parent == joint.child)]
        wheel = next((name for name in below if name in world and _lies_on_side(
            robot, name, world[name][:3, :3])), None)
        if wheel is not None:
            raise DescriptionError(
                f"{robot.display}: not a differential drive: joint '{joint.name}' steers "
                f"the wheel on link '{wheel}' about the vertical (a car-like base, which "
                "cannot turn in place); simulate drives differential-drive bases only")


def _lies_on_side(robot: RobotDescription, link: str, rotation: np.ndarray) -> bool:
    """True when ``link`` carries a cylinder whose axis is horizontal (``rotation``: to root)."""
    shapes = robot.link(link)
    return any(shape.geometry.kind == "cylinder"
               and abs(float((rotation @ pose_matrix(shape.origin)[:3, 2])[2])) < _LEVEL
               for shape in (*shapes.collisions, *shapes.visuals))
