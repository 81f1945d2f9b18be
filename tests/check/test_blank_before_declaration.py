"""Blank lines before ``<?xml ...?>``: read as each consumer reads them.

tinyxml2 (urdfdom, Gazebo, MuJoCo) and Assimp (RViz, Gazebo, MoveIt) skip blanks before the
declaration; expat refuses them, and so does xacro, which parses with expat. doosan-robot2's
``dsr_description2/meshes/h2017_white/H2017_2_2.dae`` opens with a line of two spaces.
Comments before the declaration stay malformed (tinyxml2 refuses them too:
``test_xml_declaration.py``).
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.corpus import check_urdf_rejects
from tests.check.helpers import findings
from tests.conftest import REPO

FINGER = REPO / "tests/realworld/ws/src/urdf_tutorial/meshes/l_finger.dae"
BODY = """<robot name="finger">
  <link name="base"/>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="finger"/>
    <axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1" velocity="1"/>
  </joint>
  <link name="finger">
    <inertial>
      <mass value="0.1"/>
      <inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/>
    </inertial>
    <visual><geometry><mesh filename="{mesh}"/></geometry></visual>
  </link>
</robot>
"""


def _codes(run, path: Path, *args: str) -> list[str]:
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB301", *args)
    json.loads(result.stdout)
    return [str(f["code"]) for f in findings(result.stdout)]


def test_a_urdf_with_a_blank_first_line_is_read_as_urdfdom_reads_it(run, tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text('  \n\n<?xml version="1.0"?>\n' + BODY.format(mesh="box.stl").replace(
        '<visual><geometry><mesh filename="box.stl"/></geometry></visual>', ""))
    assert not check_urdf_rejects(path)
    assert _codes(run, path) == []


def test_a_xacro_file_with_a_blank_first_line_fails_as_xacro_fails(run, tmp_path):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text('\n<?xml version="1.0"?>\n' + BODY.format(mesh="box.stl").replace(
        '<robot name="finger">', '<robot name="finger" xmlns:xacro="http://ros.org/wiki/xacro">'))
    result = run("check", path, "--format", "json", "--isolated")
    (finding,) = findings(result.stdout)
    assert (finding["code"], finding["line"]) == ("SB004", 2)


def test_a_collada_mesh_with_a_blank_first_line_loads(run, tmp_path):
    mesh = tmp_path / "l_finger.dae"
    mesh.write_bytes(b"  \n" + FINGER.read_bytes())
    path = tmp_path / "robot.urdf"
    path.write_text(BODY.format(mesh="l_finger.dae"))
    assert _codes(run, path) == []
    result = run("inspect", path, "--section", "totals")
    assert "cannot read" not in result.stdout + result.stderr
    assert "bounding box" in result.stdout
