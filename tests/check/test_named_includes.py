"""xacro includes named on the command line get one note (SB018), and the run passes.

``servicebot check urdf $(git ls-files '*.xacro')`` names a package's macro libraries and
parts too; a directory walk leaves them out, and named they must not fail the package.
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.helpers import FIXTURES, findings
from tests.conftest import REPO

TURTLEBOT3 = REPO / "tests" / "realworld" / "ws" / "src" / "turtlebot3_description" / "urdf"
XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def _by_file(stdout: str) -> dict[str, list[str]]:
    return {Path(f["file"]).name: [x["code"] for x in f["findings"]]
            for f in json.loads(stdout)["files"]}


def test_every_xacro_of_a_real_package_named_passes(run):
    # turtlebot3_description: the robot, its gazebo part (a named <robot> it includes) and
    # common_properties.xacro (materials only), as `git ls-files '*.xacro'` names them
    named = sorted(TURTLEBOT3.glob("*.xacro"))
    result = run("check", "urdf", *named, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    by_file = _by_file(result.stdout)
    assert by_file["common_properties.xacro"] == ["SB018"]
    assert by_file["turtlebot3_burger.gazebo.xacro"] == ["SB018"]
    assert "SB018" not in by_file["turtlebot3_burger.urdf.xacro"]
    notes = {Path(f["file"]).name: f["message"] for f in findings(result.stdout)
             if f["code"] == "SB018"}
    assert notes["turtlebot3_burger.gazebo.xacro"].startswith(
        f"included by {TURTLEBOT3 / 'turtlebot3_burger.urdf.xacro'}:")


def test_a_macro_library_named_alone_is_a_note_not_an_error(run):
    result = run("check", "urdf", FIXTURES / "SB018_xacro_include.xacro", "--isolated")
    assert result.exit_code == 0, result.stdout
    assert "SB009" not in result.stdout and "SB109" not in result.stdout
    assert "info SB018 [xacro-include] an include" in result.stdout


def test_a_broken_urdf_or_a_malformed_include_still_fails(run, tmp_path):
    unnamed = tmp_path / "robot.urdf"  # a .urdf is a robot, never an include
    unnamed.write_text('<robot><link name="base"/></robot>\n')
    malformed = tmp_path / "parts.xacro"
    malformed.write_text(f'<robot {XACRO_NS}><xacro:macro name="m"><link name="a">'
                         "</xacro:macro></robot>\n")
    result = run("check", "urdf", unnamed, malformed, "--format", "json", "--isolated")
    assert result.exit_code == 1
    by_file = _by_file(result.stdout)
    assert "SB009" in by_file["robot.urdf"] and by_file["parts.xacro"] == ["SB004"]


def test_a_named_robot_xacro_not_included_is_checked(run, tmp_path):
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO_NS}><link name="a"/><link name="a"/></robot>\n')
    result = run("check", "urdf", robot, "--format", "json", "--isolated")
    assert result.exit_code == 1
    assert _by_file(result.stdout)["robot.urdf.xacro"][0] == "SB101"


def test_a_named_include_with_blank_lines_before_its_declaration_fails_as_xacro_does(
        run, tmp_path):
    # xacro (expat) refuses blank lines before <?xml ...?>: no SB018 note, the SB004 error
    library = tmp_path / "parts.xacro"
    library.write_text(f'\n\n<?xml version="1.0"?>\n<robot {XACRO_NS}><xacro:macro name="m">'
                       '<link name="a"/></xacro:macro></robot>\n')
    result = run("check", "urdf", library, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.stdout
    assert _by_file(result.stdout)["parts.xacro"] == ["SB004"]
