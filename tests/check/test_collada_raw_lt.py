"""A COLLADA mesh with a raw ``<`` in an attribute value reads, as Assimp reads it.

velodyne_simulator's five meshes carry ``<geometry name="<STL_BINARY>">`` from the exporter
that wrote them. XML forbids the raw ``<``; Assimp (RViz, MoveIt, Gazebo Classic) and
gz-common's tinyxml2 read the file anyway. check called all five SB402, and inspect could
not draw them. A file broken elsewhere stays SB402.
"""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import run_servicebot

TRIANGLE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="meshId0" name="<STL_BINARY>">
      <mesh>
        <source id="pos"><float_array id="pos-a" count="9">0 0 0 0.1 0 0 0 0.1 0</float_array>
          <technique_common><accessor source="#pos-a" count="3" stride="3">
            <param name="X" type="float"/><param name="Y" type="float"/>
            <param name="Z" type="float"/></accessor></technique_common></source>
        <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
        <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n" name="<STL_BINARY>">
    <instance_geometry url="#meshId0"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""
ROBOT = """<robot name="r"><link name="base_link">
  <visual><geometry><mesh filename="tri.dae"/></geometry></visual></link></robot>
"""


def test_a_raw_lt_in_an_attribute_is_read_past(tmp_path):
    (tmp_path / "tri.dae").write_text(TRIANGLE)
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT)
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json")
    assert result.returncode == 0 and not findings(result.stdout), result.stdout
    drawn = run_servicebot("inspect", robot, "--render", tmp_path / "r.png")
    assert drawn.returncode == 0 and drawn.stderr.splitlines() == [f"wrote {tmp_path / 'r.png'}"]
    (tmp_path / "tri.dae").write_text(TRIANGLE.replace("</mesh>", "</mess>"))
    broken = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB402")
    (found,) = findings(broken.stdout)
    assert found["code"] == "SB402" and "not well-formed" in found["message"]
