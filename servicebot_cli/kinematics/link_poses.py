"""Where every link is, from the URDF tree alone: origins composed with joint motions.

Iterative, so chains deeper than Python's recursion limit are fine, and each link is placed
once even in a malformed graph. Needs no Pinocchio model (``check`` uses it on files that
Pinocchio rejects) and no Pinocchio ``Data``, whose size grows with the square of the
joints. Pure: values in, arrays out.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.elements import ONE_AXIS_TYPES, Joint
from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]


def joint_motion(joint: Joint, value: float) -> FloatArray:
    """4x4 motion of a joint at ``value``: a rotation about, or a slide along, its axis.

    Rotation by angle t about unit axis k (Rodrigues): ``I + sin t K + (1 - cos t) K^2``.
    """
    motion = np.eye(4)
    if value == 0 or joint.type not in ONE_AXIS_TYPES:
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


def link_transforms(robot: RobotDescription,
                    values: Mapping[str, float] | None = None) -> dict[str, FloatArray]:
    """``transform_link_to_root`` (4x4) of every link the root reaches.

    Args:
        robot: The description.
        values: Joint name to position [rad or m], unchecked; others are zero.

    Returns:
        Link name to transform; empty when the robot has no single root link.
    """
    config = values or {}
    root = robot.root_link
    if root is None:
        return {}
    children: dict[str, list[Joint]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent or "", []).append(joint)
    transforms = {root: np.eye(4)}
    stack = [root]
    while stack:
        parent = stack.pop()
        for joint in children.get(parent, ()):
            if joint.child and joint.child not in transforms:
                motion = joint_motion(joint, config.get(joint.name, 0.0))
                transforms[joint.child] = transforms[parent] @ pose_matrix(joint.origin) @ motion
                stack.append(joint.child)
    return transforms
