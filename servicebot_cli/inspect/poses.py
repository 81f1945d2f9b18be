"""Where every link is at a joint configuration the user typed.

A configuration is ``{joint name: value}`` in [rad] or [m]; joints not named stay at zero,
and joints that follow a named one (``<mimic>``) follow it. Names and limits are checked as
``fk`` checks them, so a wrong name gets the same did-you-mean message as in every other
command; the poses come from the URDF tree
(:mod:`servicebot_cli.kinematics.link_poses`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from servicebot_cli.kinematics import link_poses
from servicebot_cli.kinematics.link_poses import FloatArray
from servicebot_cli.kinematics.mimics import Mimics
from servicebot_cli.kinematics.user_joints import clamped_user_vector

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def checked_values(robot: RobotDescription, values: Mapping[str, float], *,
                   clamp: bool = False) -> dict[str, float]:
    """``values`` after the checks fk makes, clamped into the limits if ``clamp``.

    A joint that follows a named one (``<mimic>``) takes its value from it, and is checked
    too; joints not named, and not following one, stay at zero unchecked, as in ``fk``.

    Raises:
        JointNotFound: A name that is not a movable joint, with the closest names.
        OutOfLimits: A value outside its joint's limits (unless ``clamp``), or a follower
            that its leader's value puts outside its own.
    """
    return checked_and_held(robot, values, clamp=clamp)[0]


def checked_and_held(robot: RobotDescription, values: Mapping[str, float], *,
                     clamp: bool = False) -> tuple[dict[str, float], dict[str, str]]:
    """:func:`checked_values`, and each leader ``clamp`` held where a follower fits.

    The second mapping names, for such a leader, the follower whose limits moved it.
    """
    if not values:
        return {}, {}
    space = robot.joint_space
    mimics = Mimics.of(robot.joints, space)
    vector, clamped = clamped_user_vector(space, values.items(), clamp=clamp, mimics=mimics)
    held = {c.joint: c.because for c in clamped if c.because}
    kept = {space.index(name) for name in values}
    for follower, leader in zip(mimics.follower, mimics.leader, strict=True):
        if leader in kept:  # in rule order: a follower's follower too
            kept.add(follower)
    return {space.names[i]: float(vector[i]) for i in sorted(kept)}, held


def link_transforms(robot: RobotDescription, values: Mapping[str, float] | None = None, *,
                    clamp: bool = False) -> dict[str, FloatArray]:
    """``transform_link_to_root`` (4x4) of every link the root reaches, at checked ``values``.

    Raises:
        JointNotFound, OutOfLimits: As :func:`checked_values`.
    """
    return link_poses.link_transforms(robot, checked_values(robot, values or {}, clamp=clamp))
