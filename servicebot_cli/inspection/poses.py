"""Where every link is at a joint configuration, from the shared Pinocchio model.

A configuration is what a user types: ``{joint name: value}`` in [rad] or [m]; joints not
named stay at zero. Names and limits are checked by the foundation's JointSpace, so a wrong
name gets the same did-you-mean message as in every other command.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]


def configuration_q(robot: RobotDescription, values: Mapping[str, float], *,
                    clamp: bool = False) -> FloatArray:
    """Pinocchio ``q`` for ``values`` (joint name to [rad] or [m]); the rest at zero.

    Raises:
        JointNotFound: A name that is not a movable joint, with the closest names.
        OutOfLimits: A value outside its joint's limits (unless ``clamp``).
    """
    import pinocchio as pin

    space = robot.joint_space
    vector = space.vector(dict(values), clamp=clamp)
    return space.to_q(vector, q0=pin.neutral(robot.model))


def link_transforms(robot: RobotDescription, values: Mapping[str, float] | None = None, *,
                    clamp: bool = False) -> dict[str, FloatArray]:
    """``transform_link_to_root`` (4x4) of every link Pinocchio models, at ``values``.

    The root link is the identity: the fixed-base model's world frame.
    """
    import pinocchio as pin

    model = robot.model
    data = model.createData()
    pin.framesForwardKinematics(model, data, configuration_q(robot, values or {}, clamp=clamp))
    transforms: dict[str, FloatArray] = {}
    for frame_id, frame in enumerate(model.frames):
        if frame.type == pin.FrameType.BODY and frame.name not in transforms:
            # Pinocchio's data.oMf[i] is transform_frame_to_world for frame i.
            transforms[frame.name] = np.array(data.oMf[frame_id].homogeneous)
    return transforms
