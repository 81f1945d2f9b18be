"""MoveIt's semantic descriptions (SRDF) are no URDF, and check says so (moveit_robots)."""

from __future__ import annotations

import json

from tests.check.helpers import findings

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
ARM = (f'<robot name="arm" {XACRO_NS}><group name="arm"><chain base_link="base" '
       'tip_link="tool0"/></group><disable_collisions link1="base" link2="link1" '
       'reason="Adjacent"/></robot>')
ROBOT = (f'<robot name="baxter" {XACRO_NS}><xacro:include filename="arm.srdf.xacro"/>'
         '</robot>')


def test_a_directory_of_srdf_files_says_what_they_are(run, tmp_path):
    (tmp_path / "arm.srdf.xacro").write_text(ARM)
    result = run("check", tmp_path, "--isolated")
    assert result.exit_code == 2
    assert result.stderr.strip().endswith("its 1 *.srdf.xacro file(s) are MoveIt semantic "
                                          "descriptions, not URDF")


def test_a_named_srdf_is_no_robot_to_check(run, tmp_path):
    """baxter_moveit_config's baxter.srdf.xacro was SB109 'no <link>: add base_link', and a
    plain one 'an include (macros, properties or parts)'."""
    (tmp_path / "arm.srdf.xacro").write_text(ARM)
    (tmp_path / "robot.srdf.xacro").write_text(ROBOT)
    result = run("check", tmp_path / "robot.srdf.xacro", tmp_path / "arm.srdf.xacro",
                 "--format", "json", "--isolated")
    assert result.exit_code == 0
    found = [(f["code"], f["message"]) for file in json.loads(result.stdout)["files"]
             for f in file["findings"]]
    assert found == [("SB018", "a MoveIt semantic description (SRDF), not a URDF: nothing "
                      "for check urdf here")] * 2


def test_srdf_content_under_another_name_is_named_as_such(run, tmp_path):
    path = tmp_path / "baxter.srdf"
    path.write_text(ARM)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB109")
    (found,) = findings(result.stdout)
    assert "with its <disable_collisions>, <group> it is a MoveIt semantic description" \
        in found["message"]
