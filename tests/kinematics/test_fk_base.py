"""``fk --base X Y YAW``: poses in the world, held against Pinocchio's own planar-base model."""

from __future__ import annotations

import json
import math

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.description.loader import RobotSource, load
from tests.conftest import SIM_URDF, assert_one_line_error

ARM = {"arm_base_to_link1": 0.4, "arm_link1_to_link2": -0.3, "arm_link3_to_link4": 0.8}


def world_pose(frame: str, x: float, y: float, yaw: float) -> pin.SE3:
    """The frame in the world, by Pinocchio on the model with a planar root joint."""
    robot = load(RobotSource.of(SIM_URDF))
    model = robot.model_with_base("planar")
    q = pin.neutral(model)
    q[:4] = x, y, math.cos(yaw), math.sin(yaw)
    for name, value in ARM.items():
        q[model.joints[model.getJointId(name)].idx_q] = value
    data = model.createData()
    pin.framesForwardKinematics(model, data, q)
    return data.oMf[model.getFrameId(frame)]


def joint_args(deg: bool = False) -> list[str]:
    return [a for name, v in ARM.items()
            for a in ("-j", f"{name}={math.degrees(v) if deg else v}")]


@pytest.mark.parametrize("deg", [False, True])
def test_poses_are_in_the_world_where_the_base_stands(run, deg):
    yaw = 2.5
    result = run("fk", "--base", "1.5", "-2", str(math.degrees(yaw) if deg else yaw),
                 *joint_args(deg), "-f", "arm_tool_link", "-f", "camera_link",
                 *(["--deg"] if deg else []), "--format", "json")
    answer = json.loads(result.stdout)
    assert answer["relative_to"] == "world"
    for pose in answer["poses"]:
        expected = world_pose(pose["frame"], 1.5, -2.0, yaw)
        np.testing.assert_allclose(pose["matrix"], expected.homogeneous, atol=1e-9)
        assert pose["frame"] in ("arm_tool_link", "camera_link")


def test_batch_lines_are_placed_where_the_base_stands(run, tmp_path):
    configs = tmp_path / "q.csv"
    configs.write_text(",".join(ARM) + "\n" + ",".join(map(str, ARM.values())) + "\n")
    (row,) = [json.loads(r) for r in run("fk", "--configs", configs, "--base", "0.5", "0.5",
                                         "-1", "--format", "json").stdout.splitlines()]
    expected = world_pose("arm_tool_link", 0.5, 0.5, -1.0)
    np.testing.assert_allclose(row["poses"][0]["position_m"], expected.translation, atol=1e-9)


def test_the_text_answer_says_world(run):
    assert run("fk", "--base", "1", "0", "0").stdout.startswith("arm_tool_link in world")


@pytest.mark.parametrize(("args", "needle"), [
    (("--base", "1", "0", "0", "--relative-to", "arm_link2"), "--relative-to"),
    (("--base", "1", "nan", "0"), "--base"),
    (("--base", "1", "0"), "--base"),
])
def test_bad_base_options_are_one_line(run, args, needle):
    assert_one_line_error(run("fk", *args), 2, needle)
