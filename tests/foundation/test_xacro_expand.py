"""xacro expansion without ROS: includes, packages, arguments, source positions, errors."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from servicebot_cli.description.loader import RobotSource, read_description
from tests.conftest import XACRO_SOURCE, assert_one_line_error, run_servicebot

MAIN = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="tag" default="a"/>
  <xacro:include filename="parts/wheel.xacro"/>
  <link name="base_link"/>
  <xacro:wheel side="left" y="0.3"/>
  <xacro:wheel side="right" y="-0.3"/>
  <link name="mesh_holder">
    <visual>
      <geometry>
        <mesh filename="$(find demo_pkg)/meshes/part.stl"/>
      </geometry>
    </visual>
  </link>
  <link name="tag_$(arg tag)"/>
</robot>
"""
WHEEL = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side y">
    <link name="${side}_wheel"/>
    <joint name="${side}_joint" type="continuous">
      <parent link="base_link"/>
      <child link="${side}_wheel"/>
      <origin xyz="0 ${y} 0"/>
      <limit effort="1" velocity="1"/>
    </joint>
  </xacro:macro>
</robot>
"""


@pytest.fixture
def project(tmp_path, monkeypatch):
    (tmp_path / "parts").mkdir()
    (tmp_path / "robot.urdf.xacro").write_text(MAIN)
    (tmp_path / "parts" / "wheel.xacro").write_text(WHEEL)
    package = tmp_path / "ws" / "src" / "group" / "demo_pkg"
    package.mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>demo_pkg</name></package>")
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    return tmp_path, package


def test_package_given_with_option(run, project):
    root, package = project
    result = run("expand", "robot.urdf.xacro", "tag:=b", "--package", f"demo_pkg={package}")
    assert result.exit_code == 0, result.stderr
    assert f'<mesh filename="{package}/meshes/part.stl"/>' in result.stdout
    assert '<link name="tag_b"/>' in result.stdout
    assert "xacro:" not in result.stdout and "servicebot-src" not in result.stdout


def test_package_found_through_ros_package_path(run, project):
    root, package = project
    result = run("expand", "robot.urdf.xacro", env={"ROS_PACKAGE_PATH": str(root / "ws")})
    assert result.exit_code == 0, result.stderr
    assert f"{package}/meshes/part.stl" in result.stdout


def test_package_found_through_ament_prefix_path(run, project):
    root, _ = project
    share = root / "install" / "share" / "demo_pkg"
    share.mkdir(parents=True)
    result = run("expand", "robot.urdf.xacro", env={"AMENT_PREFIX_PATH": str(root / "install")})
    assert result.exit_code == 0, result.stderr
    assert f"{share}/meshes/part.stl" in result.stdout


def test_missing_package_names_it_and_where_it_looked(run, project):
    result = run("expand", "robot.urdf.xacro")
    line = assert_one_line_error(result, 2, "robot.urdf.xacro:11:9", "package 'demo_pkg' not found",
                                 "ROS_PACKAGE_PATH", "--package NAME=DIR")
    assert "Traceback" not in line


def test_every_element_knows_its_xacro_line_and_macro_call(project):
    root, package = project
    robot = read_description(RobotSource.of("robot.urdf.xacro",
                                            packages=(("demo_pkg", str(package)),)))
    left = robot.joint("left_joint")
    where = robot.source_of(left.element)
    assert (where.file, where.line, where.column) == ("parts/wheel.xacro", 4, 5)
    assert (where.via.file, where.via.line) == ("robot.urdf.xacro", 6)
    right = robot.source_of(robot.joint("right_joint").element)
    assert right.via.line == 7
    base = robot.source_of(robot.link("base_link").element)
    assert (base.file, base.line, base.via) == ("robot.urdf.xacro", 5, None)
    assert str(where) == "parts/wheel.xacro:4:5 (from the macro call at robot.urdf.xacro:6:3)"
    assert robot.files == ("robot.urdf.xacro", "parts/wheel.xacro")


def test_bundled_xacro_positions_point_into_the_includes():
    robot = read_description(RobotSource.of(XACRO_SOURCE, xacro_args=(("hardware", "real"),)))
    hardware = robot.ros2_control[0].element
    where = robot.source_of(hardware)
    assert Path(where.file).name == "ros2_control.xacro"
    assert robot.ros2_control[0].hardware_param("baud_rate") == "9600"


def test_an_argument_the_file_does_not_read_is_a_warning_as_ros_xacro_accepts_it(run, project):
    root, package = project
    result = run("expand", "robot.urdf.xacro", "tga:=b", "--package", f"demo_pkg={package}")
    assert result.exit_code == 0
    assert result.stderr.startswith("warning: robot.urdf.xacro: xacro argument 'tga' is not "
                                    "declared or read by this file (its arguments: tag)")


def test_an_argument_read_under_a_computed_name_is_used(run, tmp_path):
    (tmp_path / "r.urdf.xacro").write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        "  <link name=\"$(arg ${'v' + 'ar'})\"/>\n</robot>\n")
    result = run("expand", tmp_path / "r.urdf.xacro", "var:=base", "other:=x")
    assert result.exit_code == 0, result.stderr
    assert '<link name="base"/>' in result.stdout
    # read under its computed name, 'var' is read; 'other' is read nowhere (xacro's own
    # test_expression_in_extension warned of 'var' too)
    assert "'var'" not in result.stderr
    assert "xacro argument 'other' is not declared or read by this file" in result.stderr


def test_malformed_xacro_argument_is_a_usage_error(run):
    assert_one_line_error(run("expand", XACRO_SOURCE, ":=x"), 2, "NAME:=VALUE")
    assert_one_line_error(run("expand", XACRO_SOURCE, "a=b:=x"), 2, "NAME:=VALUE")


@pytest.mark.parametrize("name", ["robot-name", "arm.side", "9th", "ns/arg"])
def test_an_argument_named_as_xacros_command_line_takes_it_is_set(run, tmp_path, name):
    """xacro's load_mappings takes any name before ':='; 'robot-name:=x' was refused, so
    such an argument could not be set at all."""
    (tmp_path / "r.urdf.xacro").write_text(
        f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:arg name="{name}" '
        f'default="bot"/><link name="$(arg {name})"/></robot>')
    result = run("expand", tmp_path / "r.urdf.xacro", f"{name}:=x")
    assert result.exit_code == 0, result.output
    assert '<link name="x"/>' in result.stdout


def test_xacro_expression_error_names_file_and_line(run, tmp_path):
    bad = tmp_path / "bad.xacro"
    bad.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <link name="a">\n    <visual><geometry><box size="${w} 1 1"/></geometry>'
                   "</visual>\n  </link>\n</robot>\n")
    assert_one_line_error(run("expand", bad), 2, f"{bad}:3:", "name 'w' is not defined")


def test_undeclared_xacro_namespace(run, tmp_path):
    bad = tmp_path / "nons.urdf.xacro"
    bad.write_text('<robot name="r">\n  <xacro:property name="a" value="1"/>\n</robot>\n')
    assert_one_line_error(run("expand", bad), 2, f"{bad}:2:", "xmlns:xacro")


def test_missing_include_names_it(run, tmp_path):
    bad = tmp_path / "inc.xacro"
    bad.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="gone.xacro"/>\n</robot>\n')
    assert_one_line_error(run("expand", bad), 2, "gone.xacro", "No such file or directory")


def test_an_include_with_an_entity_is_refused(run, tmp_path):
    (tmp_path / "evil.xacro").write_text(
        '<!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n<robot>&x;</robot>')
    main = tmp_path / "main.xacro"
    main.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '  <xacro:include filename="evil.xacro"/>\n</robot>\n')
    line = assert_one_line_error(run("expand", main), 2, "evil.xacro", "entity declaration 'x'")
    assert "root:" not in line


def test_output_file_is_written_atomically(run, tmp_path):
    out = tmp_path / "robot.urdf"
    out.write_text("previous")
    assert run("expand", XACRO_SOURCE, "hardware:=nope", "-o", out).exit_code == 2
    assert out.read_text() == "previous"  # a failed expansion leaves the old file alone
    assert [p.name for p in tmp_path.iterdir()] == ["robot.urdf"]
    assert run("expand", XACRO_SOURCE, "-o", out).exit_code == 0
    assert out.read_text().startswith("<?xml")


def test_output_into_missing_directory_creates_it_as_xacro_does(run, tmp_path):
    result = run("expand", XACRO_SOURCE, "-o", tmp_path / "no" / "x.urdf")
    assert result.exit_code == 0, result.stderr
    assert (tmp_path / "no" / "x.urdf").read_text().startswith("<?xml")


def test_output_under_a_regular_file_is_refused(run, tmp_path):
    (tmp_path / "file").write_text("x")
    assert_one_line_error(run("expand", XACRO_SOURCE, "-o", tmp_path / "file" / "x.urdf"), 2,
                          "is a file, not a directory")


def test_package_option_must_name_a_directory(run, tmp_path):
    assert_one_line_error(run("expand", XACRO_SOURCE, "--package", f"p={tmp_path}/none"), 2,
                          "is not a directory")
    assert_one_line_error(run("expand", XACRO_SOURCE, "--package", "nodir"), 2, "NAME=DIR")


def test_a_missing_include_the_build_makes_from_a_template_says_so(tmp_path):
    """hector_quadrotor's CMake configure_file writes quadrotor_plugins.gazebo.xacro from
    its .in beside it: a source checkout has only the template."""
    (tmp_path / "plugins.gazebo.xacro.in").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="a"/></robot>')
    robot = tmp_path / "q.urdf.xacro"
    robot.write_text('<robot name="q" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="plugins.gazebo.xacro"/><link name="b"/></robot>')
    result = run_servicebot("check", "urdf", robot, "--isolated", "--select", "SB001")
    assert result.returncode == 1
    assert "'plugins.gazebo.xacro.in' beside it is the template the package's build makes it " \
        "from: build the package" in result.stdout
    (tmp_path / "plugins.gazebo.xacro.in").unlink()
    assert ".in' beside it" not in run_servicebot("check", "urdf", robot, "--isolated").stdout


def test_a_xacro_warning_is_said_once_as_a_warning(tmp_path):
    """Without a terminal xacro writes "warning: " before its warnings; expand printed
    "warning: warning: redefining global symbol: pi", and check's SB017 quoted the prefix."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '  <xacro:property name="pi" value="3"/>\n  <link name="base"/>\n</robot>\n')
    expanded = run_servicebot("expand", path, "-o", tmp_path / "r.urdf")
    assert expanded.returncode == 0
    # at the property that warned (xacro names only the file)
    assert expanded.stderr.splitlines() == [f"warning: {path}:2:3: redefining global symbol: pi"]
    checked = run_servicebot("check", "urdf", path, "--isolated")
    assert f"{path}:2:3: warning SB017 [xacro-warning] redefining global symbol: pi" \
        in checked.stdout


