"""Where every link is at a joint configuration.

A configuration is what a user types: ``{joint name: value}`` in [rad] or [m]; joints not
named stay at zero. Names and limits are checked by the foundation's JointSpace, so a wrong
name gets the same did-you-mean message as in every other command.

The transforms are composed along the URDF tree, iteratively, from each joint's origin and
motion (tests check them against Pinocchio's forward kinematics). Pinocchio's ``Data`` is
not used here: its size grows with the square of the joints, and a 1000-joint chain, which
``inspect`` must still describe, would not fit in memory.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.elements import Joint
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]


def checked_values(robot: RobotDescription, values: Mapping[str, float], *,
                   clamp: bool = False) -> dict[str, float]:
    """``values`` after the foundation's checks, clamped into the limits if ``clamp``.

    Raises:
        JointNotFound: A name that is not a movable joint, with the closest names.
        OutOfLimits: A value outside its joint's limits (unless ``clamp``).
    """
    space = robot.joint_space
    vector = space.vector(dict(values), clamp=clamp)
    return {name: float(vector[space.index(name)]) for name in values}


def joint_motion(joint: Joint, value: float) -> FloatArray:
    """4x4 motion of a joint at ``value``: a rotation about, or a slide along, its axis.

    Rotation by angle t about unit axis k (Rodrigues): ``I + sin t K + (1 - cos t) K^2``.
    """
    motion = np.eye(4)
    if value == 0 or joint.type not in ("revolute", "continuous", "prismatic"):
        return motion
    axis = np.array(joint.axis, dtype=float)
    norm = np.linalg.norm(axis)
    if not np.isfinite(norm) or norm == 0:
        return motion
    axis /= norm
    if joint.type == "prismatic":
        motion[:3, 3] = axis * value
        return motion
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    motion[:3, :3] = np.eye(3) + np.sin(value) * k + (1 - np.cos(value)) * (k @ k)
    return motion


def link_transforms(robot: RobotDescription, values: Mapping[str, float] | None = None, *,
                    clamp: bool = False) -> dict[str, FloatArray]:
    """``transform_link_to_root`` (4x4) of every link the root reaches, at ``values``.

    Raises:
        JointNotFound, OutOfLimits: As :func:`checked_values`.
    """
    config = checked_values(robot, values or {}, clamp=clamp)
    root = robot.root_link
    if root is None:
        return {}
    children: dict[str, list[Joint]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent or "", []).append(joint)
    transforms = {root: np.eye(4)}
    stack = [root]
    while stack:  # iterative: chains deeper than Python's recursion limit are fine
        parent = stack.pop()
        for joint in children.get(parent, ()):
            if joint.child and joint.child not in transforms:
                motion = joint_motion(joint, config.get(joint.name, 0.0))
                transforms[joint.child] = transforms[parent] @ pose_matrix(joint.origin) @ motion
                stack.append(joint.child)
    return transforms
