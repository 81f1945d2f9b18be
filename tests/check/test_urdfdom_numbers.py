"""Numbers written as real URDFs write them, judged as urdfdom (check_urdf) judges them."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.check.corpus import check_urdf_drops
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


@pytest.mark.parametrize(("xyz", "shown", "kind"), [
    ("0\t0\t0.3", r"0\t0\t0.3", "tab"),
    ("0 0\n0.3", r"0\n0.3", "line break"),
])
def test_a_tab_inside_a_vector_is_named_at_its_element(run, tmp_path, xyz, shown, kind):
    """urdfdom splits ``xyz`` at spaces only and refuses ``0<tab>0<tab>0.3``; the XML parser
    here reads the tab as a space, so the refusal pointed at <robot> and printed a valid-looking
    ``[0 0 0.3]``."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n  <link name="a"/>\n  <link name="b"/>\n'
                    '  <joint name="j" type="fixed"><parent link="a"/><child link="b"/>\n'
                    f'    <origin xyz="{xyz}"/>\n  </joint>\n</robot>\n')
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert (found["code"], found["line"]) == ("SB701", 5)
    assert found["message"] == (f"not a valid URDF: a vector value holds a {kind} ('{shown}'): "
                                "urdfdom separates the numbers of xyz, rpy, scale and axis by "
                                "spaces only")
    assert found["fix"] == "put spaces between the numbers"
    shown_by_fk = run("fk", path)
    assert shown_by_fk.exit_code == 2 and f"holds a {kind} ('{shown}')" in shown_by_fk.stderr