@pytest.mark.parametrize(("expression", "said"), [
    ("$(eval 1/0)", "a $(...) substitution failed: ZeroDivisionError: division by zero"),
    ("$(eval nope + 1)", "a $(...) substitution failed: NameError: name 'nope' is not defined"),
])
def test_a_failed_eval_names_the_python_error_once(tmp_path, expression, said):
    """xacro's own text is "<class 'ZeroDivisionError'>: division by zero division by zero"."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    f'  <link name="{expression}"/>\n</robot>\n')
    result = run_servicebot("expand", path)
    line = assert_one_line_error(result, 2, f"r.urdf.xacro:2:3: xacro: {said}")
    assert "<class" not in line and line.count("division by zero") <= 1


def test_a_recursive_macro_as_deep_as_xacro_expands_it_is_no_endless_nest(tmp_path):
    """A segment macro that calls itself until ``i`` reaches 220 (a chain, a track, a cable):
    ROS xacro expands it; the position tracking once ran out of frames at about 107 levels
    and called it "nest without end"."""
    path = tmp_path / "chain.urdf.xacro"
    path.write_text(
        '<robot name="chain" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="l0"/>\n'
        '<xacro:macro name="seg" params="i"><xacro:if value="${i &lt; 220}">\n'
        '  <link name="l${i+1}"/>\n'
        '  <joint name="j${i+1}" type="fixed"><parent link="l${i}"/><child link="l${i+1}"/>'
        '</joint>\n'
        '  <xacro:seg i="${i+1}"/></xacro:if></xacro:macro>\n<xacro:seg i="0"/></robot>\n')
    reference = subprocess.run([sys.executable, "-c", "import xacro; xacro.main()", str(path)],
                               capture_output=True, text=True, check=False)
    assert reference.returncode == 0 and reference.stdout.count("<joint ") == 220
    expanded = run_servicebot("expand", path)
    assert expanded.returncode == 0, expanded.stderr
    assert expanded.stdout.count("<joint ") == 220


@pytest.mark.parametrize("value", ["${0.5}", "${2}", "${1 == 1}"])
def test_an_attribute_xacro_cannot_write_is_one_line_not_a_crash(run, tmp_path, value):
    """xacro:attribute with a number (or a boolean): xacro's writer fails on it, so does xacro."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '<link name="a"><visual><geometry>\n'
                    f'<box><xacro:attribute name="size" value="{value}"/></box>\n'
                    '</geometry></visual></link></robot>')
    assert_one_line_error(run("expand", path), 2, f"{path}:3:1", "attribute 'size' of <box>",
                          "not text")
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 1 and '"SB006"' in result.stdout


