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


INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
            'ixz="0" iyz="0"/></inertial>')
ARM = (f'<link name="base_link">{INERTIAL}</link><link name="link1">{INERTIAL}</link>'
       '<joint name="j1" type="revolute"><parent link="base_link"/><child link="link1"/>'
       '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')


def _assert_broken_robot(run, target) -> None:
    result = run("check", "urdf", target, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.stdout
    found = {f["code"] for f in findings(result.stdout)}
    assert "SB103" in found and "SB018" not in found, found


def test_a_robot_joined_to_a_world_it_does_not_define_fails_named_and_walked(run, tmp_path):
    # the shape of a part (no root of its own, one missing parent) is no evidence of one:
    # nothing includes this file, and simulate refuses it
    robot = tmp_path / "arm" / "arm.urdf.xacro"
    robot.parent.mkdir()
    robot.write_text(f'<?xml version="1.0"?>\n<robot name="arm" {XACRO_NS}>\n'
                     '<joint name="world_joint" type="fixed"><parent link="world"/>'
                     f'<child link="base_link"/></joint>\n{ARM}\n</robot>\n')
    _assert_broken_robot(run, robot)
    _assert_broken_robot(run, robot.parent)


def test_a_robot_whose_root_link_is_in_a_false_condition_fails(run, tmp_path):
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO_NS}><xacro:arg name="with_base" default="false"/>'
                     '<xacro:if value="$(arg with_base)"><link name="base"/></xacro:if>'
                     f'<link name="a">{INERTIAL}</link><joint name="j" type="fixed">'
                     '<parent link="base"/><child link="a"/></joint></robot>\n')
    _assert_broken_robot(run, robot)


def test_a_robot_built_by_a_macro_it_hands_its_missing_parent_fails(run, tmp_path):
    (tmp_path / "arm.xacro").write_text(
        f'<robot {XACRO_NS}><xacro:macro name="arm" params="parent">{ARM}'
        '<joint name="mount" type="fixed"><parent link="${parent}"/><child link="base_link"/>'
        '</joint></xacro:macro></robot>\n')
    for parent in ("world", "table"):
        robot = tmp_path / f"on_{parent}.urdf.xacro"
        robot.write_text(f'<robot name="r" {XACRO_NS}><xacro:include filename="arm.xacro"/>'
                         f'<xacro:arm parent="{parent}"/></robot>\n')
        _assert_broken_robot(run, robot)


def test_a_part_that_a_file_of_its_package_includes_is_a_part(run, tmp_path):
    # stretch's stretch_gripper_with_puller.xacro: a named <robot> hung from link_wrist_yaw,
    # included by the robot file of its package; named alone, or found in a walk of urdf/
    package = tmp_path / "stretch_like"
    (package / "urdf" / "parts").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>stretch_like</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>BSD</license></package>\n')
    gripper = package / "urdf" / "parts" / "gripper.xacro"
    gripper.write_text(f'<robot name="gripper" {XACRO_NS}><link name="finger">{INERTIAL}</link>'
                       '<joint name="mount" type="fixed"><parent link="link_wrist_yaw"/>'
                       '<child link="finger"/></joint></robot>\n')
    robot = package / "urdf" / "robot.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO_NS}><link name="link_wrist_yaw">{INERTIAL}'
                     '</link><xacro:include filename="$(find stretch_like)/urdf/parts/'
                     'gripper.xacro"/></robot>\n')
    for target in (gripper, gripper.parent):
        result = run("check", "urdf", target, "--format", "json", "--isolated")
        assert result.exit_code == 0, result.stdout
        (only,) = findings(result.stdout)
        assert only["code"] == "SB018", only
        assert f"(included by {robot})" in only["message"]
        assert "every link hangs from 'link_wrist_yaw'" in only["message"]
    result = run("check", "urdf", robot, "--format", "json", "--isolated")
    assert "SB018" not in {f["code"] for f in findings(result.stdout)}


def test_a_part_only_a_comment_includes_is_an_alternative_part(run, tmp_path):
    # stretch_ros2's stretch_dry_erase_marker.xacro: switched in by moving a comment,
    # <!--<xacro:include filename="stretch_dry_erase_marker.xacro" />-->, in the robot file
    urdf = tmp_path / "urdf"
    urdf.mkdir()
    marker = urdf / "marker.xacro"
    marker.write_text(f'<robot name="marker" {XACRO_NS}><link name="pen">{INERTIAL}</link>'
                      '<joint name="mount" type="fixed"><parent link="link_wrist_yaw"/>'
                      '<child link="pen"/></joint></robot>\n')
    robot = urdf / "robot.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO_NS}><link name="link_wrist_yaw">{INERTIAL}'
                     '</link><!--<xacro:include filename="marker.xacro" />--></robot>\n')
    result = run("check", "urdf", urdf, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    found = {(f["file"].rsplit("/", 1)[-1], f["code"]) for f in findings(result.stdout)}
    assert ("marker.xacro", "SB018") in found and ("marker.xacro", "SB103") not in found
    robot.write_text(robot.read_text().replace("marker.xacro", "other.xacro"))
    assert run("check", "urdf", marker, "--isolated").exit_code == 1  # named nowhere: a robot


def test_an_alternative_part_is_checked_alone_but_for_its_missing_parent(run, tmp_path):
    """Nothing includes it with its robot but a comment, so nothing else would report its
    own defects (stretch_gripper_with_puller.xacro's were hidden behind the SB018 note)."""
    urdf = tmp_path / "urdf"
    urdf.mkdir()
    tool = urdf / "tool.xacro"
    tool.write_text(f'<robot name="tool" {XACRO_NS}><link name="pen"><inertial>'
                    '<mass value="-1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" '
                    'izz="1"/></inertial></link><joint name="mount" type="fixed">'
                    '<parent link="link_wrist_yaw"/><child link="pen"/></joint></robot>\n')
    (urdf / "robot.urdf.xacro").write_text(
        f'<robot name="r" {XACRO_NS}><link name="link_wrist_yaw">{INERTIAL}</link>'
        '<!--<xacro:include filename="tool.xacro" />--></robot>\n')
    result = run("check", "urdf", tool, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.stdout
    codes = [f["code"] for f in findings(result.stdout)]
    assert codes[0] == "SB018" and "SB302" in codes  # its negative mass
    assert not {"SB103", "SB104", "SB105", "SB701", "SB702"} & set(codes)
