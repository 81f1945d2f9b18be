"""Broken collision meshes: ik refuses them in one line, before coal (Assimp) reads them.

Assimp crashed (SIGSEGV) on an ASCII PLY whose face names a vertex that does not exist,
allocated gigabytes (SIGTERM waiting the while) for a PLY header claiming 400 million
vertices, and its own words (coal's source file and function, and a wrong hint on the mesh
directory) made the error line.
"""

from __future__ import annotations

import struct
import time
from pathlib import Path

from tests.conftest import assert_one_line_error, run_servicebot

_TAIL = "--allow-collisions skips the check"


def _robot(tmp_path: Path, mesh: str, data: bytes | str) -> Path:
    """A one-joint robot whose link 'arm' has ``mesh`` (holding ``data``) as its shapes."""
    (tmp_path / mesh).write_bytes(data.encode() if isinstance(data, str) else data)
    urdf = tmp_path / f"robot_{mesh}.urdf"
    urdf.write_text(f"""<robot name="r">
  <link name="base"/>
  <link name="arm">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/>
    </inertial>
    <visual><geometry><mesh filename="{mesh}"/></geometry></visual>
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
""")
    return urdf


def _ik(urdf: Path, runner=None, timeout: float = 60):  # type: ignore[no-untyped-def]
    args = ("-f", "arm", "--position", "0", "0", "0")
    if runner is None:  # a process of its own: a crash must not take pytest with it
        return run_servicebot("ik", urdf.name, *args, cwd=urdf.parent, timeout=timeout)
    return runner("ik", urdf, *args)


_PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n")


def test_ply_face_naming_a_missing_vertex_is_refused_not_a_crash(tmp_path):
    urdf = _robot(tmp_path, "bad.ply", _PLY_HEAD + "3 0 1 9\n")
    result = _ik(urdf)
    assert_one_line_error(result, 2, f"{urdf.name}: collision mesh 'bad.ply' of link 'arm' "
                          "cannot be read: a face refers to a vertex that does not exist",
                          f"(run servicebot check {urdf.name})", _TAIL)


def test_ply_header_claiming_400m_vertices_is_refused_at_once(tmp_path):
    urdf = _robot(tmp_path, "big.ply", "ply\nformat ascii 1.0\nelement vertex 400000000\n"
                  "property float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n")
    start = time.monotonic()
    result = _ik(urdf, timeout=20)  # it allocated gigabytes, and went on
    assert time.monotonic() - start < 15
    assert_one_line_error(result, 2, "collision mesh 'big.ply' of link 'arm' cannot be read",
                          "400000000", _TAIL)


def test_binary_ply_header_claiming_more_faces_than_the_file_holds(tmp_path):
    head = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            b"property float y\nproperty float z\nelement face 100000000\n"
            b"property list uchar int vertex_indices\nend_header\n")
    body = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    result = _ik(_robot(tmp_path, "big_bin.ply", head + body))
    assert_one_line_error(result, 2, "collision mesh 'big_bin.ply'", "100000000", _TAIL)


def test_a_good_ply_still_loads(tmp_path, run):
    result = _ik(_robot(tmp_path, "good.ply", _PLY_HEAD + "3 0 1 2\n"), run)
    assert result.exit_code == 0, result.stderr


def test_a_mesh_our_reader_refuses_gets_its_reason_not_coals_words(tmp_path, run):
    urdf = _robot(tmp_path, "hex.stl", "solid x\nfacet normal 0 0 1\nouter loop\n"
                  "vertex 0x1p3 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                  "endsolid x\n")
    line = assert_one_line_error(_ik(urdf, run), 2, "collision mesh 'hex.stl' of link 'arm' "
                                 "cannot be read: ASCII STL", _TAIL)
    for raw in ("From file", "assimp.cpp", "in function", "Hint:", "mesh directory"):
        assert raw not in line


def test_a_mesh_with_no_triangles_is_refused_as_check_calls_it(tmp_path, run):
    result = _ik(_robot(tmp_path, "empty.stl", "solid x\nendsolid x\n"), run)
    assert_one_line_error(result, 2, "collision mesh 'empty.stl' of link 'arm' has no "
                          "triangles", _TAIL)


def test_coal_failing_still_gives_only_its_message_without_the_wrong_hint(tmp_path, run):
    # a <source> without an accessor: our reader takes its numbers, Assimp refuses it
    dae = """<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="12">
0 0 0 1 0 0 0 1 0 0 0 1</float_array></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="4"><input semantic="VERTEX" source="#v" offset="0"/>
<p>0 2 1 0 3 2 0 1 3 1 2 3</p></triangles></mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node>
</visual_scene></library_visual_scenes></COLLADA>
"""
    result = _ik(_robot(tmp_path, "bad.dae", dae), run)
    line = assert_one_line_error(result, 2, "collision mesh 'bad.dae' of link 'arm' "
                                 "cannot be read: ", _TAIL)
    for raw in ("From file", "assimp.cpp", "in function", "Hint:", "Could not load resource"):
        assert raw not in line



def test_a_collision_mesh_over_a_gigabyte_is_not_read(tmp_path):
    """A 3 GB sparse .stl was read whole before coal saw it, as check read it before."""
    huge = tmp_path / "huge.stl"
    with huge.open("wb") as handle:
        handle.truncate(3 * 10**9)
    robot = tmp_path / "r.urdf"
    robot.write_text('<robot name="r"><link name="b"/><link name="a"><collision><geometry>'
                     '<mesh filename="huge.stl"/></geometry></collision></link><joint name="j" '
                     'type="revolute"><parent link="b"/><child link="a"/><axis xyz="0 0 1"/>'
                     '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>')
    result = run_servicebot("ik", robot, "-f", "a", "--position", "0.1", "0", "0")
    assert_one_line_error(result, 2, "collision mesh 'huge.stl' of link 'a' cannot be read: "
                          "the file is 3.0 GB, over the 1 GB a mesh is read to")


def test_a_collision_mesh_in_a_package_that_is_nowhere_names_the_mesh_and_the_way_out(tmp_path):
    """interbotix's locobot: its Create 3 base's meshes are in irobot_create_description,
    which the workspace lacks. ik said only that the package was not found."""
    robot = tmp_path / "r.urdf"
    robot.write_text("""<robot name="r">
  <link name="base"><collision><geometry>
    <mesh filename="package://nowhere_description/meshes/base.stl"/></geometry></collision></link>
  <link name="arm"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.5"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="tip"/>
  <joint name="t" type="fixed"><parent link="arm"/><child link="tip"/><origin xyz="0.3 0 0"/>
  </joint>
</robot>""")
    target = ("-f", "tip", "--position", "0.3", "0", "0.5")
    assert_one_line_error(run_servicebot("ik", robot, *target), 2,
                          "collision mesh 'package://nowhere_description/meshes/base.stl' of "
                          "link 'base': package 'nowhere_description' not found",
                          "--allow-collisions skips the collision check")
    assert run_servicebot("ik", robot, *target, "--allow-collisions").returncode == 0
