"""A package found only as a directory of its name: a missing mesh there is not an error.

ROS finds packages by package.xml; where none names the package, only some loaders take a
directory of that name above the file for it. A dataset's ``urdf_files/drake/`` folder or a
repository's ``ranger_mini/`` beside package ``ranger_mini_v2`` (agilexrobotics'
ugv_gazebo_sim) shares the name by chance: that it lacks the file says nothing about the
URDF, which check_urdf accepts. A package ROS finds and that lacks the file is SB401.
"""

from __future__ import annotations

from tests.check.helpers import findings, tetrahedron_stl

ROBOT = ('<robot name="r"><link name="a"><visual><geometry><mesh filename="package://{pkg}/'
         'meshes/{mesh}"/></geometry></visual></link></robot>')


def _layout(tmp_path, package_xml: bool, mesh_present: bool):
    root = tmp_path / "models" / "drake"
    (root / "robot" / "urdf").mkdir(parents=True)
    (root / "meshes").mkdir()
    if package_xml:
        (root / "package.xml").write_text("<package><name>drake</name></package>")
    if mesh_present:
        (root / "meshes" / "base.stl").write_bytes(tetrahedron_stl(0.1))
    path = root / "robot" / "urdf" / "arm.urdf"
    path.write_text(ROBOT.format(pkg="drake", mesh="base.stl"))
    return path


def _codes(run, path):
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    return result.exit_code, {f["code"]: f for f in findings(result.stdout)}


def test_a_directory_that_shares_the_name_and_lacks_the_mesh_is_a_missing_package(run,
                                                                                  tmp_path):
    code, found = _codes(run, _layout(tmp_path, package_xml=False, mesh_present=False))
    assert code == 0 and "SB401" not in found
    assert found["SB408"]["severity"] == "warning"
    assert "package 'drake' not found as ROS finds packages" in found["SB408"]["message"]
    assert "1 mesh not checked" in found["SB408"]["message"]


def test_a_directory_that_shares_the_name_and_holds_the_mesh_is_loader_only(run, tmp_path):
    code, found = _codes(run, _layout(tmp_path, package_xml=False, mesh_present=True))
    assert code == 0 and set(found) & {"SB401", "SB408"} == set()
    assert found["SB409"]["severity"] == "warning"


def test_a_package_ros_finds_that_lacks_the_mesh_is_an_error(run, tmp_path):
    code, found = _codes(run, _layout(tmp_path, package_xml=True, mesh_present=False))
    assert code == 1 and found["SB401"]["severity"] == "error"


def test_a_find_of_a_directory_name_that_is_no_package_name_is_a_warning(run, tmp_path):
    """$(find my_robot_description) where that directory's package.xml says
    acme_robot_description: ROS's xacro fails ('package not found'); check passed it."""
    package = tmp_path / "ws" / "src" / "my_robot_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>acme_robot_description</name></package>")
    (package / "urdf" / "parts.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="tool"/></robot>')
    robot = package / "urdf" / "robot.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                     '  <!-- $(find nothing_here) in a comment is never expanded -->\n'
                     '  <xacro:include filename="$(find my_robot_description)/urdf/parts.xacro"/>\n'
                     '  <link name="base"/>\n  <joint name="j" type="fixed"><parent link="base"/>'
                     '<child link="tool"/></joint>\n</robot>\n')
    result = run("check", "urdf", robot, "--isolated", "--format", "json")
    assert result.exit_code == 0
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB409"]
    assert (found["line"], found["column"], found["severity"]) == (3, 28, "warning")
    assert found["message"].startswith("$(find my_robot_description) resolves only as the "
                                       "directory")
    assert found["fix"] == "write $(find acme_robot_description), the <name> in its package.xml"
    (package / "urdf" / "robot.urdf.xacro").write_text(
        robot.read_text().replace("my_robot_description)", "acme_robot_description)"))
    assert [f for f in findings(run("check", "urdf", robot, "--isolated", "--format",
                                    "json").stdout) if f["code"] == "SB409"] == []


def test_a_package_name_a_letter_off_a_workspace_package_is_suggested(run, tmp_path):
    """package://clearpath_platfrom_description/...: SB408 'not found', as if the package were
    missing from the environment, with no word of the workspace package it misspells."""
    package = tmp_path / "ws" / "src" / "foo_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>foo_description</name></package>")
    robot = package / "urdf" / "r.urdf"
    robot.write_text('<robot name="r"><link name="base"><visual><geometry><mesh filename='
                     '"package://foo_descripton/meshes/base.stl"/></geometry></visual></link>'
                     '</robot>')
    (found,) = findings(run("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB408").stdout)
    assert found["message"].startswith("package 'foo_descripton' not found (did you mean "
                                       "'foo_description'?): 1 mesh not checked")


def test_a_find_of_a_package_named_by_a_property_is_judged_alike(run, tmp_path):
    """andino: $(find ${package_name}), package_name a property of the file. With the
    package.xml's <name> misspelt, ROS's xacro fails ('package not found') and check passed
    the file with no word: the name a property gives is now judged as one written."""
    package = tmp_path / "ws" / "src" / "my_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>my_descripton</name></package>")
    (package / "urdf" / "inc.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="tool"/></robot>')
    robot = package / "urdf" / "robot.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                     '  <xacro:property name="pkg" value="my_description"/>\n'
                     '  <link name="base"/>\n'
                     '  <xacro:include filename="$(find ${pkg})/urdf/inc.xacro"/>\n'
                     '  <joint name="j" type="fixed"><parent link="base"/><child link="tool"/>'
                     '</joint>\n</robot>\n')
    result = run("check", "urdf", robot, "--isolated", "--format", "json")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB409"]
    assert (found["line"], found["severity"]) == (4, "warning")
    assert found["message"].startswith("$(find my_description) resolves only as the directory")
