"""A xacro part that hangs from a link it does not define is an include (SB018), not a robot.

baxter's end effectors (rethink_ee_description, vendored under tests/realworld/parts) are
named ``<robot>`` files whose every link hangs from ``left_hand``, sent as a URDF fragment
at run time; checked alone they failed with SB103 and SB104. A robot with a root of its own
and a dangling joint, or a ``.urdf`` part, still fails.
"""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import REPO

NULL_GRIPPER = (REPO / "tests" / "realworld" / "parts" / "rethink_ee_description" / "urdf"
                / "null_gripper")
XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
PART = ('<link name="gripper"/><link name="tip"/>'
        '<joint name="mount" type="fixed"><parent link="hand"/><child link="gripper"/></joint>'
        '<joint name="end" type="fixed"><parent link="gripper"/><child link="tip"/></joint>')


def test_a_real_end_effector_fragment_is_a_part_not_a_broken_robot(run):
    for target in (NULL_GRIPPER, NULL_GRIPPER / "example_end_effector.urdf.xacro"):
        result = run("check", "urdf", target, "--format", "json", "--isolated")
        assert result.exit_code == 0, result.stdout
        (only,) = findings(result.stdout)
        assert only["code"] == "SB018" and only["severity"] == "info"
        assert "every link hangs from 'left_hand', which it does not define" in only["message"]


def test_a_robot_with_its_own_root_and_a_dangling_joint_still_fails(run, tmp_path):
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO_NS}><link name="base"/>{PART}</robot>\n')
    result = run("check", "urdf", robot, "--format", "json", "--isolated")
    assert result.exit_code == 1
    assert "SB103" in {f["code"] for f in findings(result.stdout)}


def test_a_part_with_two_missing_parents_or_as_urdf_still_fails(run, tmp_path):
    two = tmp_path / "two.urdf.xacro"
    two.write_text(f'<robot name="r" {XACRO_NS}>{PART}<link name="x"/><joint name="k" '
                   'type="fixed"><parent link="arm"/><child link="x"/></joint></robot>\n')
    plain = tmp_path / "part.urdf"
    plain.write_text(f'<robot name="r">{PART}</robot>\n')
    for path in (two, plain):
        result = run("check", "urdf", path, "--format", "json", "--isolated")
        assert result.exit_code == 1, path
        assert "SB103" in {f["code"] for f in findings(result.stdout)}
