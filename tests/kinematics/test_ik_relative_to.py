"""``ik --relative-to FRAME``: targets in another frame, checked by Pinocchio on the URDF itself.

The reference here is Pinocchio's own URDF parser and forward kinematics on the same file,
with the frame's pose taken at the start configuration the command was given.
"""

from __future__ import annotations

import json

import numpy as np
import pinocchio as pin
import pytest

from tests.conftest import SIM_URDF, assert_one_line_error

MODEL = pin.buildModelFromUrdf(str(SIM_URDF))


def pose(frame: str, joints: dict[str, float]) -> pin.SE3:
    """``frame`` in the root link's frame at ``joints`` (others zero), by Pinocchio."""
    q = pin.neutral(MODEL)
    for name, value in joints.items():
        q[MODEL.joints[MODEL.getJointId(name)].idx_q] = value
    data = MODEL.createData()
    pin.framesForwardKinematics(MODEL, data, q)
    return data.oMf[MODEL.getFrameId(frame)]


def solved(result) -> dict[str, float]:
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["joints"]


REACHED = {"arm_base_to_link1": 0.3, "arm_link1_to_link2": -0.4, "arm_link2_to_link3": 0.9,
           "arm_link3_to_link4": 0.2}


@pytest.mark.parametrize("frame", ["arm_base_link", "camera_link", "base_link"])
def test_a_full_pose_given_in_a_frame_is_reached_there(run, frame):
    goal = pose(frame, {}).actInv(pose("arm_tool_link", REACHED))
    rpy = pin.rpy.matrixToRpy(goal.rotation)
    joints = solved(run("ik", "--relative-to", frame, "--position", *goal.translation,
                        "--rpy", *rpy, "--seed", "2", "--format", "json"))
    reached = pose(frame, {}).actInv(pose("arm_tool_link", joints))
    np.testing.assert_allclose(reached.translation, goal.translation, atol=1e-6)
    assert np.linalg.norm(pin.log3(reached.rotation.T @ goal.rotation)) < 1e-6


def test_a_frame_the_arm_moves_stands_where_the_start_puts_it(run):
    start = {"arm_base_to_link1": 0.5, "arm_link1_to_link2": 0.3}
    frame = pose("arm_link2", start)
    goal_in_root = pose("arm_tool_link", REACHED).translation
    given = frame.actInv(goal_in_root)
    answer = run("ik", "--relative-to", "arm_link2", "--position", *given, "--seed", "1",
                 *(a for n, v in start.items() for a in ("--start", f"{n}={v}")),
                 "--format", "json")
    assert json.loads(answer.stdout)["relative_to"] == "arm_link2"
    np.testing.assert_allclose(pose("arm_tool_link", solved(answer)).translation, goal_in_root,
                               atol=1e-6)


def test_batch_targets_are_in_the_frame_too(run, tmp_path):
    goal = pose("arm_base_link", {}).actInv(pose("arm_tool_link", REACHED))
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n" + ",".join(repr(float(v)) for v in goal.translation) + "\n")
    result = run("ik", "--relative-to", "arm_base_link", "--targets", targets, "--seed", "1",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    joints = json.loads(result.stdout.splitlines()[0])["joints"]
    reached = pose("arm_base_link", {}).actInv(pose("arm_tool_link", joints))
    np.testing.assert_allclose(reached.translation, goal.translation, atol=1e-6)


def test_free_angles_about_a_turned_frame_are_refused(run):
    result = run("ik", "--relative-to", "arm_link2", "--start", "arm_link1_to_link2=0.5",
                 "--position", "0.2", "0", "0.1", "--rpy", "0", "1", "0",
                 "--orientation-axes", "pitch")
    assert_one_line_error(result, 2, "turned")


def test_an_unknown_frame_names_the_nearest(run):
    assert_one_line_error(run("ik", "--relative-to", "camra_link", "--position", "0.4", "0",
                              "0.2"), 2, "camera_link")
