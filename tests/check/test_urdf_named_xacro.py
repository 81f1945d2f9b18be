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