@pytest.mark.parametrize(("directive", "said"), [
    ('<xacro:if value="$(arg enable_crane)">', "Undefined substitution argument enable_crane"),
    ('<xacro:if value="maybe">', "not a boolean expression"),
    ('<xacro:unless value="${undefined_flag}">', "name 'undefined_flag' is not defined"),
])
def test_a_directive_that_fails_is_placed_at_its_line_not_the_robots(run, tmp_path, directive,
                                                                     said):
    """TALOS's talos_full files were all reported at <robot> (11:1) for an argument a
    <xacro:if value> reads."""
    path = tmp_path / "r.urdf.xacro"
    closing = "</xacro:unless>" if "unless" in directive else "</xacro:if>"
    path.write_text('<?xml version="1.0"?>\n<robot name="r" '
                    'xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="a"/>\n\n'
                    f'  {directive}\n    <link name="b"/>\n  {closing}\n  <link name="c"/>\n'
                    '</robot>\n')
    assert_one_line_error(run("expand", path), 2, f"{path}:5:3", said)


def test_an_error_after_a_directive_is_placed_at_its_own_element(run, tmp_path):
    path = tmp_path / "r.urdf.xacro"
    path.write_text('<?xml version="1.0"?>\n<robot name="r" '
                    'xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '  <xacro:if value="true"><link name="b"/></xacro:if>\n'
                    '  <link name="${missing}"/>\n</robot>\n')
    assert_one_line_error(run("expand", path), 2, f"{path}:4:3", "missing")


