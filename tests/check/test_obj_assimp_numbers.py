"""OBJ numbers written without a digit before the point, judged as Assimp judges them.

Assimp (RViz, Gazebo, MoveIt, and Pinocchio through coal) counts the numbers of a ``v`` or
``vt`` line by their first characters and does not count ``.1``: it drops such a vertex, or
refuses the file over such a texture coordinate. coal, which loads meshes with Assimp, is
the reference: check reports SB402 exactly where coal cannot load the tetrahedron whole.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.check.helpers import findings

TETRAHEDRON = ["v 0 0 0", "v 0.1 0 0", "v 0.1 0.1 0", "v 0 0.1 0.1"]
FACES = ["f 1 2 3", "f 1 3 4", "f 1 2 4", "f 2 3 4"]


def _coal_reads_it_whole(path: Path) -> bool:
    import coal

    try:
        mesh = coal.MeshLoader().load(str(path))
    except Exception:  # noqa: BLE001  # Assimp refused it: coal's words vary by version
        return False
    return (mesh.num_vertices, mesh.num_tris) == (4, 4)


@pytest.mark.parametrize(("replaced", "line", "end", "misread"), [
    (1, "v .1 0 0", "\n", True),
    (1, "v -.1 0 0", "\n", False),
    (1, "v +.1 0 0", "\n", False),
    (1, "v 0.1 0 0 .5", "\n", False),  # a fourth number: three are still counted
    (1, "\tv\t.1\t0\t0", "\r\n", True),
    (3, "v 0 .1 .1", "\n", True),
    (None, "vt .5 0.5", "\n", True),
    (None, "vt 0.5 .5 0", "\n", False),
    (None, "vn .5 0 0", "\n", False),
])
def test_a_number_without_a_leading_digit_fails_where_assimp_misreads_it(
        run, tmp_path, replaced, line, end, misread):
    lines = list(TETRAHEDRON)
    if replaced is None:
        lines.append(line)
    else:
        lines[replaced] = line
    mesh = tmp_path / "tet.obj"
    mesh.write_bytes(end.join([*lines, *FACES, ""]).encode())
    assert _coal_reads_it_whole(mesh) is not misread
    robot = tmp_path / "r.urdf"
    robot.write_text('<robot name="r"><link name="a"><collision><geometry>'
                     '<mesh filename="tet.obj"/></geometry></collision></link></robot>')
    result = run("check", robot, "--format", "json", "--isolated", "--select", "SB402")
    found = findings(result.stdout)
    assert [f["code"] for f in found] == (["SB402"] if misread else [])
    if misread:
        number = next(word for word in line.split() if word.startswith("."))
        assert f"does not take '{number}' for a number" in found[0]["message"]
        assert found[0]["message"].endswith(f"; write 0{number}")


def test_ik_names_the_line_where_assimp_said_vertex_index_out_of_range(run, tmp_path):
    """ik's collision check loads the mesh with coal; Assimp's own words point elsewhere."""
    (tmp_path / "tet.obj").write_text("\n".join(
        ["v 0 0 0", "v .1 0 0", "v .1 .1 0", "v 0 .1 .1", *FACES, ""]))
    robot = tmp_path / "arm.urdf"
    robot.write_text(
        '<robot name="arm"><link name="base"/><link name="l1"><collision><origin xyz="0 0 0.5"/>'
        '<geometry><mesh filename="tet.obj"/></geometry></collision></link>'
        '<joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<link name="tip"/><joint name="t" type="fixed"><parent link="l1"/><child link="tip"/>'
        '<origin xyz="0.3 0 0"/></joint></robot>')
    result = run("ik", robot, "--frame", "tip", "--position", "0.3", "0", "0")
    assert result.exit_code == 2
    assert ("collision mesh 'tet.obj' of link 'l1' cannot be read: line 2 'v .1 0 0': Assimp "
            "(RViz, Gazebo, MoveIt, Pinocchio) does not take '.1' for a number and drops the "
            "vertex; write 0.1") in result.stderr
    assert "index out of range" not in result.stderr
