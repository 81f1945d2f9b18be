"""ik on a robot whose fixed joint shares its child link's name, on a branch the chain locks.

URDF allows it and real robots do it: baxter_description names the fixed joint that holds
link ``left_hand`` ``left_hand`` too, and the gripper hangs from that link. Pinocchio then
has two frames ``left_hand``, and ``buildReducedModel`` (which locks the other arm) raised
``Several frames match the filter``: ``ik`` ended with an internal error (exit 3).
"""

from __future__ import annotations

import json

import numpy as np

INERTIA = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
           'ixz="0" iyz="0"/></inertial>')


def _joint(name: str, kind: str, parent: str, child: str, extra: str = "") -> str:
    limit = ('<limit lower="-3" upper="3" effort="10" velocity="1"/>' if kind == "revolute"
             else "")
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            f"{extra}{limit}</joint>")


def _arm(side: str, y_m: float) -> str:
    """An arm like baxter's: shoulder, elbow, a fixed 'hand' joint to link 'hand', a gripper."""
    return "".join((
        f'<link name="{side}_upper">{INERTIA}</link><link name="{side}_lower">{INERTIA}</link>',
        f'<link name="{side}_hand"/><link name="{side}_gripper"/>',
        _joint(f"{side}_s0", "revolute", "torso", f"{side}_upper",
               f'<origin xyz="0 {y_m} 0.5"/><axis xyz="0 0 1"/>'),
        _joint(f"{side}_e0", "revolute", f"{side}_upper", f"{side}_lower",
               '<origin xyz="0.3 0 0"/><axis xyz="0 1 0"/>'),
        _joint(f"{side}_hand", "fixed", f"{side}_lower", f"{side}_hand",
               '<origin xyz="0.3 0 0"/>'),
        _joint(f"{side}_gripper_base", "fixed", f"{side}_hand", f"{side}_gripper",
               '<origin xyz="0.05 0 0"/>'),
    ))


def test_ik_solves_an_arm_beside_a_locked_arm_with_such_names(run, tmp_path):
    robot = tmp_path / "two_arms.urdf"
    robot.write_text(f'<robot name="two_arms"><link name="torso"/>{_arm("left", 0.3)}'
                     f'{_arm("right", -0.3)}</robot>\n')
    for frame in ("left_gripper", "right_hand"):
        result = run("ik", robot, "-f", frame, "--position", "0.60715391", "0.3", "0.33220106",
                     "--format", "json")
        assert result.exit_code in (0, 1), result.stderr
        assert "internal error" not in result.stderr
    result = run("ik", robot, "-f", "left_gripper", "--position", "0.60715391", "0.3", "0.33220106",
                 "--format", "json")
    assert result.exit_code == 0, result.stderr
    answer = json.loads(result.stdout)
    assert np.isfinite(answer["position_error_m"]) and answer["position_error_m"] < 1e-4


def test_a_moving_joint_named_like_its_link_on_the_locked_arm(run, tmp_path):
    # nao names each revolute joint as the link it moves (LAnklePitch moves LAnklePitch);
    # the joint's own frame must keep its name while the other arm is locked
    robot = tmp_path / "nao_like.urdf"
    arms = f'{_arm("left", 0.3)}{_arm("right", -0.3)}'
    for side in ("left", "right"):
        arms = arms.replace(f'name="{side}_e0"', f'name="{side}_lower"')
    robot.write_text(f'<robot name="nao_like"><link name="torso"/>{arms}</robot>\n')
    for frame in ("left_gripper", "right_gripper", "left_lower"):
        result = run("ik", robot, "-f", frame, "--position", "0.3", "0.3", "0.5",
                     "--format", "json")
        assert result.exit_code in (0, 1), result.stderr
        assert "internal error" not in result.stderr
    result = run("fk", robot, "-f", "left_gripper", "-j", "left_lower=0.5", "--format", "json")
    assert result.exit_code == 0, result.stderr
