"""Odd inputs found by hunting: inspect and fk answer in their own words, never a traceback.

Each robot is written to ``tmp_path``; every run turns Python warnings into errors, so numpy
complaining on the way would fail the test even where pytest keeps warnings off stderr.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import pytest
from click.testing import Result

from tests.conftest import RunCli, assert_one_line_error, run_servicebot

_INERTIA = '<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/>'
_LIMIT = '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'

MESH_ROBOT = f"""<robot name="r">
  <link name="base"/>
  <link name="arm">
    <inertial><mass value="1"/>{_INERTIA}</inertial>
    <visual><geometry><mesh filename="{{mesh}}"/></geometry></visual>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>{_LIMIT}</joint>
</robot>
"""

SELF_LOOP = f"""<robot name="r">
  <link name="base"><inertial><mass value="1"/>{_INERTIA}</inertial></link>
  <link name="arm"><inertial><mass value="1"/>{_INERTIA}</inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="base"/>{_LIMIT}</joint>
</robot>
"""

RING = f"""<robot name="r">
  <link name="c"/><link name="a"/><link name="b"/>
  <joint name="ab" type="revolute"><parent link="a"/><child link="b"/>{_LIMIT}</joint>
  <joint name="ba" type="revolute"><parent link="b"/><child link="a"/>{_LIMIT}</joint>
</robot>
"""

FAR_INERTIALS = f"""<robot name="r">
  <link name="base"><inertial><origin xyz="1e308 1e308 1e308"/><mass value="1"/>{_INERTIA}
    </inertial></link>
  <link name="arm"><inertial><origin xyz="1e308 1e308 1e308"/><mass value="1"/>{_INERTIA}
    </inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>{_LIMIT}</joint>
</robot>
"""

STL_FACET = "facet normal 0 0 0\nouter loop\n{}endloop\nendfacet\n"


def _ascii_stl(*triangles: tuple[str, str, str]) -> str:
    body = "".join(STL_FACET.format("".join(f"vertex {v}\n" for v in t)) for t in triangles)
    return f"solid x\n{body}endsolid\n"


def _strict(run: RunCli, *args: object) -> Result:
    """``servicebot ARGS...`` with every Python warning turned into an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return run(*args)


def _mesh_robot(tmp_path: Path, name: str, text: str) -> Path:
    (tmp_path / name).write_text(text)
    urdf = tmp_path / f"robot_{name}.urdf"
    urdf.write_text(MESH_ROBOT.format(mesh=name))
    return urdf


def test_an_obj_with_2d_vertices_is_an_unreadable_mesh(run, tmp_path):
    urdf = _mesh_robot(tmp_path, "flat.obj", "v 0 0\nv 1 0\nv 0 1\nf 1 2 3\n")
    result = _strict(run, "inspect", urdf, "--section", "totals", "--format", "json")
    assert (result.exit_code, result.stderr) == (0, "")
    notes = json.loads(result.stdout)["totals"]["notes"]
    assert "mesh flat.obj: cannot read: a vertex ('v' line) without three numbers" in notes
    drawn = _strict(run, "inspect", urdf, "--render", tmp_path / "r.png")
    assert_one_line_error(drawn, 2, "no visual geometry to draw (mesh flat.obj: cannot read: ")
    assert not (tmp_path / "r.png").exists()


@pytest.mark.parametrize("vertices", [
    ("1e308 0 0", "-1e308 0 0", "0 1e308 0"),  # overflows when trimesh merges vertices
    ("0 0 0", "1e+300 0 0", "0 1e+300 0"),  # an invalid cast to integers there
])
def test_huge_mesh_coordinates_are_refused_in_our_words(run, tmp_path, vertices):
    urdf = _mesh_robot(tmp_path, "huge.stl", _ascii_stl(vertices))
    line = assert_one_line_error(_strict(run, "inspect", urdf, "--render", tmp_path / "r.png"),
                                 2, "mesh huge.stl: not drawn: it has coordinates that are not "
                                 "finite numbers within 1e+06")
    assert "encountered" not in line
    result = _strict(run, "inspect", urdf, "--section", "totals", "--format", "json")
    assert (result.exit_code, result.stderr) == (0, "")
    notes = json.loads(result.stdout)["totals"]["notes"]
    assert [n for n in notes if n.startswith("mesh huge.stl")] == [
        "mesh huge.stl: not drawn: it has coordinates that are not finite numbers within "
        "1e+06 (check reports it)"]


@pytest.mark.parametrize("command", [
    ("inspect",), ("inspect", "--section", "links"), ("inspect", "--format", "dot"),
    ("fk",), ("fk", "--all-frames"), ("fk", "--frame", "arm"),
])
def test_a_joint_from_a_link_to_itself_is_refused_in_one_line(run, tmp_path, command):
    urdf = tmp_path / "loop.urdf"
    urdf.write_text(SELF_LOOP)
    result = _strict(run, command[0], urdf, *command[1:])
    assert result.stderr == (
        f"Error: {urdf}: not a valid URDF: joint 'j' connects link 'base' to itself; a URDF is "
        f"a tree (run 'servicebot check {urdf}' for details)\n")
    assert (result.exit_code, result.stdout) == (2, "")


