"""Forward kinematics: where frames are for given joint values.

A pose is ``transform_frame_to_reference``, the 4x4 homogeneous transform that maps
coordinates in the frame to coordinates in the reference frame: its last column is the
frame's origin in the reference frame [m], its rotation block the frame's axes there.
Pure: a model, data and configurations in; transforms out.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics import rotations
from servicebot_cli.kinematics.frames import frame_ids

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.joint_space import JointSpace

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class FramePose:
    """The pose of one frame in a reference frame.

    Attributes:
        frame: The frame (a link).
        relative_to: The reference frame.
        matrix: ``transform_frame_to_reference``, shape (4, 4).
    """

    frame: str
    relative_to: str
    matrix: FloatArray = field(repr=False)

    @property
    def position_m(self) -> FloatArray:
        """The frame's origin in the reference frame [m], shape (3,)."""
        return self.matrix[:3, 3]

    @property
    def rpy_rad(self) -> FloatArray:
        """Roll, pitch, yaw [rad] of the frame in the reference frame (URDF convention)."""
        return rotations.rpy_from_matrix(self.matrix[:3, :3])

    @property
    def quaternion_xyzw(self) -> FloatArray:
        """The frame's orientation as a unit quaternion ``(x, y, z, w)``, ``w >= 0``."""
        return rotations.quaternion_from_matrix(self.matrix[:3, :3])


def transforms(model: pin.Model, data: pin.Data, q: FloatArray, frames: Sequence[int],
               reference: int) -> FloatArray:
    """``transform_frame_to_reference`` of each frame for configuration ``q``.

    Args:
        model: The Pinocchio model.
        data: Its data (overwritten).
        q: Configuration, shape (model.nq,).
        frames: Frame indices.
        reference: Index of the reference frame.

    Returns:
        Shape (len(frames), 4, 4).
    """
    import pinocchio as pin

    pin.forwardKinematics(model, data, q)
    # Pinocchio's data.oMf[i] is transform_frame_to_world for frame i.
    transform_reference_to_world = pin.updateFramePlacement(model, data, reference).copy()
    out = np.empty((len(frames), 4, 4))
    for k, frame in enumerate(frames):
        transform_frame_to_world = pin.updateFramePlacement(model, data, frame)
        out[k] = transform_reference_to_world.actInv(transform_frame_to_world).homogeneous
    return out


def frame_transforms(model: pin.Model, data: pin.Data, qs: FloatArray, frames: Sequence[int],
                     reference: int) -> FloatArray:
    """:func:`transforms` for many configurations: the same numbers, bit for bit.

    Only the forward pass and the asked frames are computed per configuration. When the
    reference is the root itself (its pose the identity at every ``q``), the product with
    its inverse, which would change nothing, is skipped.

    Args:
        model: The Pinocchio model.
        data: Its data (overwritten).
        qs: Configurations, shape (n, model.nq).
        frames: Frame indices.
        reference: Index of the reference frame.

    Returns:
        Shape (n, len(frames), 4, 4).
    """
    import pinocchio as pin

    forward_kinematics, place = pin.forwardKinematics, pin.updateFramePlacement
    out = np.empty((len(qs), len(frames), 4, 4))
    at_root = (model.frames[reference].parentJoint == 0
               and model.frames[reference].placement.isIdentity(0.0))
    for k, q in enumerate(qs):
        forward_kinematics(model, data, q)
        if at_root:
            for i, frame in enumerate(frames):
                out[k, i] = place(model, data, frame).homogeneous
            continue
        transform_reference_to_world = place(model, data, reference).copy()
        for i, frame in enumerate(frames):
            out[k, i] = transform_reference_to_world.actInv(place(model, data, frame)).homogeneous
    return out


def configurations(space: JointSpace, values: FloatArray) -> FloatArray:
    """``space.to_q`` of each row of ``values`` (one value per joint), shape (n, nq)."""
    qs = np.tile(space.neutral(), (len(values), 1))
    for i, kind in enumerate(space.types):
        start = space.idx_q[i]
        if kind == "continuous":  # (cos, sin) in q
            qs[:, start] = np.cos(values[:, i])
            qs[:, start + 1] = np.sin(values[:, i])
        else:
            qs[:, start] = values[:, i]
    return qs


def frame_poses(model: pin.Model, data: pin.Data, q: FloatArray, frames: Sequence[str],
                relative_to: str, known: Sequence[str] | None = None) -> list[FramePose]:
    """The pose of each named frame in frame ``relative_to``.

    Args:
        model: The Pinocchio model.
        data: Its data (overwritten).
        q: Configuration, shape (model.nq,).
        frames: Link names.
        relative_to: The reference link.
        known: Every link name, for suggestions (default: the model's body frames).

    Raises:
        FrameNotFound: A name that is not a link, with the nearest names.
    """
    import pinocchio as pin

    if known is None:
        known = [f.name for f in model.frames if f.type == pin.FrameType.BODY]
    *ids, reference = frame_ids(model, [*frames, relative_to], known)
    matrices = transforms(model, data, q, ids, reference)
    return [FramePose(name, relative_to, m) for name, m in zip(frames, matrices, strict=True)]


def pose_table(matrices: FloatArray) -> FloatArray:
    """Position, roll-pitch-yaw and quaternion of a stack of transforms, vectorised.

    Args:
        matrices: Shape (..., 4, 4).

    Returns:
        Shape (..., 10): ``x, y, z`` [m], ``roll, pitch, yaw`` [rad], ``qx, qy, qz, qw``.
    """
    rotation = matrices[..., :3, :3]
    return np.concatenate([matrices[..., :3, 3], rotations.rpy_from_matrix(rotation),
                           rotations.quaternion_from_matrix(rotation)], axis=-1)
