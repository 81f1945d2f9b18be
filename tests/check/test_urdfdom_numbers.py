"""Numbers written as real URDFs write them, judged as urdfdom (check_urdf) judges them."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from tests.check.corpus import check_urdf_commands, check_urdf_drops
from tests.check.helpers import findings

LINK = """<robot name="r">
  <link name="base">
    <inertial>
      <mass value="1"/>
      <inertia ixx="1e-05" ixy="0" ixz="0" iyy="1e-05" iyz="0" izz="{izz}"/>
    </inertial>
  </link>
</robot>
"""


def _write(tmp_path: Path, izz: str) -> Path:
    path = tmp_path / "robot.urdf"
    path.write_text(LINK.format(izz=izz))
    return path


@pytest.mark.parametrize("izz", [" 9e-06", "\t9e-06", "9e-06"])
def test_blanks_before_a_number_are_read_as_urdfdom_reads_them(run, tmp_path, izz):
    # unitree_ros' r1_description/R1.urdf: izz=" 9e-06"; urdfdom's istream skips the blank
    path = _write(tmp_path, izz)
    assert not check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB01")
    assert findings(result.stdout) == [] and result.exit_code == 0


def test_blanks_after_a_number_are_refused_as_urdfdom_refuses_them(run, tmp_path):
    # unitree_ros' dex2_5/Left_Hand.urdf: ixz="-0.00000000003261 "; urdfdom drops the inertial
    path = _write(tmp_path, "9e-06 ")
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB01")
    assert [f["code"] for f in findings(result.stdout)] == ["SB013"]


@pytest.mark.parametrize("izz", ["\u00a09e-06", "\u20039e-06"])
def test_a_unicode_blank_before_a_number_is_refused_as_urdfdom_refuses_it(run, tmp_path, izz):
    # istringstream skips only the C locale's blanks: a no-break space stops it
    path = _write(tmp_path, izz)
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB01")
    assert [f["code"] for f in findings(result.stdout)] == ["SB013"]


@pytest.mark.parametrize(("xyz", "piece", "kind"), [
    ("0\t0\t0.3", r"0\t0\t0.3", "tab"),
    ("0 0\n0.3", r"0\n0.3", "line break"),
    ("0 0 0.3&#9;", r"0.3\t", "tab"),  # a character reference, which XML keeps as a tab
])
def test_a_tab_inside_a_vector_is_named_at_its_element(run, tmp_path, xyz, piece, kind):
    """urdfdom splits ``xyz`` at spaces only and refuses ``0<tab>0<tab>0.3``; the XML parser
    here reads a written tab as a space, so check passed such a file, or put SB701 on
    ``<robot>`` and printed a valid-looking ``[0 0 0.3]``."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n  <link name="a"/>\n  <link name="b"/>\n'
                    '  <joint name="j" type="fixed"><parent link="a"/><child link="b"/>\n'
                    f'    <origin xyz="{xyz}"/>\n  </joint>\n</robot>\n')
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated")
    (found, skipped) = findings(result.stdout)
    assert (found["code"], found["line"], skipped["code"]) == ("SB013", 5, "SB702")
    assert found["message"].endswith(f"{kind} inside '{piece}': urdfdom separates numbers by "
                                     "spaces only, so it cannot read them")
    assert found["fix"] == "put single spaces between the numbers"
    shown_by_fk = run("fk", path)
    assert shown_by_fk.exit_code == 2 and f"holds a {kind} (" in shown_by_fk.stderr


@pytest.mark.parametrize("element", [
    '<inertial><origin xyz="0\t0\t0.1"/><mass value="5"/><inertia ixx="1" ixy="0" ixz="0" '
    'iyy="1" iyz="0" izz="1"/></inertial>',
    '<visual><geometry><box size="1\t1\t1"/></geometry></visual>',
    '<collision><origin xyz="0\n0 0"/><geometry><sphere radius="1"/></geometry></collision>',
    '<visual><geometry><sphere radius="1"/></geometry><material name="m"><color '
    'rgba="1\t0\t0\t1"/></material></visual>',
])
def test_a_tab_that_makes_urdfdom_drop_an_element_fails(run, tmp_path, element):
    """urdfdom logs 'Could not parse' and loads the robot without the element (check_urdf
    still exits 0; Pinocchio builds it massless): the robot silently changes."""
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">\n  <link name="base">\n    {element}\n  </link>\n'
                    '</robot>\n')
    _, native, env = check_urdf_commands()
    said = subprocess.run([*native, str(path)], capture_output=True, text=True, env=env)
    assert "Could not parse" in said.stdout + said.stderr or "malformed color" in said.stderr
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB013")
    assert result.exit_code == 1
    assert [f["line"] for f in findings(result.stdout)] == [3]


@pytest.mark.parametrize("version", ["1.0", "01.0", "001.1", " 1.0", "+1.0", "1.02", "1.3",
                                     "1.0 ", "2.0", "1", "1.x"])
def test_a_robot_version_is_read_as_urdfdom_reads_it(run, tmp_path, version):
    """urdfdom reads the two parts as unsigned numbers ("01.0" is 1.0), blanks before them
    allowed, none after; 1.0 to 1.2 are supported."""
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r" version="{version}"><link name="a"/></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB016")
    assert (result.exit_code == 1) is check_urdf_drops(path)


@pytest.mark.parametrize(("kind", "read"), [("fixed", False), ("floating", False),
                                            ("planar", True), ("continuous", True)])
def test_an_axis_urdfdom_skips_is_judged_as_mujoco_reads_it(run, tmp_path, kind, read):
    """urdfdom reads no axis of a fixed or floating joint (check_urdf passes xyz="a b c"
    there); MuJoCo's URDF reader does, and refuses the file ('bad format')."""
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
                    f'type="{kind}"><parent link="a"/><child link="b"/><axis xyz="a b c"/>'
                    '</joint></robot>')
    assert check_urdf_drops(path) is read
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB013")
    assert result.exit_code == 1
    assert ("MuJoCo reads it" in result.stdout) is not read


def test_sb701_alone_points_at_the_origin_that_holds_the_tab(run, tmp_path):
    """With SB013 not selected, Pinocchio's refusal is placed by the file's text: it was put
    on the first element whose value read the same with spaces (a visual origin above)."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n  <link name="a"><visual><origin xyz="0 0 0"/>'
                    '<geometry><sphere radius="1"/></geometry></visual></link>\n'
                    '  <link name="b"/>\n  <joint name="j" type="fixed"><parent link="a"/>'
                    '<child link="b"/>\n    <origin xyz="0\t0\t0"/>\n  </joint>\n</robot>\n')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB701")
    (found,) = findings(result.stdout)
    assert (found["code"], found["line"], found["column"]) == ("SB701", 5, 13)


@pytest.mark.parametrize("blank", ["\u00a0", "\u2009"], ids=["no-break space", "thin space"])
def test_a_unicode_blank_between_numbers_is_named_where_it_is(run, tmp_path, blank):
    """xyz="0<NBSP>0 0.083": Python's split() reads three numbers, urdfdom's (spaces only)
    two, and drops the origin; check said only Pinocchio's 'Unable to parse component
    [0 0]' at the <robot> line."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n<link name="a"><visual>\n'
                    f'<origin xyz="0{blank}0 0.083"/>\n<geometry><box size="1 1 1"/>'
                    "</geometry></visual></link>\n</robot>\n", encoding="utf-8")
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB013"]
    assert found["line"] == 3 and f"(U+{ord(blank):04X}) inside" in found["message"]
