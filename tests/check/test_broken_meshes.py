"""Mesh files broken in the ways a messy disk breaks them: one finding each, nothing more.

No exit 3, no numpy warning on stderr, no memory that grows with what a header claims.
"""

from __future__ import annotations

import os

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="r">
  <link name="base"/>
  <link name="arm">
    <inertial><mass value="{mass}"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0"
      izz="0.1"/></inertial>
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""
TETRA = ('<float_array id="pa" count="12">0 0 0 1 0 0 0 1 0 0 0 1</float_array>'
         '<technique_common><accessor source="#pa" count="4" stride="3"/></technique_common>'
         '</source>'
         '<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>')


def _collada(*, unit: str = "1", primitive: str = "", encoding: str = "") -> str:
    declared = f' encoding="{encoding}"' if encoding else ""
    primitive = primitive or ('<triangles count="4"><input semantic="VERTEX" source="#v" '
                              'offset="0"/><p>0 2 1 0 3 2 0 1 3 1 2 3</p></triangles>')
    return (f'<?xml version="1.0"{declared}?><COLLADA xmlns="http://www.collada.org/2005/11/'
            f'COLLADASchema" version="1.4.1"><asset><unit meter="{unit}"/></asset>'
            f'<library_geometries><geometry id="g"><mesh><source id="p">{TETRA}{primitive}'
            '</mesh></geometry></library_geometries><library_visual_scenes><visual_scene '
            'id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>'
            "</library_visual_scenes></COLLADA>")


CASES = {
    "a vcount of a trillion": ("m.dae", _collada(primitive=(
        '<polylist count="2"><input semantic="VERTEX" source="#v" offset="0"/>'
        "<vcount>3 1000000000000</vcount><p>0 1 2 0 1 3</p></polylist>")),
        "a polygon list shorter than its vertex counts"),
    "an encoding nobody has": ("m.dae", _collada(encoding="klingon"),
                               "its XML declaration names an unknown encoding: klingon"),
    "a unit of inf metres": ("m.dae", _collada(unit="inf"),
                             "vertices with NaN or infinite coordinates"),
    # Assimp (RViz, Gazebo, MoveIt; coal under ik) refuses these three; check passed them
    "a float_array holding fewer numbers than its count": (
        "m.dae", _collada().replace('count="12"', 'count="999"'),
        "says count=\"999\" and holds 12 numbers, which Assimp (RViz, Gazebo, MoveIt) refuses"),
    "a source without an accessor": (
        "m.dae", _collada().replace('<technique_common><accessor source="#pa" count="4" '
                                    'stride="3"/></technique_common>', ""),
        "source 'p' has no <accessor>, without which Assimp (RViz, Gazebo, MoveIt) reads no "
        "positions"),
    "an accessor past its array's count": (
        "m.dae", _collada().replace('count="12"', 'count="6"'),
        "reads 4 points of 3 numbers (12) where its <float_array> says count=\"6\", though it "
        "holds 12: Assimp reads the count it is told; Assimp 5.4 and later (RViz, Gazebo, "
        "MoveIt) refuse it ('Not enough data for accessor'), older Assimp (Ubuntu 22.04 and "
        "24.04) reads past the numbers it kept: vertices of garbage, or a crash"),
    # trimesh's exceptions were the message ("KeyError: 'y'"); ik's own reader says it
    "a PLY whose header promises more than it holds": (
        "m.ply", "ply\nformat ascii 1.0\nelement vertex 99\nproperty float x\nend_header\n"
        "0\n", "the header declares 99 'vertex' elements, more than the file's 2 bytes hold"),
    "a mesh named without a suffix": (
        "mesh", "solid m\nendsolid m\n", "its name has no suffix (.stl, .dae, .obj), from "
        "which Assimp (RViz, Gazebo, MoveIt) takes a mesh's format"),
    "an index beyond int64": ("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -1\n"
                                       "f 1 2 1180591620717411303424\n",
                              "a face refers to a vertex that does not exist"),
}


