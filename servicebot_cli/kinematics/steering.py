"""Steered wheels: a car-like base, which simulate and drive must not run as a differential drive.

A wheel that a revolute joint turns about the vertical is steered (ros2_control_demos'
carlikebot, an Ackermann base). Its rear wheels still look like a differential drive, but
the base cannot turn in place: a run of it as one would be wrong, not approximate, and
``drive`` would send its rear motors opposite speeds to turn.
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
_ON_THE_FLOOR_M = 0.01  # a wheel's lowest point within this of the lowest wheel's


def refuse_steered_wheels(robot: RobotDescription) -> None:
    """Refuse a base whose wheels a revolute joint steers about the vertical.

    A steering joint is revolute, turns about the root link's z (at the zero configuration)
    and carries a wheel on its link or the next one (a steering hinge and its wheel joint,
    as pybullet's racecar has them): a cylinder lying on its side whose lowest point is as
    low as the lowest wheel's, on the floor. A turret or an arm's waist carrying a
    horizontal cylinder higher up steers nothing.

    Raises:
        DescriptionError: Naming the first steering joint and its wheel.
    """
    world = link_transforms(robot)
    lowest = {name: bottom for name in world
              if (bottom := _wheel_bottom(robot, name, world[name])) is not None}
    if not lowest:
        return
    floor_m = min(lowest.values())
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
        wheel = next((name for name in below
                      if name in lowest and lowest[name] <= floor_m + _ON_THE_FLOOR_M), None)
        if wheel is not None:
            raise DescriptionError(
                f"{robot.display}: not a differential drive: joint '{joint.name}' steers "
                f"the wheel on link '{wheel}' about the vertical (a car-like base, which "
                "cannot turn in place); servicebot simulates and drives differential-drive "
                "bases only")


def _wheel_bottom(robot: RobotDescription, link: str, pose: np.ndarray) -> float | None:
    """Height of the lowest point of ``link``'s cylinders lying on their side, or None.

    ``pose`` is the link's ``transform_link_to_root``.
    """
    bottoms = []
    found = robot.find_link(link)
    for shape in () if found is None else (*found.collisions, *found.visuals):
        geometry = shape.geometry
        if geometry.kind != "cylinder" or geometry.radius is None:
            continue
        placed = pose @ pose_matrix(shape.origin)
        if abs(float(placed[2, 2])) < _LEVEL:  # its axis is horizontal
            bottoms.append(float(placed[2, 3]) - geometry.radius)
    return min(bottoms) if bottoms else None
