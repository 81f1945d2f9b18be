"""``fk`` as one call: a request in, the poses and the notes about them out. No click.

Nothing is printed. The command turns its options into a :class:`FkRequest`; :func:`run`
loads the robot (through the shared loader), picks the frames, checks the joint values and
computes the poses; ``output.poses`` renders the :class:`FkResult`. Batch mode
(``--configs``) shares :class:`FrameQuery` and :func:`resolve_frames` (see ``batch.fk``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.forward import FramePose, frame_poses
from servicebot_cli.kinematics.frames import link_names, pick_frame
from servicebot_cli.kinematics.mimics import Mimics
from servicebot_cli.kinematics.transforms import planar_matrix
from servicebot_cli.kinematics.user_joints import (
    clamped_user_vector,
    unnamed_outside,
    user_values,
)

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
WORLD = "world"
"""The name poses are in when ``--base`` says where the robot stands."""


@dataclass(frozen=True)
class FrameQuery:
    """Which frames to place, in which frame, and how joint values are read.

    Attributes:
        robot: The description to load.
        frames: Links to place; empty: the arm's tool frame.
        all_frames: Every link instead (one table).
        relative_to: The reference link; None: the root link.
        deg: Angles in degrees, in and out.
        clamp: Clamp joint values outside their limits instead of refusing them.
        base: Where the root link stands in the world: ``x`` [m], ``y`` [m], ``yaw``
            [rad, or deg with ``deg``]; poses are then in the world. None: in the reference.
    """

    robot: RobotSource
    frames: tuple[str, ...] = ()
    all_frames: bool = False
    relative_to: str | None = None
    deg: bool = False
    clamp: bool = False
    base: tuple[float, float, float] | None = None

    def transform_root_to_world(self) -> FloatArray | None:
        """The planar pose :attr:`base` as a 4 x 4 transform; None without a base."""
        if self.base is None:
            return None
        x_m, y_m, yaw = self.base
        return planar_matrix(x_m, y_m, math.radians(yaw) if self.deg else yaw)


@dataclass(frozen=True)
class FkRequest:
    """One configuration's poses.

    Attributes:
        query: The frames and units.
        joints: ``(name, value)`` pairs in the user's units; unnamed joints stay at zero.
    """

    query: FrameQuery
    joints: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class FkResult:
    """The poses of one configuration.

    Attributes:
        robot: The robot's name.
        relative_to: The reference frame.
        poses: One per frame asked for, in order.
        joints: Every movable joint's value in the user's units.
        deg: Angles in degrees.
        as_table: Every frame was asked for: shown as one table.
        notes: Lines for stderr: the frame picked, joints outside their limits, clamps.
    """

    robot: str
    relative_to: str
    poses: tuple[FramePose, ...]
    joints: Mapping[str, float] = field(repr=False)
    deg: bool = False
    as_table: bool = False
    notes: tuple[str, ...] = ()


def resolve_frames(robot: RobotDescription,
                   query: FrameQuery) -> tuple[tuple[str, ...], str, tuple[str, ...]]:
    """The frames to place, the reference frame, and notes on the frame picked.

    Raises:
        FrameNotFound: A frame or reference that is not a link, with the nearest names.
    """
    notes: list[str] = []
    if query.all_frames:
        frames = link_names(robot)
    else:
        picks = [pick_frame(robot, name) for name in query.frames] or [pick_frame(robot, None)]
        frames = tuple(name for name, _ in picks)
        notes.extend(note for _, note in picks if note)
    reference, _ = pick_frame(robot, query.relative_to or robot.root_link or "")
    return frames, reference, tuple(notes)


def run(request: FkRequest) -> FkResult:
    """The poses of the request's frames for its joint values.

    Raises:
        DescriptionError: The robot cannot be loaded.
        FrameNotFound: A frame that is not a link.
        JointNotFound: A joint the robot does not have.
        OutOfLimits: A value outside its joint's limits, without ``clamp``.
    """
    query = request.query
    robot = load(query.robot)
    frames, reference, notes = resolve_frames(robot, query)
    space = robot.joint_space
    mimics = Mimics.of(robot.joints, space)
    values, clamped = clamped_user_vector(space, request.joints, deg=query.deg,
                                          clamp=query.clamp, mimics=mimics,
                                          fixed=robot.unvalued_joints)
    shown = user_values(space, values, deg=query.deg)
    for follower, leader, made in mimics.overridden(values, (n for n, _ in request.joints),
                                                    space):
        as_made = values.copy()
        as_made[space.index(follower)] = made
        made_shown = user_values(space, as_made, deg=query.deg)[follower]
        notes += (f"note: joint '{follower}' follows '{leader}' (<mimic>), which makes it "
                  f"{made_shown:g}; the {shown[follower]:g} given is used, as "
                  "robot_state_publisher takes a value from joint_states",)
    outside = unnamed_outside(space, values)
    if outside:
        notes += (f"note: {', '.join(outside)} not given: 0, outside the limits "
                  f"(give {outside[0]}=VALUE for a reachable pose)",)
    poses = frame_poses(robot.model, robot.data, space.to_q(values), frames, reference,
                        link_names(robot))
    in_world = query.transform_root_to_world()
    if in_world is not None:
        reference = WORLD
        poses = [FramePose(p.frame, WORLD, in_world @ p.matrix) for p in poses]
    return FkResult(robot.name, reference, tuple(poses), shown, query.deg, query.all_frames,
                    notes + tuple(c.note() for c in clamped))