def test_an_include_cycle_is_named_at_once(tmp_path):
    """A file including itself after 40 macro calls ran 10 s into the macro-call budget and
    blamed a macro; a robot including '*' from its own directory took half a minute."""
    calls = "".join(f'  <xacro:part n="{i}"/>\n' for i in range(40))
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                     '  <xacro:macro name="part" params="n"><link name="l${n}"/></xacro:macro>\n'
                     f'{calls}  <xacro:include filename="robot.urdf.xacro"/>\n</robot>\n')
    result = run_servicebot("expand", robot)
    assert_one_line_error(result, 2, "robot.urdf.xacro:43:3: xacro: "
                          f"'{robot}' includes itself (robot.urdf.xacro -> robot.urdf.xacro) "
                          "64 deep, where servicebot stops: an include cycle that no condition "
                          "ends, or a recursion deeper than 64 levels")
    (tmp_path / "b.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="a.xacro"/>'
        '</robot>')
    (tmp_path / "a.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="b.xacro"/>'
        '</robot>')
    twice = tmp_path / "twice.urdf.xacro"  # the same file twice, one after the other: no cycle
    twice.write_text('<robot name="t" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="part.xacro"/><xacro:include filename="part.xacro"/>'
                     '<link name="base"/></robot>')
    (tmp_path / "part.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"/>')
    assert run_servicebot("expand", twice).returncode == 0
    cycle = tmp_path / "cycle.urdf.xacro"
    cycle.write_text('<robot name="c" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="a.xacro"/></robot>')
    result = run_servicebot("expand", cycle)
    assert result.returncode == 2
    assert "includes itself (a.xacro -> b.xacro -> a.xacro) 64 deep" in result.stderr


def test_an_include_recursion_a_condition_ends_is_expanded_as_xacro_does(tmp_path):
    """part.xacro includes itself while ${level > 0}, lowering level each time: the real
    xacro expands three links; refusing every file already on the include stack was wrong.
    xacro's own tests recurse 16 deep, which stopped at 16: 60 now expand."""
    (tmp_path / "part.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:if value="${level > 0}"><link name="l${level}"/>'
        '<xacro:property name="level" value="${level - 1}" scope="global" lazy_eval="false"/>'
        '<xacro:include filename="part.xacro"/></xacro:if></robot>')
    robot = tmp_path / "top.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:property name="level" value="3"/><link name="base"/>'
                     '<xacro:include filename="part.xacro"/></robot>')
    result = run_servicebot("expand", robot)
    assert result.returncode == 0, result.stderr
    assert [line.strip() for line in result.stdout.splitlines() if "<link" in line] == [
        '<link name="base"/>', '<link name="l3"/>', '<link name="l2"/>', '<link name="l1"/>']
    robot.write_text(robot.read_text().replace('value="3"', 'value="60"'))
    result = run_servicebot("expand", robot)
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("<link") == 61


