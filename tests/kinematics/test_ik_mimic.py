"""``ik`` with joints that follow another (``<mimic>``): answers a robot can take.

Every answer is placed by yourdfpy, which sets each follower from its leader itself: an
answer whose followers do not follow lands elsewhere there.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import yourdfpy

from tests.conftest import assert_one_line_error
from tests.kinematics.robots import PANDA

# A tool kept level by a parallelogram: 'level' turns back what 'shoulder' turns
PARALLEL_ARM = """<?xml version="1.0"?>
<robot name="parallel_arm">
  <link name="base"/>
  <link name="upper"/><link name="fore"/><link name="hand"/><link name="tool"/>
  <joint name="yaw" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.15"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="5" velocity="2"/></joint>
  <joint name="shoulder" type="revolute"><parent link="upper"/><child link="fore"/>
    <axis xyz="0 1 0"/><limit lower="-1.5" upper="1.5" effort="5" velocity="2"/></joint>
  <joint name="level" type="revolute"><parent link="fore"/><child link="hand"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 1 0"/>
    <limit lower="LEVEL_LOWER" upper="1.5" effort="5" velocity="2"/>
    <mimic joint="shoulder" multiplier="-1" offset="0"/></joint>
  <joint name="wrist" type="revolute"><parent link="hand"/><child link="tool"/>
    <origin xyz="0.15 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="5" velocity="2"/></joint>
</robot>
"""


def _arm(tmp_path, level_lower="-1.5"):
    path = tmp_path / f"parallel_arm{level_lower}.urdf"
    path.write_text(PARALLEL_ARM.replace("LEVEL_LOWER", level_lower))
    return path


def _placed(path, joints, frame):
    """Where yourdfpy puts ``frame`` for ``joints`` (its followers set by yourdfpy)."""
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    urdf.update_cfg({n: v for n, v in joints.items() if n in urdf.actuated_joint_names})
    return urdf.get_transform(frame, urdf.base_link)[:3, 3]


def _ik(run, path, frame, position, *extra):
    result = run("ik", path, "-f", frame, "--position", *map(str, position), "--seed", "1",
                 "--format", "json", *extra)
    return result, json.loads(result.stdout)


def test_a_levelling_joint_turns_back_what_the_shoulder_turns(run, tmp_path):
    path = _arm(tmp_path)
    target = _placed(path, {"yaw": 0.2, "shoulder": -0.25}, "tool")
    result, answer = _ik(run, path, "tool", target)
    assert result.exit_code == 0, result.stderr
    joints = answer["joints"]
    assert joints["level"] == pytest.approx(-joints["shoulder"], abs=1e-12)
    assert joints["shoulder"] == pytest.approx(-0.25, abs=1e-6)  # the only way there
    assert _placed(path, joints, "tool") == pytest.approx(target, abs=1e-6)


def test_a_follower_s_limits_bound_its_leader(run, tmp_path):
    """level >= -0.2 means shoulder <= 0.2: a target only shoulder = 0.5 reaches is refused."""
    path = _arm(tmp_path, level_lower="-0.2")
    target = _placed(_arm(tmp_path), {"shoulder": 0.5}, "tool")
    result, answer = _ik(run, path, "tool", target)
    assert result.exit_code == 1 and not answer["success"]
    joints = answer["joints"]
    assert joints["level"] >= -0.2 - 1e-12 and joints["shoulder"] <= 0.2 + 1e-12
    assert joints["level"] == pytest.approx(-joints["shoulder"], abs=1e-12)
    reachable = _placed(path, {"shoulder": 0.1, "yaw": -0.4}, "tool")
    assert _ik(run, path, "tool", reachable)[0].exit_code == 0


def test_panda_fingers_open_together_when_a_finger_is_the_frame(run):
    """panda_finger_joint2 mimics panda_finger_joint1; only joint2 moves the right finger."""
    rng = np.random.default_rng(3)
    arm = {f"panda_joint{k}": v for k, v in
           enumerate([0.3, -0.4, 0.2, -2.0, 0.1, 1.6, 0.5] + rng.uniform(-0.1, 0.1, 7), 1)}
    target = _placed(PANDA, {**arm, "panda_finger_joint1": 0.01}, "panda_rightfinger")
    result, answer = _ik(run, PANDA, "panda_rightfinger", target,
                         "--start", "panda_finger_joint1=0.03")
    assert result.exit_code == 0, result.stderr
    _assert_fingers_together_at(answer["joints"], target)


def test_batch_answers_keep_the_fingers_together(run, tmp_path):
    """Targets in series go through the compiled loop: its answers are completed the same."""
    targets = tmp_path / "targets.csv"
    rows = [_placed(PANDA, {"panda_joint4": -2.0 + 0.05 * k, "panda_joint6": 1.5,
                            "panda_finger_joint1": 0.004 * k}, "panda_rightfinger")
            for k in range(6)]
    targets.write_text("x_m,y_m,z_m\n" + "".join(",".join(map(str, r)) + "\n" for r in rows))
    out = tmp_path / "answers.jsonl"
    result = run("ik", PANDA, "-f", "panda_rightfinger", "--targets", targets, "-o", out,
                 "--seed", "2", "--start", "panda_finger_joint1=0.02")
    assert result.exit_code == 0, result.stderr
    answers = [json.loads(line) for line in out.read_text().splitlines()]
    assert len(answers) == 6 and all(a["success"] for a in answers)
    for answer, target in zip(answers, rows, strict=True):
        _assert_fingers_together_at(answer["joints"], target)


def _assert_fingers_together_at(joints, target):
    """Panda's fingers apart by the same amount, the right one at ``target`` (by yourdfpy)."""
    assert joints["panda_finger_joint2"] == pytest.approx(joints["panda_finger_joint1"],
                                                          abs=1e-12)
    assert _placed(PANDA, joints, "panda_rightfinger") == pytest.approx(target, abs=1e-6)


