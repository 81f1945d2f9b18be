"""Robots to test kinematics on: the bundled one, and UR5, Panda and Kinova's 6-DoF Jaco 2
from example-robot-data."""

from __future__ import annotations

from importlib.metadata import files
from pathlib import Path

import numpy as np
import pinocchio as pin

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.description.robot import RobotDescription
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.frames import link_names
from tests.conftest import SIM_URDF


def example_robot(relative: str) -> Path:
    """A URDF shipped in the example-robot-data wheel (the ``test`` extra)."""
    for entry in files("example-robot-data") or ():
        if str(entry).endswith(f"robots/{relative}"):
            return Path(entry.locate())
    raise FileNotFoundError(f"example-robot-data has no robots/{relative}")


UR5 = example_robot("ur_description/urdf/ur5_robot.urdf")
PANDA = example_robot("panda_description/urdf/panda.urdf")
JACO2 = example_robot("kinova_description/robots/kinova.urdf")  # continuous joints among them
# (URDF, tool frame) of each robot
ARMS = {"service": (SIM_URDF, "arm_tool_link"), "ur5": (UR5, "tool0"),
        "panda": (PANDA, "panda_hand_tcp"), "jaco2": (JACO2, "j2s6s200_end_effector"),
        "panda finger": (PANDA, "panda_leftfinger")}  # a prismatic joint last


def robot_and_chain(name: str) -> tuple[RobotDescription, Chain]:
    path, tool = ARMS[name]
    robot = load(RobotSource.of(path))
    return robot, Chain(robot.model, robot.joint_space, tool, link_names(robot))


def random_values(robot: RobotDescription, rng: np.random.Generator) -> np.ndarray:
    """One value per movable joint: uniform within limits, any angle for continuous ones."""
    space = robot.joint_space
    lower = np.where(np.isnan(space.lower), -np.pi, space.lower)
    upper = np.where(np.isnan(space.upper), np.pi, space.upper)
    return rng.uniform(lower, upper)


def tool_pose(robot: RobotDescription, frame: str, q: np.ndarray) -> pin.SE3:
    """transform_frame_to_root at ``q``, by Pinocchio on a fresh data."""
    data = robot.model.createData()
    pin.framesForwardKinematics(robot.model, data, q)
    return data.oMf[robot.model.getFrameId(frame)].copy()
