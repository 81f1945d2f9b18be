"""A ``.urdf`` file that only xacro can read is read through xacro, as its launch file does."""

from __future__ import annotations

import json

import pytest

from tests.check.helpers import findings

SAM_BOT_LIKE = """<?xml version="1.0"?>
<robot name="sam_bot" xmlns:xacro="http://ros.org/wiki/xacro">
  <!-- ${commented} -->
  <xacro:property name="base_width" value="0.31"/>
  <link name="base_link">
    <visual>
      <geometry><box size="0.42 ${base_width} 0.18"/></geometry>
    </visual>
  </link>
</robot>
"""


def _check(run, tmp_path, text: str) -> tuple[int, list[tuple[str, str]]]:
    path = tmp_path / "sam_bot_description.urdf"
    path.write_text(text)
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    return result.exit_code, [(str(f["code"]), f"{f['message']}; {f['fix']}") for f in
                              findings(result.stdout)]


def test_a_urdf_with_xacro_expressions_is_expanded_with_a_warning(run, tmp_path):
    # navigation2_tutorials' sam_bot_description.urdf: display.launch.py runs xacro on it
    exit_code, found = _check(run, tmp_path, SAM_BOT_LIKE)
    assert exit_code == 0
    assert [code for code, _ in found] == ["SB017"]
    assert "expanded with xacro" in found[0][1] and found[0][1].endswith("; name it .urdf.xacro")


def test_a_urdf_with_xacro_elements_but_no_expression_is_read_as_it_is(run, tmp_path):
    # ros/urdf's test/pr2_desc.urdf: stray <xacro:...> calls that urdfdom ignores
    text = SAM_BOT_LIKE.replace("${base_width}", "0.31").replace(
        '<xacro:property name="base_width" value="0.31"/>', '<xacro:head_gazebo name="h"/>')
    exit_code, found = _check(run, tmp_path, text)
    assert exit_code == 0 and [code for code, _ in found] == ["SB017"]
    assert "read as plain URDF" in found[0][1]


def test_a_urdf_with_expressions_and_only_the_xacro_namespace_is_expanded(run, tmp_path):
    """turtlebot3_simulations' common_properties.urdf: ${255/255} in colours, the xacro
    namespace declared, no xacro element. It was read as plain URDF: SB013 on each."""
    text = SAM_BOT_LIKE.replace('<xacro:property name="base_width" value="0.31"/>', "") \
        .replace("${base_width}", "${31/100}")
    exit_code, found = _check(run, tmp_path, text)
    assert exit_code == 0 and [code for code, _ in found] == ["SB017"]
    assert "expanded with xacro" in found[0][1]
    without = text.replace(' xmlns:xacro="http://ros.org/wiki/xacro"', "")
    assert "SB013" in {code for code, _ in _check(run, tmp_path, without)[1]}


