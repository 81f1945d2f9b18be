"""``/tf`` and ``/tf_static`` (tf2_msgs/TFMessage) of a run, a piece at a time.

The base in ``odom`` as diff_drive_controller publishes it, every movable joint's transform
and every fixed joint's (once, latched) as robot_state_publisher does, and the wheels' as
Gazebo's diff-drive plugin does.
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
from servicebot_cli.simulate.sensors import joint_states
from servicebot_cli.simulate.simulator import SimResult

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.robot import RobotDescription

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
        return cls._placed(joint, joint.parent or "", np.array(joint.origin.xyz, float),
                           rpy_matrix(*joint.origin.rpy))

    @classmethod
    def _placed(cls, joint: Joint, parent: str, offset_m: FloatArray,
                rotation: FloatArray) -> _MovingJoint:
        """``joint`` moving its child from ``parent``: its origin there (offset, rotation)."""
        axis = np.array(joint.axis, float) / np.linalg.norm(joint.axis)
        return cls((parent, joint.child or ""), offset_m, axis,
                   rotation @ axis if joint.type == "prismatic" else None,
                   quaternion_from_matrix(rotation))

    @classmethod
    def in_gazebo(cls, robot: RobotDescription, joint: Joint) -> _MovingJoint:
        """``joint`` from the link Gazebo merges its parent into, as Gazebo's model has it.

        Converting a URDF, Gazebo merges every link hanging from a fixed joint into that
        joint's parent (TurtleBot3's ``base_link`` into ``base_footprint``); the joint's parent
        is then that link, and its origin carries the fixed joints' offsets.
        """
        by_child = {j.child: j for j in robot.joints}
        parent, rotation = joint.parent or "", rpy_matrix(*joint.origin.rpy)
        offset = np.array(joint.origin.xyz, float)
        while (up := by_child.get(parent)) is not None and up.type == "fixed":
            above = rpy_matrix(*up.origin.rpy)
            offset, rotation = above @ offset + np.array(up.origin.xyz, float), above @ rotation
            parent = up.parent or ""
        return cls._placed(joint, parent, offset, rotation)


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
        return _joint_messages(self.joints, joints.times_s, joints.positions)


def _joint_messages(moving: list[_MovingJoint], times_s: FloatArray, q: FloatArray) -> ByteRows:
    """One TFMessage of all ``moving`` joints per sample, at ``q`` (samples, joints)."""
    slides = np.array([j.slide is not None for j in moving], dtype=bool)
    turns = rotations.about_axis(np.array([j.axis for j in moving]).reshape(-1, 3),
                                 np.where(slides, 0.0, q))
    quaternions = rotations.multiply(np.array([j.fixed for j in moving]).reshape(-1, 4),
                                     turns)  # (samples, joints, 4)
    translations = [j.offset_m + (np.zeros((len(q), 3)) if j.slide is None
                                  else q[:, i, None] * j.slide)
                    for i, j in enumerate(moving)]
    return tf_messages([j.frames for j in moving], times_s, translations,
                        [quaternions[:, i] for i in range(len(moving))])


class WheelTransform:
    """A drive wheel's parent -> wheel transform, as Gazebo's diff-drive plugin sends it.

    ``gazebo_ros_diff_drive`` (``<publish_wheel_tf>``, ROS 1 ``<publishWheelTF>``) sends one
    transform per wheel joint at each of its updates, the odometry's times, stamped with
    simulated time: from the joint's parent link in Gazebo's model (fixed joints merged:
    :meth:`_MovingJoint.in_gazebo`) to its child link, the wheel's pose in the model's frame
    at its angle then (the same as from the parent for a wheel on the root link; the
    simulator's wheels are). The joint's constants and its wheel are found at the first
    piece, for every piece of the run.
    """

    def __init__(self, joint: str) -> None:
        self.joint = joint
        self.moving: _MovingJoint | None = None
        self.side: tuple[int, int] | None = None  # its wheel angles' column and sign

    def __call__(self, result: SimResult) -> ByteRows:
        """The piece's messages, one an odometry time."""
        if self.moving is None:
            robot = result.body.robot
            self.moving = _MovingJoint.in_gazebo(robot, robot.joint(self.joint))
            wheel = next((w for w in result.body.geometry.wheels if w.joint == self.joint),
                         None)
            self.side = None if wheel is None else \
                (0 if wheel.side == "left" else 1, wheel.axis_sign)
        times = result.odometry.times_s
        angles = np.zeros(len(result.wheel_angles_rad)) if self.side is None else \
            self.side[1] * result.wheel_angles_rad[:, self.side[0]]
        sampled = joint_states.at_times((self.joint,), angles[:, None], result.plan.dt_s, times,
                                        result.first_tick)
        return _joint_messages([self.moving], times, sampled.positions)


def tf_static(result: SimResult) -> ByteRows:
    """Fixed joints, once at time 0 (in the first piece), latched (robot_state_publisher)."""
    static = [(f.parent, f.name, f.origin) for f in result.body.robot.fixed_frames]
    return tf_messages([(p, c) for p, c, _ in static], np.zeros(1 if result.first else 0),
                        [np.array(o.xyz)[None] for _, _, o in static],
                        [quaternion_from_matrix(rpy_matrix(*o.rpy))[None] for _, _, o in static])
