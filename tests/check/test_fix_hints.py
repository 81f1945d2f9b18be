"""What a finding suggests fits the joint it is about."""

from __future__ import annotations

import pytest

from tests.check.helpers import findings, tetrahedron_stl

ARM = ('<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
       '<joint name="j" type="{kind}"><parent link="a"/><child link="b"/>{limit}</joint>'
       '<joint name="j2" type="revolute"><parent link="b"/><child link="c"/>'
       '<limit lower="-1" upper="1" effort="1" velocity="1"/>{mimic}</joint></robot>')


@pytest.mark.parametrize(("kind", "continuous"), [("revolute", True), ("prismatic", False)])
def test_a_missing_limit_suggests_continuous_only_for_a_revolute_joint(run, tmp_path, kind,
                                                                       continuous):
    path = tmp_path / "r.urdf"
    path.write_text(ARM.format(kind=kind, limit="", mimic=""))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB202")
    (found,) = findings(result.stdout)
    assert ("continuous" in found["fix"]) is continuous


def test_a_mimic_of_a_missing_joint_never_suggests_the_joint_itself(run, tmp_path):
    """'j2x' on joint j2 suggested 'j2', which would mimic itself (SB210); nor a fixed joint,
    which nothing follows (SB209 again)."""
    path = tmp_path / "r.urdf"
    path.write_text(ARM.format(kind="revolute", limit='<limit lower="-1" upper="1" effort="1" '
                               'velocity="1"/>', mimic='<mimic joint="j2x"/>'))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB209")
    (found,) = findings(result.stdout)
    assert found["message"].endswith("which does not exist; did you mean 'j'?")


@pytest.mark.parametrize(("body", "fix"), [
    # roverrobotics_ros2's payload parts read their includer's property: an argument
    # (NAME:=VALUE, as the rule's general fix said) does not define it
    ('<link name="l"><visual><geometry><box size="1 1 ${size}"/></geometry></visual></link>',
     "define 'size' (<xacro:property name=\"size\""),
    ('<link name="$(arg name)"/>', "pass name:=VALUE, or give the argument a default"),
])
def test_a_xacro_failure_says_whether_an_argument_or_a_property_is_missing(run, tmp_path, body,
                                                                           fix):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}</robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB006")
    (found,) = findings(result.stdout)
    assert found["fix"].startswith(fix)


@pytest.mark.parametrize(("limit", "continuous"), [
    ('<limit lower="-300" upper="300" effort="1" velocity="1"/>', True),  # ocs2's Kinova roll
    ('<limit lower="-90" upper="90" effort="1" velocity="1"/>', False),
    ('<limit lower="-30" upper="200" effort="1" velocity="1"/>', False),
])
def test_limits_in_degrees_suggest_continuous_only_for_a_wide_symmetric_range(run, tmp_path,
                                                                              limit,
                                                                              continuous):
    path = tmp_path / "r.urdf"
    path.write_text(ARM.format(kind="revolute", limit=limit, mimic=""))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB212")
    (found,) = findings(result.stdout)
    assert found["fix"].startswith('lower="')
    assert ("continuous" in found["fix"]) is continuous


def test_a_name_defined_twice_is_suggested_once(run, tmp_path):
    """ros2/urdf's fail_pr2_desc_double.urdf: 'did you mean 'wheel_link' or 'wheel_link''."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"/><link name="wheel_link"/>'
                    '<link name="wheel_link"/><joint name="j" type="fixed">'
                    '<parent link="base_link"/><child link="wheel_lnk"/></joint></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB103")
    (found,) = findings(result.stdout)
    assert found["message"].endswith("did you mean 'wheel_link' or 'base_link'?")


@pytest.mark.parametrize(("second", "expected"), [
    ('<color rgba="1 0 0 1"/>', True),  # urdfdom draws it white, the first definition
    ('<color rgba="1 1 1 1.0"/>', False),  # the same colour, written otherwise
    ("", False),  # a reference to the first definition by name
])
def test_a_material_name_reused_with_another_colour_is_the_first(run, tmp_path, second,
                                                                 expected):
    """urdfdom's model.cpp gives a visual the first definition of its material's name."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"><visual><geometry><box size="1 1 1"/>'
                    '</geometry><material name="paint"><color rgba="1 1 1 1"/></material>'
                    '</visual></link><link name="b"><visual><geometry><box size="1 1 1"/>'
                    f'</geometry><material name="paint">{second}</material></visual></link>'
                    '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
                    '</robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB114")
    found = findings(result.stdout)
    assert bool(found) is expected
    if expected:
        assert "has rgba '1 0 0 1', but 'paint' is already rgba '1 1 1 1'" in \
            found[0]["message"]


def test_a_package_named_dot_dot_is_not_told_to_get_a_package_xml(run, tmp_path):
    """package://../meshes/part.stl: 'give the package a package.xml with <name>..</name>'."""
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "part.stl").write_bytes(tetrahedron_stl(0.1))
    (tmp_path / "urdf").mkdir()
    path = tmp_path / "urdf" / "r.urdf"
    path.write_text('<robot name="r"><link name="a"><visual><geometry><mesh filename='
                    '"package://../meshes/part.stl"/></geometry></visual></link></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB409")
    (found,) = findings(result.stdout)
    assert found["fix"].startswith("write package://NAME/... with a package's name")


def test_a_vector_with_too_few_numbers_says_how_many(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"><visual><origin xyz="0 0"/><geometry>'
                    '<box size="1 1 1"/></geometry></visual></link></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB013")
    (found,) = findings(result.stdout)
    assert found["fix"] == "write 3 numbers separated by spaces"


def test_a_ros2_control_of_no_robot_names_no_suggestion(run, tmp_path):
    """A <robot> holding only <ros2_control> (checked apart from the file including it):
    'the robot has no names', and a fix to use a suggestion there was none of."""
    robot = tmp_path / "control.urdf"
    robot.write_text('<robot name="r"><ros2_control name="s" type="system"><hardware><plugin>'
                     'mock_components/GenericSystem</plugin></hardware><joint name="w1">'
                     '<command_interface name="velocity"/></joint></ros2_control></robot>')
    result = run("check", robot, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB504"]
    assert found["message"].endswith("which does not exist; the robot has no joints")
    assert found["fix"] == "add the joint to the robot, or check the file that includes this one"


def test_a_joint_defined_twice_is_judged_by_its_first_definition(run, tmp_path):
    """urdfdom refuses the file (SB102); ros2_control's rules read the second, fixed 'j1',
    and told to remove its command interface, which would break the revolute one."""
    robot = tmp_path / "dup.urdf"
    robot.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<joint name="j1" type="fixed"><parent link="b"/><child link="c"/></joint>'
        '<ros2_control name="s" type="system"><hardware><plugin>mock_components/GenericSystem'
        '</plugin></hardware><joint name="j1"><command_interface name="position"/>'
        '<state_interface name="position"/></joint></ros2_control></robot>')
    codes = {f["code"] for f in findings(run("check", robot, "--format", "json",
                                             "--isolated").stdout)}
    assert "SB102" in codes and "SB506" not in codes


def test_a_mimic_of_a_missing_joint_suggests_no_fixed_joint(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ARM.format(kind="fixed", limit="", mimic='<mimic joint="j2x"/>')
                    .replace("</robot>", '<link name="d"/><joint name="jx" type="revolute">'
                             '<parent link="c"/><child link="d"/><limit lower="-1" upper="1" '
                             'effort="1" velocity="1"/></joint></robot>'))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB209")
    (found,) = findings(result.stdout)
    assert "'jx'" in found["message"] and "'j'" not in found["message"]