@pytest.mark.parametrize("command", [("inspect", "--section", "totals"), ("fk", "--frame", "a")])
def test_a_ring_of_joints_off_the_tree_is_refused_in_one_line(run, tmp_path, command):
    urdf = tmp_path / "ring.urdf"
    urdf.write_text(RING)
    assert_one_line_error(_strict(run, command[0], urdf, *command[1:]), 2,
                          "not a valid URDF: kinematic loop: a -[ab]-> b -[ba]-> a",
                          f"servicebot check {urdf}")


def test_a_centre_of_mass_that_overflows_is_a_dash_and_a_note(run, tmp_path):
    urdf = tmp_path / "far.urdf"
    urdf.write_text(FAR_INERTIALS)
    result = _strict(run, "inspect", urdf, "--section", "totals")
    assert (result.exit_code, result.stderr) == (0, "")
    assert "inf" not in result.stdout
    rows = {line[:23].strip(): line[23:].strip() for line in result.stdout.splitlines()}
    assert rows["centre of mass"] == "-"
    assert "note: centre of mass not shown: the links' masses and <inertial> origins" \
        in result.stdout
    data = json.loads(_strict(run, "inspect", urdf, "--section", "totals", "--format",
                              "json").stdout)
    assert data["totals"]["centre_of_mass_m"] is None


def test_no_numpy_warning_reaches_a_real_terminal(tmp_path):
    urdf = tmp_path / "far.urdf"
    urdf.write_text(FAR_INERTIALS)
    done = run_servicebot("inspect", urdf, "--section", "totals")
    assert (done.returncode, done.stderr) == (0, "")


def test_pinocchios_own_refusal_names_the_joints_and_is_not_called_invalid_urdf(run, tmp_path):
    """moveit_robots' Atlas: 24 Sandia finger joints with velocity="-1". urdfdom reads them;
    Pinocchio makes [-(-1), -1] of each and refuses the model. inspect said 'not a valid
    URDF: Some components of min_velocity are greater than max_velocity'."""
    urdf = tmp_path / "fingers.urdf"
    joints = "".join(
        f'<link name="l{i}"/><joint name="finger_j{i}" type="revolute"><parent link="l{i - 1}"/>'
        f'<child link="l{i}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" '
        f'velocity="{-1 if i % 2 else 1}"/></joint>' for i in range(1, 5))
    urdf.write_text(f'<robot name="r"><link name="l0"/>{joints}</robot>')
    result = run("inspect", urdf)
    assert_one_line_error(result, 2, "Pinocchio cannot build its model: Some components of "
                          "min_velocity are greater than max_velocity (joints 'finger_j1', "
                          "'finger_j3': a negative velocity limit)", f"servicebot check {urdf}")
    assert "not a valid URDF" not in result.stderr


def test_a_missing_package_is_one_note_however_many_meshes_it_hides(run, tmp_path):
    """ros-naoqi's pepper.urdf: pepper_meshes is a separate download; inspect printed one
    'package not found' note per mesh, 47 of them (check says it once)."""
    links = "".join(f'<link name="l{i}"><visual><geometry><mesh filename="package://'
                    f'pepper_meshes/meshes/{i}.dae"/></geometry></visual></link>'
                    for i in range(3))
    joints = "".join(f'<joint name="j{i}" type="fixed"><parent link="l0"/><child link="l{i}"/>'
                     '</joint>' for i in (1, 2))
    urdf = tmp_path / "pepper.urdf"
    urdf.write_text(f'<robot name="p">{links}{joints}</robot>')
    result = run("inspect", urdf, "--format", "json")
    notes = [n for n in json.loads(result.stdout)["totals"]["notes"] if "pepper_meshes" in n]
    assert len(notes) == 1 and notes[0].startswith(
        "3 meshes (package://pepper_meshes/meshes/0.dae and others): package 'pepper_meshes' "
        "not found")


def test_the_arm_reach_is_the_arms_not_the_head_written_first(run, tmp_path):
    """ros-naoqi's Pepper: HeadYaw and HeadPitch come first in the file; 'arm reach' measured
    from HeadYaw to a camera frame (0.18 m) instead of along an arm."""
    def revolute(name: str, parent: str, child: str, xyz: str) -> str:
        return (f'<link name="{child}"/><joint name="{name}" type="revolute"><parent '
                f'link="{parent}"/><child link="{child}"/><origin xyz="{xyz}"/><axis '
                'xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')

    parts = [revolute("HeadYaw", "torso", "neck", "0 0 0.3"),
             revolute("HeadPitch", "neck", "head", "0 0 0.05"),
             revolute("ShoulderPitch", "torso", "shoulder", "0 0.15 0.2"),
             revolute("ElbowRoll", "shoulder", "forearm", "0.2 0 0"),
             revolute("WristYaw", "forearm", "hand", "0.2 0 0")]
    urdf = tmp_path / "pepper.urdf"
    urdf.write_text(f'<robot name="p"><link name="torso"/>{"".join(parts)}</robot>')
    arm = json.loads(run("inspect", urdf, "--section", "totals", "--format", "json")
                     .stdout)["totals"]["arm"]
    assert (arm["tip"], arm["reach_m"]) == ("hand", pytest.approx(0.4))