def test_a_follower_with_multiplier_zero_stands_at_its_offset(run, tmp_path):
    path = tmp_path / "standing.urdf"
    path.write_text(PARALLEL_ARM.replace("LEVEL_LOWER", "-1.5")
                    .replace('multiplier="-1" offset="0"', 'multiplier="0" offset="0.3"'))
    target = _placed(path, {"yaw": -0.1, "shoulder": 0.4}, "tool")
    result, answer = _ik(run, path, "tool", target)
    assert result.exit_code == 0, result.stderr
    assert answer["joints"]["level"] == pytest.approx(0.3, abs=1e-12)
    assert _placed(path, answer["joints"], "tool") == pytest.approx(target, abs=1e-6)


def test_a_follower_of_a_follower_and_a_loop_resolve_to_one_value():
    from servicebot_cli.kinematics.chain_mimic import Groups
    from servicebot_cli.kinematics.mimics import Mimics

    # 1 = 2 * 0 + 1; 2 = -1 * 1 + 0.5: so 2 = -2 * 0 - 0.5. 3 and 4 follow each other.
    groups = Groups.of(Mimics((1, 2, 3, 4), (0, 1, 4, 3), (2.0, -1.0, 3.0, 5.0),
                              (1.0, 0.5, 0.0, 0.0)), 5)
    assert groups.root[:3] == (0, 0, 0)
    assert groups.factor[:3].tolist() == [1.0, 2.0, -2.0]
    assert groups.offset[:3].tolist() == [0.0, 1.0, -0.5]
    assert groups.members(2) == [0, 1, 2]
    assert sorted(groups.members(3)) == [3, 4] and len({groups.root[3], groups.root[4]}) == 1


@pytest.mark.parametrize(("change", "needle"), [
    (('name="level" type="revolute"', 'name="level" type="continuous"'), "is continuous"),
    (('<axis xyz="0 1 0"/><limit lower="-1.5"', '<axis xyz="0 1 0"/><limit lower="0.5"'),
     "limits no value of it meets"),  # level = -shoulder <= -0.5, below its -0.2
])
def test_couplings_ik_cannot_solve_are_one_line(run, tmp_path, change, needle):
    path = _arm(tmp_path, "-0.2")
    path.write_text(path.read_text().replace(*change))
    result = run("ik", path, "-f", "tool", "--position", "0.3", "0", "0.2")
    assert_one_line_error(result, 2, "'shoulder'", needle)


def test_limits_that_leave_one_value_hold_the_joints_there(run, tmp_path):
    """shoulder in [0, 1.5] and level = -shoulder in [0, 1.5]: only 0 (PR2's gripper has it).

    A target out of reach makes ik restart from random values within those limits (drawn
    one by one: the continuous wrist makes the chain's q more than its angles).
    """
    path = _arm(tmp_path, "0")
    path.write_text(path.read_text().replace('<axis xyz="0 1 0"/><limit lower="-1.5"',
                                             '<axis xyz="0 1 0"/><limit lower="0"')
                    .replace('name="wrist" type="revolute"', 'name="wrist" type="continuous"'))
    result, answer = _ik(run, path, "tool", _placed(path, {"yaw": 0.5}, "tool"))
    assert result.exit_code == 0, result.stderr
    assert answer["joints"]["shoulder"] == 0.0 and answer["joints"]["level"] == 0.0
    result, answer = _ik(run, path, "tool", _placed(_arm(tmp_path), {"shoulder": 0.4}, "tool"))
    assert result.exit_code == 1 and answer["attempts"] > 1
    assert answer["joints"]["shoulder"] == 0.0 and answer["joints"]["level"] == 0.0


def test_a_frame_only_a_standing_follower_moves_is_one_line(run, tmp_path):
    path = tmp_path / "stand.urdf"
    path.write_text("""<robot name="stand"><link name="base"/><link name="tip"/><link name="b"/>
  <joint name="lead" type="revolute"><parent link="base"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="stands" type="revolute"><parent link="base"/><child link="tip"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1"
    velocity="1"/><mimic joint="lead" multiplier="0" offset="0.3"/></joint></robot>""")
    result = run("ik", path, "-f", "tip", "--position", "0.2", "0", "0.1")
    assert_one_line_error(result, 2, "frame 'tip' moves only with joints that stand at "
                          "their <mimic> offset")


def test_a_bounded_follower_of_a_continuous_leader_is_one_line(run, tmp_path):
    path = _arm(tmp_path)
    path.write_text(path.read_text().replace('name="shoulder" type="revolute"',
                                             'name="shoulder" type="continuous"'))
    result = run("ik", path, "-f", "tool", "--position", "0.3", "0", "0.2")
    assert_one_line_error(result, 2, "joint 'level' follows continuous joint 'shoulder'")


def test_a_start_given_to_the_leader_starts_the_follower_solved_for(run):
    """Panda's right finger moves with panda_finger_joint2, which follows joint1: a start
    of joint1 is where the search begins (it began at joint2's 0)."""
    start = {"panda_joint4": -2.0, "panda_joint6": 1.5, "panda_finger_joint1": 0.03}
    target = _placed(PANDA, start, "panda_rightfinger")
    result, answer = _ik(run, PANDA, "panda_rightfinger", target,
                         *(f"--start={k}={v}" for k, v in start.items()))
    assert result.exit_code == 0, result.stderr
    assert answer["joints"]["panda_finger_joint2"] == pytest.approx(0.03, abs=1e-9)
