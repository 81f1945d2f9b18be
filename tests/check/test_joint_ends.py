"""A joint's <parent link=""> or <child link="">: urdfdom refuses the joint, and check says so.

check said "link 'arm' is connected to nothing (no joint names it)" of the child of such a
joint, which does name it; urdfdom's own words are "Joint [j] is missing a parent and/or
child link specification".
"""

from __future__ import annotations

import pytest

from tests.check.corpus import check_urdf_rejects
from tests.check.helpers import findings


@pytest.mark.parametrize("end", ["parent", "child"])
def test_an_empty_link_name_is_the_joints_error(run, tmp_path, end):
    ends = {"parent": "base", "child": "arm", end: ""}
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n  <link name="base"/>\n  <link name="arm"/>\n'
                    '  <joint name="j" type="fixed">\n'
                    f'    <parent link="{ends["parent"]}"/><child link="{ends["child"]}"/>\n'
                    '  </joint>\n</robot>\n')
    assert check_urdf_rejects(path)
    result = run("check", path, "--format", "json", "--isolated")
    found = {(f["code"], f["line"]): f["message"] for f in findings(result.stdout)}
    assert found[("SB012", 5)] == (
        f"joint 'j' has <{end} link=\"\">: it names no link, and urdfdom refuses the joint")
    # the parent it names is joined; an unnamed child leaves 'arm' unnamed by any joint
    assert {code for code, _ in found} - {"SB012", "SB702"} == (
        set() if end == "parent" else {"SB108"})


@pytest.mark.parametrize("end", ["parent", "child"])
def test_a_name_of_blanks_is_a_name(run, tmp_path, end):
    """urdfdom looks a link named ' ' up as any other: missing, SB103; there, a joint."""
    ends = {"parent": "base", "child": "arm", end: " "}
    path = tmp_path / "robot.urdf"
    text = ('<robot name="r">\n  <link name="base"/>\n  <link name="arm"/>\n'
            '  <joint name="j" type="fixed">\n'
            f'    <parent link="{ends["parent"]}"/><child link="{ends["child"]}"/>\n'
            '  </joint>\n</robot>\n')
    path.write_text(text)
    assert check_urdf_rejects(path)
    result = run("check", path, "--format", "json", "--isolated")
    found = {(f["code"], f["line"]): f["message"] for f in findings(result.stdout)}
    assert found[("SB103", 4)].startswith(f"joint 'j' has {end} link ' ', which does not exist")


def test_a_link_named_with_blanks_is_a_warning(run, tmp_path):
    """check_urdf, Pinocchio and MuJoCo take a link named ' ': it was 'without a name', an
    error, and the joint to it 'names no link, and urdfdom refuses the joint'."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="base"/><link name=" "/><joint name="j" '
                    'type="fixed"><parent link="base"/><child link=" "/></joint></robot>')
    assert not check_urdf_rejects(path)
    result = run("check", path, "--format", "json", "--isolated")
    assert [(f["code"], f["severity"]) for f in findings(result.stdout)] == [
        ("SB110", "warning")]
    assert result.exit_code == 0
