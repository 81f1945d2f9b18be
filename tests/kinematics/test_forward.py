"""FK agrees with an independent implementation (yourdfpy) to 1e-9 m, on three robots."""

from __future__ import annotations

import math

import numpy as np
import pytest
import yourdfpy

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.forward import frame_poses, pose_table, transforms
from servicebot_cli.kinematics.frames import default_tool_frame, link_names
from servicebot_cli.kinematics.mimics import Mimics
from tests.kinematics.robots import ARMS, random_values

CONFIGURATIONS = 40


@pytest.mark.parametrize("name", list(ARMS))
def test_every_link_agrees_with_yourdfpy(name):
    path, _ = ARMS[name]
    robot = load(RobotSource.of(path))
    space, links = robot.joint_space, list(link_names(robot))
    mimics = Mimics.of(robot.joints, space)
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    root = robot.root_link
    rng = np.random.default_rng(42)
    worst_m = worst_rad = 0.0
    for _ in range(CONFIGURATIONS):
        values = mimics.apply(random_values(robot, rng), [], space)
        urdf.update_cfg({n: v for n, v in zip(space.names, values, strict=True)
                         if n in urdf.actuated_joint_names})
        poses = frame_poses(robot.model, robot.data, space.to_q(values), links, root)
        for pose in poses:
            theirs = urdf.get_transform(pose.frame, root)
            worst_m = max(worst_m, float(np.abs(pose.matrix[:3, 3] - theirs[:3, 3]).max()))
            worst_rad = max(worst_rad, float(np.abs(pose.matrix[:3, :3] - theirs[:3, :3]).max()))
    assert worst_m < 1e-9 and worst_rad < 1e-9, (worst_m, worst_rad)


def test_bundled_arm_in_closed_form():
    """Yaw a, shoulder b: tool at shoulder + 0.9 m along the yawed, pitched x axis."""
    robot = load(RobotSource.bundled("sim"))
    space = robot.joint_space
    for a, b in [(0.0, 0.0), (0.7, -0.4), (-1.2, 1.1)]:
        values = space.vector({"arm_base_to_link1": a, "arm_link1_to_link2": b})
        [pose] = frame_poses(robot.model, robot.data, space.to_q(values), ["arm_tool_link"],
                             "base_link")
        reach = 0.9 * np.array([math.cos(a) * math.cos(b), math.sin(a) * math.cos(b),
                                -math.sin(b)])
        assert pose.position_m == pytest.approx(np.array([-0.1, 0, 0.6]) + reach, abs=1e-12)
        assert pose.rpy_rad == pytest.approx([0.0, b, a], abs=1e-12)


def test_relative_to_another_frame_is_the_inverse_composition():
    robot = load(RobotSource.bundled("sim"))
    space = robot.joint_space
    q = space.to_q(random_values(robot, np.random.default_rng(5)))
    tool, camera = frame_poses(robot.model, robot.data, q, ["arm_tool_link", "camera_link"],
                               "base_link")
    [relative] = frame_poses(robot.model, robot.data, q, ["arm_tool_link"], "camera_link")
    assert relative.matrix == pytest.approx(np.linalg.inv(camera.matrix) @ tool.matrix, abs=1e-12)
    [itself] = frame_poses(robot.model, robot.data, q, ["camera_link"], "camera_link")
    assert itself.matrix == pytest.approx(np.eye(4), abs=1e-12)


def test_pose_table_matches_the_pose_properties():
    robot = load(RobotSource.bundled("sim"))
    space, model = robot.joint_space, robot.model
    q = space.to_q(random_values(robot, np.random.default_rng(6)))
    ids = [model.getFrameId(n) for n in ("arm_link2", "arm_tool_link")]
    matrices = transforms(model, robot.data, q, ids, model.getFrameId("base_link"))
    table = pose_table(matrices[None])[0]
    poses = frame_poses(model, robot.data, q, ["arm_link2", "arm_tool_link"], "base_link")
    for row, pose in zip(table, poses, strict=True):
        assert row == pytest.approx(np.concatenate([pose.position_m, pose.rpy_rad,
                                                    pose.quaternion_xyzw]))


@pytest.mark.parametrize(("name", "tool"), [("service", "arm_tool_link"), ("ur5", "tool0"),
                                            ("panda", "panda_hand_tcp")])
def test_default_tool_frame(name, tool):
    choice = default_tool_frame(load(RobotSource.of(ARMS[name][0])))
    assert choice.name == tool and choice.obvious


@pytest.mark.parametrize("name", list(ARMS))
def test_frame_ids_in_one_pass_are_pinocchios_own(name):
    """``frame_ids`` (one pass over the frames) against Pinocchio's look-up, name by name."""
    from servicebot_cli.common.errors import FrameNotFound
    from servicebot_cli.kinematics.frames import frame_id, frame_ids

    robot = load(RobotSource.of(ARMS[name][0]))
    links = list(link_names(robot))
    assert frame_ids(robot.model, links[::-1], links) == [
        robot.model.getFrameId(link) for link in links[::-1]]
    assert frame_ids(robot.model, links, links) == [frame_id(robot.model, n, links)
                                                    for n in links]
    with pytest.raises(FrameNotFound):
        frame_ids(robot.model, [links[0], links[0] + "_typo"], links)