@pytest.mark.parametrize("case", CASES)
def test_a_broken_mesh_is_one_sb402(tmp_path, case):
    name, text, why = CASES[case]
    (tmp_path / name).write_text(text)
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(mass=1, mesh=name))
    result = run_servicebot("check", robot, "--isolated", "--format", "json", "--select",
                            "SB4")
    assert result.returncode == 1 and result.stderr == ""
    (found,) = findings(result.stdout)
    assert found["code"] == "SB402" and found["message"].endswith(why)


def test_numbers_past_a_float_arrays_count_are_left_out_as_assimp_does(tmp_path):
    """Assimp reads the count it is told; an accessor within it reads a tetrahedron."""
    (tmp_path / "m.dae").write_text(_collada().replace(
        "0 0 0 1 0 0 0 1 0 0 0 1</float_array>", "0 0 0 1 0 0 0 1 0 0 0 1 9 9 9</float_array>"))
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(mass=1, mesh="m.dae"))
    result = run_servicebot("check", robot, "--isolated", "--format", "json", "--select", "SB4")
    assert result.returncode == 0 and findings(result.stdout) == []


def test_what_is_no_mesh_file_is_named_for_what_it_is(tmp_path):
    fifo = tmp_path / "pipe.stl"
    os.mkfifo(fifo)
    (tmp_path / "loop.stl").symlink_to("loop.stl")
    expected = {fifo: "is a named pipe", "/dev/zero": "is a device, not a file",
                tmp_path / "loop.stl": "is a loop of symbolic links",
                "/tmp/" + "a" * 300 + "/m.stl": "is a name too long for the file system"}
    for mesh, why in expected.items():
        robot = tmp_path / "robot.urdf"
        robot.write_text(ROBOT.format(mass=1, mesh=mesh))
        result = run_servicebot("check", robot, "--isolated", "--format", "json", "--select",
                                "SB401", timeout=30)
        assert result.returncode == 1 and result.stderr == ""
        (found,) = findings(result.stdout)
        assert found["message"].endswith(f"{mesh} {why}")


def test_a_mass_of_1e_320_kg_leaves_no_numpy_text(tmp_path):
    (tmp_path / "m.dae").write_text(_collada())
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(mass="1e-320", mesh="m.dae"))
    result = run_servicebot("check", robot, "--isolated")
    assert result.stderr.strip().endswith("passed") or result.stderr == ""
    assert "RuntimeWarning" not in result.stdout + result.stderr


def test_meshes_assimp_reads_are_read_and_a_mesh_of_no_size_is_sb405(tmp_path):
    """An OBJ with classic Mac line ends (CR only) or a UTF-8 byte order mark loads in
    Assimp (Gazebo, RViz, ik): it has its triangles here too. A mesh whose every vertex is
    at one point is a box of size 0: an error as a collision, a warning as a visual."""
    tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
    (tmp_path / "cr.obj").write_bytes(tetra.replace("\n", "\r").encode())
    (tmp_path / "bom.obj").write_bytes(b"\xef\xbb\xbf" + tetra.encode())
    (tmp_path / "point.obj").write_text("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n")
    for mesh, codes in (("cr.obj", []), ("bom.obj", []), ("point.obj", ["SB405"])):
        robot = tmp_path / "robot.urdf"
        robot.write_text(ROBOT.format(mass=1, mesh=mesh).replace(
            "<collision>", f'<visual><geometry><mesh filename="{mesh}"/></geometry></visual>'
            "<collision>"))
        result = run_servicebot("check", robot, "--isolated", "--format", "json", "--select",
                                "SB4")
        found = findings(result.stdout)
        assert [f["code"] for f in found] == codes * 2, (mesh, found)
        if codes:
            assert [f["severity"] for f in found] == ["warning", "error"]
            assert "has no size: every vertex is at one point" in found[1]["message"]


def test_a_mesh_file_over_a_gigabyte_is_not_read(tmp_path):
    """A 3 GB sparse .stl (a disk image copied by mistake) was read whole into memory."""
    huge = tmp_path / "huge.stl"
    with huge.open("wb") as handle:
        handle.truncate(3 * 10**9)
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(mass=1, mesh="huge.stl"))
    result = run_servicebot("check", robot, "--isolated", "--format", "json", "--select", "SB4")
    (found,) = findings(result.stdout)
    assert found["code"] == "SB402" and "the file is 3.0 GB, over the 1 GB" in found["message"]
