"""A finding in an included file names it the same way, however it was included.

ROS packages include their parts with ``$(find pkg)``, which gives xacro an absolute path; a
relative include gives a relative one. A finding must name the file as the user would type
it from where they run check, so that GitHub annotations (paths in the repository) attach.
"""

from __future__ import annotations

import json

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

PARTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="arm" params="parent">
    <link name="arm"/>
    <joint name="arm_joint" type="revolute">
      <parent link="${parent}"/><child link="arm"/><axis xyz="0 0 1"/>
      <limit lower="2" upper="1" effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
</robot>
"""
ROBOT = """<?xml version="1.0"?>
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="{include}"/>
  <link name="base"/>
  <xacro:arm parent="base"/>
</robot>
"""


@pytest.fixture()
def workspace(tmp_path):
    urdf = tmp_path / "ws" / "src" / "demo_description" / "urdf"
    urdf.mkdir(parents=True)
    (urdf.parent / "package.xml").write_text(
        "<package format=\"3\"><name>demo_description</name></package>")
    (urdf / "parts.xacro").write_text(PARTS)
    (urdf / "by_find.urdf.xacro").write_text(
        ROBOT.format(include="$(find demo_description)/urdf/parts.xacro"))
    (urdf / "relative.urdf.xacro").write_text(ROBOT.format(include="parts.xacro"))
    return tmp_path / "ws"


def _sb203(workspace, *args: str) -> list[dict]:
    result = run_servicebot("check", "urdf", "--isolated", "--format", "json", *args,
                            cwd=workspace)
    return [f for report in json.loads(result.stdout)["files"] for f in report["findings"]
            if f["code"] == "SB203"]


def test_an_include_by_find_is_named_as_a_relative_include_is(workspace):
    found = _sb203(workspace, "src/demo_description/urdf/by_find.urdf.xacro",
                   "src/demo_description/urdf/relative.urdf.xacro")
    assert [f["file"] for f in found] == ["src/demo_description/urdf/parts.xacro"] * 2
    assert [f["via"] for f in found] == ["src/demo_description/urdf/by_find.urdf.xacro:5:3",
                                         "src/demo_description/urdf/relative.urdf.xacro:5:3"]


def test_github_annotations_name_files_in_the_repository(workspace):
    result = run_servicebot("check", "urdf", "--isolated", "--format", "github",
                            "src/demo_description/urdf/by_find.urdf.xacro", cwd=workspace)
    assert "::warning file=src/demo_description/urdf/parts.xacro,line=5," in result.stdout


def test_a_file_outside_the_working_directory_keeps_its_absolute_path(workspace):
    """The file checked is named as the user named it; an include outside the working
    directory has no shorter name than its absolute path."""
    urdf = workspace / "src" / "demo_description" / "urdf"
    elsewhere = workspace / "elsewhere"
    elsewhere.mkdir()
    robot = urdf / "by_find.urdf.xacro"
    result = run_servicebot("check", "urdf", "--isolated", "--format", "json", str(robot),
                            cwd=elsewhere)
    (found,) = [f for report in json.loads(result.stdout)["files"] for f in report["findings"]
                if f["code"] == "SB203"]
    assert found["file"] == str(urdf / "parts.xacro") and found["via"] == f"{robot}:5:3"


def test_an_include_through_dot_dot_is_named_by_its_shorter_path(workspace):
    """realsense-ros' tests/*.xacro include ../urdf/_d415.urdf.xacro: findings named
    tests/../urdf/..., one file under two names in a run, and GitHub could not attach them."""
    tests = workspace / "src" / "demo_description" / "tests"
    tests.mkdir()
    (tests / "test.urdf.xacro").write_text(ROBOT.format(include="../urdf/parts.xacro"))
    found = _sb203(workspace, "src/demo_description/tests/test.urdf.xacro")
    assert [f["file"] for f in found] == ["src/demo_description/urdf/parts.xacro"]


def test_a_path_through_a_symbolic_link_and_dot_dot_is_kept_as_written(tmp_path):
    """ws/a is a link to real/a; a/robot includes ../common/parts.xacro, which xacro opens
    as ws/a/../common, that is real/common. Folding '..' as text named ws/common, which does
    not exist, and the mesh beside the include was then missing (SB401)."""
    real = tmp_path / "real"
    (real / "a").mkdir(parents=True)
    (real / "common").mkdir()
    (real / "common" / "parts.xacro").write_text(PARTS.replace(
        '<link name="arm"/>', '<link name="arm"><visual><geometry><mesh filename="arm.stl"/>'
        "</geometry></visual></link>"))
    (real / "common" / "arm.stl").write_bytes(b"\0" * 80 + (0).to_bytes(4, "little"))
    (real / "a" / "robot.urdf.xacro").write_text(ROBOT.format(include="../common/parts.xacro"))
    ws = tmp_path / "ws"
    ws.mkdir()
    (ws / "a").symlink_to(real / "a")
    result = run_servicebot("check", "urdf", "--isolated", "--format", "json",
                            str(ws / "a" / "robot.urdf.xacro"), cwd=ws)
    found = [f for report in json.loads(result.stdout)["files"] for f in report["findings"]]
    assert "SB401" not in {f["code"] for f in found}, result.stdout
    assert "SB403" in {f["code"] for f in found}  # the mesh was read: it has no triangles
    assert all(f["file"] == str(ws / "a" / "../common/parts.xacro") for f in found
               if f["code"] == "SB203")


def test_a_missing_include_is_fixed_by_its_path_not_its_permissions(run, tmp_path):
    robot = tmp_path / "r.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="nope.xacro"/><link name="a"/></robot>')
    result = run("check", robot, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
    assert found["fix"] == "fix the path, or add the file"
