"""``/tf`` and ``/tf_static`` (tf2_msgs/TFMessage) of a run, a piece at a time.

The base in ``odom`` as diff_drive_controller publishes it, every movable joint's transform
and every fixed joint's (once, latched) as robot_state_publisher does.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.rotations import quaternion_from_matrix
from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.bag import cdr
from servicebot_cli.simulate.bag import quaternions as rotations
from servicebot_cli.simulate.bag.byte_rows import ByteRows
from servicebot_cli.simulate.simulator import SimResult

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint

FloatArray = npt.NDArray[np.float64]
ODOM_FRAME = "odom"


def _transforms(frames: list[tuple[str, str]]) -> cdr.Layout:
    layout = cdr.Layout()
    layout.constant("<I", len(frames))
    for i, (parent, child) in enumerate(frames):
        layout.field(f"sec{i}", "<i4")
        layout.field(f"nanosec{i}", "<u4")
        layout.string(parent)
        layout.string(child)
        layout.field(f"translation{i}", "<f8", 3)
        layout.field(f"rotation{i}", "<f8", 4)
    return layout


def tf_messages(frames: list[tuple[str, str]], times: FloatArray,
                translations: list[FloatArray], quaternions: list[FloatArray]) -> ByteRows:
    """TFMessages of ``frames`` (parent, child) at ``times`` [s], one row each.

    ``translations[i]`` (n, 3) and ``quaternions[i]`` (n, 4) place frame ``i``'s child.
    """
    layout = _transforms(frames)
    records = layout.records(len(times))
    stamps = cdr.stamps_ns(times)
    sec, nanosec = stamps // 1_000_000_000, stamps % 1_000_000_000
    for i in range(len(frames)):
        records[f"sec{i}"] = sec
        records[f"nanosec{i}"] = nanosec
        records[f"translation{i}"] = translations[i]
        records[f"rotation{i}"] = quaternions[i]
    return cdr.rows(records)


def tf_base(result: SimResult, frames: tuple[str, str] | None = None) -> ByteRows:
    """The base in ``odom``, as the drive controller publishes it with its odometry.

    ``frames`` are the controller's odometry frame and base frame; None: ``odom`` and the
    root link.
    """
    odom = result.odometry
    zeros = np.zeros_like(odom.x_m)
    parent, child = frames or (ODOM_FRAME, result.body.root_link)
    return tf_messages([(parent, child)], odom.times_s,
                        [np.column_stack((odom.x_m, odom.y_m, zeros + odom.z_m))],
                        [rotations.yaw(odom.yaw_rad)])


@dataclass(frozen=True)
class _MovingJoint:
    """What does not change with a movable joint's position, as robot_state_publisher sends it.

    Attributes:
        frames: Parent and child link.
        offset_m: The origin's translation, shape (3,).
        axis: Unit axis in the joint frame, shape (3,).
        slide: Unit direction of a prismatic joint in the parent frame; None for others.
        fixed: The origin's rotation as a quaternion (x, y, z, w).
    """

    frames: tuple[str, str]
    offset_m: FloatArray
    axis: FloatArray
    slide: FloatArray | None
    fixed: FloatArray

    @classmethod
    def of(cls, joint: Joint) -> _MovingJoint:
        """The constants of URDF joint ``joint``."""
        axis = np.array(joint.axis, float) / np.linalg.norm(joint.axis)
        rotation = rpy_matrix(*joint.origin.rpy)
        return cls((joint.parent or "", joint.child or ""), np.array(joint.origin.xyz), axis,
                   rotation @ axis if joint.type == "prismatic" else None,
                   quaternion_from_matrix(rotation))


class JointTransforms:
    """Every movable joint's transform, as robot_state_publisher sends them.

    Each joint's constants are worked out at the first piece, for every piece of the run.
    """

    def __init__(self) -> None:
        self.names: tuple[str, ...] = ()
        self.joints: list[_MovingJoint] = []

    def __call__(self, result: SimResult) -> ByteRows:
        """The piece's messages, one a joint state sample."""
        joints = result.joints
        if tuple(joints.names) != self.names or not self.joints:
            self.names = tuple(joints.names)
            self.joints = [_MovingJoint.of(result.body.robot.joint(n)) for n in self.names]
        q = joints.positions  # (samples, joints)
        slides = np.array([j.slide is not None for j in self.joints], dtype=bool)
        turns = rotations.about_axis(np.array([j.axis for j in self.joints]).reshape(-1, 3),
                                     np.where(slides, 0.0, q))
        quaternions = rotations.multiply(np.array([j.fixed for j in self.joints]).reshape(-1, 4),
                                         turns)  # (samples, joints, 4)
        translations = [j.offset_m + (np.zeros((len(q), 3)) if j.slide is None
                                      else q[:, i, None] * j.slide)
                        for i, j in enumerate(self.joints)]
        return tf_messages([j.frames for j in self.joints], joints.times_s, translations,
                            [quaternions[:, i] for i in range(len(self.joints))])


def tf_static(result: SimResult) -> ByteRows:
    """Fixed joints, once at time 0 (in the first piece), latched (robot_state_publisher)."""
    static = [(f.parent, f.name, f.origin) for f in result.body.robot.fixed_frames]
    return tf_messages([(p, c) for p, c, _ in static], np.zeros(1 if result.first else 0),
                        [np.array(o.xyz)[None] for _, _, o in static],
                        [quaternion_from_matrix(rpy_matrix(*o.rpy))[None] for _, _, o in static])