def test_a_robot_including_star_from_its_own_directory_ends_at_once(tmp_path):
    """three_robots.urdf.xacro with <xacro:include filename="*"/>: every command ran over 20 s
    (xacro 11 s, until Python's stack ran out)."""
    for name in "abc":
        (tmp_path / f"{name}.urdf.xacro").write_text(
            f'<robot name="{name}" xmlns:xacro="http://www.ros.org/wiki/xacro">'
            f'<link name="{name}"/><xacro:include filename="*"/></robot>')
    result = run_servicebot("expand", tmp_path / "b.urdf.xacro", timeout=20)
    assert result.returncode == 2
    assert "includes itself" in result.stderr or "files included" in result.stderr


def test_more_files_read_than_any_robot_reads_is_refused():
    from servicebot_cli.description import xacro_expand

    with pytest.raises(ValueError, match="over 10000 files included"):
        xacro_expand._refuse_include_cycle(["top.urdf.xacro"], 10_001, ValueError)
    xacro_expand._refuse_include_cycle(["top.urdf.xacro"], 10_000, ValueError)


@pytest.mark.parametrize(("given", "links"), [
    (["use_cam:="], ["base", "robot_x"]),  # an empty value: dropped, the default applies
    (["use_cam:= true"], ["base", "cam", "robot_x"]),  # both sides stripped
    ([" use_cam :=true"], ["base", "cam", "robot_x"]),
    (["_use_cam:=true"], ["base", "robot_x"]),  # a ROS parameter assignment: ignored
    (["prefix:="], ["base", "robot_x"]),  # the string argument keeps its default too
    (["prefix:=other_"], ["base"]),
])
def test_xacro_arguments_are_read_as_xacros_command_line_reads_them(run, tmp_path, given, links):
    """realsense2_description's use_nominal_extrinsics:= from an empty launch variable: xacro
    keeps the default, servicebot failed ('"" is not a boolean') or dropped the default."""
    robot = tmp_path / "r.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:arg name="use_cam" default="false"/>'
                     '<xacro:arg name="prefix" default="robot_"/><link name="base"/>'
                     '<xacro:if value="$(arg use_cam)"><link name="cam"/></xacro:if>'
                     '<xacro:if value="${\'$(arg prefix)\' == \'robot_\'}">'
                     '<link name="$(arg prefix)x"/></xacro:if></robot>')
    result = run("expand", robot, *given)
    assert result.exit_code == 0, result.output
    import re

    assert re.findall(r'<link name="([^"]+)"', result.stdout) == links


