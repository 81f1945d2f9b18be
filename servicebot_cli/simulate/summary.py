"""What a run comes to: distance, final poses, odometry drift, contacts, clearance, counts.

The summary is what ``summary.json`` holds and ``--format json`` prints (keys documented in
README.md). It carries no wall-clock time, so the same seed gives the same bytes. It is
gathered a piece of the run at a time (:class:`Summarizer`); the distance is summed in tick
order, so it does not depend on where the pieces split the run.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TypedDict

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import planar_matrix
from servicebot_cli.simulate.bag.ros_messages import Publisher
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.simulator import SimResult
from servicebot_cli.simulate.world.motion import Contact, pose_at

FloatArray = npt.NDArray[np.float64]


class Pose(TypedDict):
    """A pose on the floor in the world frame; yaw wrapped to [-pi, pi]."""

    x_m: float
    y_m: float
    yaw_rad: float


class Drift(TypedDict):
    """How far wheel odometry is from the ground truth."""

    final_position_m: float
    max_position_m: float
    final_yaw_rad: float


class Collision(TypedDict):
    """Where and when a link touched an obstacle (the base's pose then)."""

    time_s: float
    obstacle: str
    link: str
    x_m: float
    y_m: float
    yaw_rad: float


class SelfCollision(TypedDict):
    """From ``time_s`` on, link ``first`` touches ``second`` (another link, or ``floor``)."""

    time_s: float
    first: str
    second: str


class EndEffector(TypedDict):
    """The arm's last frame and its world position [m] at the end."""

    frame: str
    position_m: list[float]


class Summary(TypedDict):
    """The run's summary: ``summary.json`` and ``--format json`` (keys in README.md)."""

    robot: str
    scenario: str
    seed: int
    duration_s: float
    distance_m: float
    final_pose: Pose
    odometry_final_pose: Pose | None
    odometry_drift: Drift
    odometry_published_on: list[str]
    collisions: list[Collision]
    self_collisions: list[SelfCollision]
    min_obstacle_distance_m: float
    closest_obstacle: str | None
    closest_link: str | None
    closest_time_s: float | None
    arm_final_positions_rad: dict[str, float]
    end_effector: EndEffector | None
    messages: dict[str, int]
    controller: dict[str, ControllerValue]


class ControllerValue(TypedDict):
    """One controller parameter: its value (None: no limit) and where it came from."""

    value: float | str | list[float] | None
    source: str


def _pose(x: float, y: float, yaw: float) -> Pose:
    return {"x_m": float(x), "y_m": float(y), "yaw_rad": float(math.remainder(yaw, math.tau))}


def odometry_in_world(result: SimResult) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The odometry estimate in the world frame.

    Dead reckoning's ``odom`` frame starts at the initial pose; odometry from the world
    (Gazebo Classic's WORLD source) is in the world already.
    """
    start, odom = result.scenario.initial_pose, result.odometry
    if odom.in_world:
        return odom.x_m, odom.y_m, odom.yaw_rad
    c, s = math.cos(start.yaw_rad), math.sin(start.yaw_rad)
    return (start.x_m + c * odom.x_m - s * odom.y_m, start.y_m + s * odom.x_m + c * odom.y_m,
            start.yaw_rad + odom.yaw_rad)


def odometry_drift(result: SimResult) -> tuple[FloatArray, FloatArray]:
    """Position error [m] and yaw error [rad] of each odometry sample against the truth."""
    ox, oy, oyaw = odometry_in_world(result)
    tx, ty, tyaw = pose_at(result.truth, result.odometry.times_s)
    return np.hypot(ox - tx, oy - ty), oyaw - tyaw


class Summarizer:
    """The summary of a run, gathered from its pieces in order."""

    def __init__(self, publishers: list[Publisher], odometry_on: Sequence[str] = ()) -> None:
        """A summary of a run whose publishers are ``publishers``.

        ``odometry_on``: where the base's controller publishes its odometry (its topic,
        /tf); none: the run's wheel odometry is the simulator's alone.
        """
        self.publishers = publishers
        self.odometry_on = list(odometry_on)
        self.messages = dict.fromkeys((p.topic for p in publishers), 0)
        self.distance_sum = -0.0  # -0.0 + v == v: an empty running sum
        self.max_drift, self.final_drift = 0.0, (0.0, 0.0)
        self.odometry_pose: Pose | None = None
        self.contacts: list[Contact] = []
        self.self_collisions: list[SelfCollision] = []
        self.last: SimResult | None = None

    def add(self, piece: SimResult) -> None:
        """Count in the next piece of the run."""
        truth = piece.truth
        steps = np.hypot(np.diff(truth.x_m), np.diff(truth.y_m))
        self.distance_sum = float(np.cumsum(np.concatenate(([self.distance_sum], steps)))[-1])
        if len(piece.odometry.times_s):
            drift, yaw = odometry_drift(piece)
            ox, oy, oyaw = odometry_in_world(piece)
            self.max_drift = max(self.max_drift, float(drift.max()))
            self.final_drift = (float(drift[-1]), float(yaw[-1]))
            self.odometry_pose = _pose(ox[-1], oy[-1], oyaw[-1])
        self.contacts += piece.contacts
        self.self_collisions += [{"time_s": c.time_s, "first": c.first, "second": c.second}
                                 for c in piece.self_contacts]
        for publisher in self.publishers:
            self.messages[publisher.topic] += len(publisher.times(piece))
        self.last = piece

    def summary(self) -> Summary:
        """The summary of the pieces added; the last one must end the run."""
        last = self.last
        assert last is not None and last.last, "a summary needs the whole run"
        truth, closest = last.truth, last.closest
        return {
            "robot": last.body.robot.name,
            "scenario": last.scenario.name,
            "seed": last.seed,
            "duration_s": last.scenario.duration_s,
            "distance_m": self.distance_sum + 0.0,
            "final_pose": _pose(truth.x_m[-1], truth.y_m[-1], truth.yaw_rad[-1]),
            "odometry_final_pose": self.odometry_pose,
            "odometry_drift": {
                "final_position_m": self.final_drift[0],
                "max_position_m": self.max_drift,
                "final_yaw_rad": float(abs(math.remainder(self.final_drift[1], math.tau))),
            },
            "odometry_published_on": self.odometry_on,
            "collisions": [_collision(c) for c in self.contacts],
            "self_collisions": self.self_collisions,
            "min_obstacle_distance_m": 0.0 if self.contacts else closest.distance_m,
            "closest_obstacle": last.obstacle_names[closest.obstacle]
            if closest.obstacle >= 0 else None,
            "closest_link": last.body.shape.parts[closest.part].link
            if closest.part >= 0 else None,
            "closest_time_s": closest.index * truth.dt_s if closest.index >= 0 else None,
            "arm_final_positions_rad": dict(zip(last.body.arm_joints,
                                                last.arm_positions_rad[-1].tolist(),
                                                strict=True)),
            "end_effector": end_effector(last),
            "messages": dict(self.messages),
            "controller": _controller(last),
        }


def _controller(result: SimResult) -> dict[str, ControllerValue]:
    """Each controller parameter the run used and its source (file, scenario, ...)."""
    controller = result.scenario.controller
    out: dict[str, ControllerValue] = {}
    for name, source in result.scenario.controller_from:
        value = getattr(controller, name)
        shown = (list(value) if isinstance(value, tuple) else
                 None if isinstance(value, float) and math.isinf(value) else value)
        out[name] = {"value": shown, "source": source}
    return out


def _collision(contact: Contact) -> Collision:
    pose = _pose(contact.x_m, contact.y_m, contact.yaw_rad)
    return {"time_s": contact.time_s, "obstacle": contact.obstacle, "link": contact.link,
            "x_m": pose["x_m"],
            "y_m": pose["y_m"], "yaw_rad": pose["yaw_rad"]}


def end_effector(result: SimResult) -> EndEffector | None:
    """World position of the arm's last frame in the final configuration of the whole robot.

    The base's pose and the arm's joints are the last piece's (``result``), the arm where
    ``arm_final_positions_rad`` says. The frame is placed by the robot's shape, as every
    link the run poses (the same chain as Pinocchio's forward kinematics: a test holds them
    together).
    """
    body = result.body
    tip = _arm_tip(body)
    if tip is None:
        return None
    arm = result.arm_positions_rad[-1:]  # (1, arm joints), the shape's joints
    tip_to_base = body.shape.link_to_base(arm, tip)[0]
    base_to_world = planar_matrix(result.truth.x_m[-1], result.truth.y_m[-1],
                                  result.truth.yaw_rad[-1], body.base_height_m)
    position = (base_to_world @ tip_to_base)[:3, 3]
    return {"frame": tip, "position_m": position.tolist()}


def _arm_tip(body: SimRobot) -> str | None:
    """The first link below the arm joints that is no joint's parent (the end effector)."""
    robot = body.robot
    below = {robot.joint(n).child for n in body.arm_joints}
    changed = True
    while changed:
        changed = False
        for joint in robot.joints:
            if joint.parent in below and joint.child not in below:
                below.add(joint.child)
                changed = True
    parents = {j.parent for j in robot.joints}
    leaves = [link.name for link in robot.links if link.name in below and link.name not in parents]
    return leaves[0] if leaves else None
