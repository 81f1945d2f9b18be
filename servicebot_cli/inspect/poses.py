"""Where every link is at a joint configuration the user typed.

A configuration is ``{joint name: value}`` in [rad] or [m]; joints not named stay at zero.
Names and limits are checked by the foundation's JointSpace, so a wrong name gets the same
did-you-mean message as in every other command; the poses come from the URDF tree
(:mod:`servicebot_cli.kinematics.link_poses`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from servicebot_cli.kinematics import link_poses
from servicebot_cli.kinematics.link_poses import FloatArray

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def checked_values(robot: RobotDescription, values: Mapping[str, float], *,
                   clamp: bool = False) -> dict[str, float]:
    """``values`` after the foundation's checks, clamped into the limits if ``clamp``.

    Raises:
        JointNotFound: A name that is not a movable joint, with the closest names.
        OutOfLimits: A value outside its joint's limits (unless ``clamp``).
    """
    if not values:
        return {}
    space = robot.joint_space
    vector = space.vector(dict(values), clamp=clamp)
    return {name: float(vector[space.index(name)]) for name in values}


def link_transforms(robot: RobotDescription, values: Mapping[str, float] | None = None, *,
                    clamp: bool = False) -> dict[str, FloatArray]:
    """``transform_link_to_root`` (4x4) of every link the root reaches, at checked ``values``.

    Raises:
        JointNotFound, OutOfLimits: As :func:`checked_values`.
    """
    return link_poses.link_transforms(robot, checked_values(robot, values or {}, clamp=clamp))