@pytest.mark.parametrize(("body", "says"), [
    ('<xacro:macro name="m" params="x"><xacro:element xacro:name="${x}" size="1"/>'
     '</xacro:macro>\n<link name="b"><xacro:m x="1bad name"/></link>',
     "r.urdf.xacro:2:34: xacro: element name '1bad name' is no XML name"),
    ('<link name="b">\n<xacro:attribute name="bad name" value="1"/></link>',
     "r.urdf.xacro:2:1: xacro: attribute name 'bad name' of <link> is no XML name"),
])
def test_a_name_xacro_makes_that_is_no_xml_name_is_refused_where_it_is_made(run, tmp_path,
                                                                            body, says):
    """xacro writes '<1bad name size="1"/>' with exit 0; the refusal pointed into the
    expanded text, at a line of the source that was fine."""
    source = tmp_path / "r.urdf.xacro"
    source.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link '
                      f'name="a"/>\n{body}</robot>\n')
    assert_one_line_error(run("expand", source), 2, says)


@pytest.mark.parametrize("flag", ["--inorder", "-i"])
def test_xacros_inorder_flag_is_taken_with_a_note(run, flag):
    """Melodic-era launch files and Makefiles call 'xacro --inorder', which xacro still
    takes; expand refused it ('No such option'). The URDF is the same."""
    plain = run("expand")
    result = run("expand", flag)
    assert result.exit_code == 0 and result.stdout == plain.stdout
    assert result.stderr == ("note: in-order processing is xacro's only one since ROS "
                             "Melodic: --inorder can be dropped\n")


def test_an_include_that_is_no_xml_names_the_include_that_reads_it(run, tmp_path):
    """'/etc/hostname:1:1: XML is not well-formed' named no line of the robot's files."""
    (tmp_path / "bad.xacro").write_text("not xml at all\n")
    robot = tmp_path / "r.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                     '<link name="a"/>\n  <xacro:include filename="bad.xacro"/>\n</robot>\n')
    result = run("expand", robot)
    assert result.exit_code == 2
    assert result.stderr.rstrip().endswith(f"(included at {robot}:3:3)")


def test_a_parent_scope_at_the_top_says_so(run, tmp_path):
    """xacro stops with its own slip ("'dict' object has no attribute '_setitem'"), which
    says nothing of the file; the message now names the attribute to drop."""
    robot = tmp_path / "r.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                     '  <xacro:property name="a" value="7" scope="parent"/>\n'
                     '  <link name="l_${a}"/>\n</robot>\n')
    result = run("expand", robot)
    assert result.exit_code == 2
    assert result.stderr.strip().endswith(
        ":2:3: xacro: a property with scope=\"parent\" at the top of the file, where there is "
        "no parent scope (xacro stops on it): drop scope=\"parent\"")