def test_a_mesh_named_with_a_substitution_xacro_never_sees_says_so(run, tmp_path):
    """A .urdf read as it is (no package path, no xacro in it) naming its mesh
    $(optenv DRONE_MESHES /opt)/...: the message showed only the part after the
    substitution, and the fix said the package held no such file."""
    path = tmp_path / "drone.urdf"
    path.write_text('<robot name="d"><link name="base_link"><visual><geometry><mesh filename='
                    '"$(optenv DRONE_MESHES /opt)/quadrotor.dae"/></geometry></visual></link>'
                    '</robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB401")
    (found,) = findings(result.stdout)
    assert found["message"].endswith("does not exist; its '$(...)' is xacro's, and nothing "
                                     "substitutes it in a file xacro does not expand")
    assert found["fix"].startswith("name the file .urdf.xacro, so that xacro expands it")


STL = (b"solid p\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       b"endloop\nendfacet\nendsolid p\n")


def _package(root, name: str) -> None:
    root.mkdir(parents=True)
    (root / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")


@pytest.mark.parametrize("namespace", [' xmlns:xacro="http://www.ros.org/wiki/xacro"', ""])
def test_a_urdf_with_a_package_path_is_expanded(run, tmp_path, namespace):
    """A mesh at file://$(find ...)/meshes/... and no ${...}: read as it is, the mesh was
    'missing' (SB401, an error) though its package holds it. roverrobotics_ros2's
    rplidar_s2.urdf declares the xacro namespace; ocs2_robotic_assets' quadrotor.urdf does
    not, and ocs2's visualize.launch expands it with xacro all the same."""
    package = tmp_path / "demo_description"
    _package(package, "demo_description")
    (package / "meshes").mkdir()
    (package / "meshes" / "part.stl").write_bytes(STL)
    (package / "urdf").mkdir()
    path = package / "urdf" / "robot.urdf"
    path.write_text(f'<robot name="demo"{namespace}><link name="base_link"><visual><geometry>'
                    '<mesh filename="file://$(find demo_description)/meshes/part.stl"/>'
                    '</geometry></visual></link></robot>')
    result = run("check", path, "--format", "json", "--isolated")
    found = [(f["code"], f["message"]) for f in findings(result.stdout)]
    assert result.exit_code == 0 and [code for code, _ in found] == ["SB017"], found
    assert "holds xacro package paths ($(find ...))" in found[0][1]


def test_what_a_xacro_urdf_includes_is_a_part_not_a_robot(run, tmp_path):
    """roverrobotics_ros2: max.urdf (xacro, expanded by every launch file) includes
    accessories/*.urdf, which hang from its payload_link and read its properties; a walk
    checked each alone: SB103 and SB006, false errors."""
    package = tmp_path / "ws" / "src" / "demo_description"
    _package(package, "demo_description")
    (package / "urdf" / "parts").mkdir(parents=True)
    (package / "urdf" / "robot.urdf").write_text(
        '<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property '
        'name="z" value="0.1"/><link name="base_link"/><xacro:include '
        'filename="$(find demo_description)/urdf/parts/sensor.urdf"/></robot>')
    (package / "urdf" / "parts" / "sensor.urdf").write_text(
        '<robot name="sensor" xmlns:xacro="http://www.ros.org/wiki/xacro"><link '
        'name="sensor_link"/><joint name="j" type="fixed"><parent link="base_link"/><child '
        'link="sensor_link"/><origin xyz="0 0 ${z}"/></joint></robot>')
    result = run("check", tmp_path / "ws", "--format", "json", "--isolated", "--ignore", "SB309")
    checked = [f["file"].rsplit("/", 1)[-1] for f in json.loads(result.stdout)["files"]]
    assert result.exit_code == 0 and checked == ["robot.urdf"], result.stdout


JAKA_LIKE = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"/>
  <link name="link_1"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="joint_1" type="revolute">
    <parent link="base_link"/><child link="link_1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <gazebo>
    <plugin name="gz_ros2_control::GazeboSimROS2ControlPlugin"
            filename="libgz_ros2_control-system.so">
      <parameters>$(find arm_moveit_config)/config/ros2_controllers.yaml</parameters>
    </plugin>
  </gazebo>
</robot>
"""


def test_a_package_nowhere_outside_file_names_leaves_the_urdf_readable(run, tmp_path):
    """JAKA's jaka_zu7.urdf, given to robot_state_publisher as it is, names a MoveIt package
    in a plugin's <parameters>. Without that package, check said SB007 and checked nothing
    else, and fk and inspect refused the file (exit 2), which urdfdom and Pinocchio read."""
    path = tmp_path / "jaka_zu7.urdf"
    path.write_text(JAKA_LIKE)
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    found = [(f["code"], f["severity"], f["message"], f["line"]) for f in
             findings(result.stdout)]
    assert result.exit_code == 0 and [code for code, *_ in found] == ["SB007"], found
    assert found[0][1] == "warning" and found[0][3] == 14
    assert "package 'arm_moveit_config' not found" in found[0][2]
    assert found[0][2].startswith("$(find ...) read as written")
    fk = run("fk", path, "-j", "joint_1=0.5", "--frame", "link_1")
    assert fk.exit_code == 0, fk.output
    assert "0  0  0.1" in fk.stdout
    inspect = run("inspect", path, "--section", "joints")
    assert inspect.exit_code == 0 and "joint_1" in inspect.stdout


def test_rules_judge_the_urdf_whose_find_is_read_as_written(run, tmp_path):
    """Read as it is, the file is checked by every rule (a massless moving link here)."""
    path = tmp_path / "arm.urdf"
    path.write_text(JAKA_LIKE.replace('<inertial><mass value="1"/>\n    <inertia ixx="0.01" '
                                      'ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
                                      '</inertial>', ""))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    codes = [f["code"] for f in findings(result.stdout)]
    assert result.exit_code == 1 and "SB303" in codes and "SB007" in codes, codes


def test_a_package_nowhere_in_a_mesh_name_still_stops_the_expansion(run, tmp_path):
    """A $(find) in a mesh's file name is xacro's to substitute: read as written, the mesh
    would be 'missing'; the package missing is the finding, as before."""
    path = tmp_path / "arm.urdf"
    path.write_text(JAKA_LIKE.replace(
        '<link name="base_link"/>', '<link name="base_link"><visual><geometry><mesh filename='
        '"file://$(find arm_description)/meshes/base.stl"/></geometry></visual></link>'))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    found = [(f["code"], f["message"]) for f in findings(result.stdout)]
    assert [code for code, _ in found] == ["SB007"], found
    assert "arm_description" in found[0][1] and "read as written" not in found[0][1]
    assert run("fk", path, "-j", "joint_1=0.5").exit_code == 2


def test_expand_shows_the_package_warning_of_a_urdf_read_as_written(run, tmp_path):
    """expand stopped with an internal error (KeyError: 'package') on it."""
    path = tmp_path / "jaka_zu7.urdf"
    path.write_text(JAKA_LIKE)
    result = run("expand", path)
    assert result.exit_code == 0, result.output
    assert result.stderr.startswith("warning: ") and "$(find ...) read as written" in result.stderr
    assert '<robot name="arm">' in result.stdout


def test_xacro_arguments_mean_the_file_is_expanded(run, tmp_path):
    """Arguments given: the user means xacro to expand it, and the package is missing."""
    path = tmp_path / "jaka_zu7.urdf"
    path.write_text(JAKA_LIKE)
    result = run("check", path, "a:=1", "--format", "json", "--isolated", "--ignore", "SB309")
    found = [(f["code"], f["message"]) for f in findings(result.stdout)]
    assert [code for code, _ in found] == ["SB007"]
    assert "read as written" not in found[0][1]
