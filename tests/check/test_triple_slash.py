"""package:/// references: an absolute path, or a package as Pinocchio reads them; either
way a warning that ROS would not find them (SB409), never a missing mesh."""

from __future__ import annotations

import trimesh

from tests.check.helpers import findings

URDF = ('<robot name="r"><link name="base"><visual><geometry><mesh filename="{}"/>'
        "</geometry></visual></link></robot>")


def test_package_triple_slash_and_a_package_name_warns_that_ros_would_not_find_it(run, tmp_path):
    meshes = tmp_path / "pkgA" / "meshes"
    meshes.mkdir(parents=True)
    trimesh.creation.box((0.1, 0.1, 0.1)).export(meshes / "m.stl")
    robot = tmp_path / "robot.urdf"
    for reference in ("package:///pkgA/meshes/m.stl", f"package://{meshes / 'm.stl'}"):
        robot.write_text(URDF.format(reference))
        result = run("check", robot, "--format", "json", "--isolated",
                     "--package", f"pkgA={tmp_path / 'pkgA'}")
        found = findings(result.stdout)
        assert [f["code"] for f in found] == ["SB409"], (reference, found)
        assert "would not find it" in found[0]["message"]


def test_three_slashes_before_a_package_name_are_the_defect_named(run, tmp_path):
    """example-robot-data's Talos: package:///example-robot-data/..., in a package of that
    name. The fix is the URI, not the package; --select SB409 alone finds it."""
    package = tmp_path / "example-robot-data"
    meshes = package / "meshes"
    meshes.mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>example-robot-data</name></package>")
    trimesh.creation.box((0.1, 0.1, 0.1)).export(meshes / "m.stl")
    robot = package / "robot.urdf"
    robot.write_text(URDF.format("package:///example-robot-data/meshes/m.stl"))
    for select in ("SB409", "ALL"):
        result = run("check", robot, "--format", "json", "--isolated", "--select", select)
        (found,) = [f for f in findings(result.stdout) if f["code"] == "SB409"]
        assert found["message"].startswith(
            "package:///example-robot-data/... has three slashes: ROS reads the package name "
            "before the third as empty and would not find it; Pinocchio reads package "
            "'example-robot-data' there (the package holding the file")
        assert found["fix"] == "write package://example-robot-data/... with two slashes"


def test_three_slashes_before_a_directory_that_is_no_package_ask_for_both_fixes(run, tmp_path):
    """Found as a directory above the file (no package.xml): two slashes alone would leave
    ROS still without the package."""
    meshes = tmp_path / "myrobot" / "meshes"
    meshes.mkdir(parents=True)
    trimesh.creation.box((0.1, 0.1, 0.1)).export(meshes / "m.stl")
    robot = tmp_path / "myrobot" / "robot.urdf"
    robot.write_text(URDF.format("package:///myrobot/meshes/m.stl"))
    result = run("check", robot, "--format", "json", "--isolated", "--select", "SB409")
    (found,) = findings(result.stdout)
    assert found["fix"] == ("write package://myrobot/... with two slashes, and give the "
                            "package a package.xml with <name>myrobot</name>")


def test_three_slashes_before_an_absolute_path_ask_for_a_path_or_a_package(run, tmp_path):
    """An absolute path behind package:/// (onshape-to-robot's output): the fix asked for a
    package.xml with an empty <name></name>."""
    meshes = tmp_path / "meshes"
    meshes.mkdir()
    trimesh.creation.box((0.1, 0.1, 0.1)).export(meshes / "m.stl")
    robot = tmp_path / "robot.urdf"
    robot.write_text(URDF.format(f"package://{meshes / 'm.stl'}"))
    (found,) = findings(run("check", robot, "--format", "json", "--isolated").stdout)
    assert found["fix"] == ("write the path relative to the file, or package://PKG/... with "
                            "the name of the package that holds it")



def test_a_package_uri_with_no_path_is_a_missing_mesh_not_a_missing_package(run, tmp_path):
    """onshape-to-robot's MuJoCo output writes package://body.stl: ROS looks for a package
    called 'body.stl'. It was SB408 with the fix --package body.stl=DIR."""
    trimesh.creation.box((0.1, 0.1, 0.1)).export(tmp_path / "body.stl")
    robot = tmp_path / "robot.urdf"
    robot.write_text(URDF.format("package://body.stl"))
    found = findings(run("check", robot, "--format", "json", "--isolated").stdout)[0]
    assert found["code"] == "SB401" and found["severity"] == "error"
    assert found["message"].endswith(
        "no file after the package name 'body.stl' (package://PACKAGE/PATH) (a file of that "
        "name is beside the file): ROS looks for a package called 'body.stl'")
