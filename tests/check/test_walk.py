"""A directory walk leaves out the files xacro would include, read as xacro reads the include."""

from __future__ import annotations

from pathlib import Path

from servicebot_cli.check.files import walk

ROBOT = ('<robot name="{name}" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}'
         '<link name="{name}"/></robot>')


def _write(path: Path, name: str, include: str = "") -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    body = f'<xacro:include filename="{include}"/>' if include else ""
    path.write_text(ROBOT.format(name=name, body=body))


def _package(root: Path, name: str) -> Path:
    root.mkdir(parents=True)
    (root / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    return root


def _walked(directory: Path) -> list[str]:
    return [p.relative_to(directory).as_posix() for p in walk(directory)]


def test_find_names_the_file_under_the_package_not_any_file_ending_alike(tmp_path):
    package = _package(tmp_path / "foo_description", "foo")
    _write(package / "urdf/robot.urdf.xacro", "robot", "$(find foo)/urdf/arm.xacro")
    _write(package / "urdf/arm.xacro", "arm")
    _write(package / "old/urdf/arm.xacro", "old_arm")  # ends with urdf/arm.xacro too
    assert _walked(package) == ["old/urdf/arm.xacro", "urdf/robot.urdf.xacro"]


def test_find_reaches_the_source_file_an_install_rule_puts_there(tmp_path):
    package = _package(tmp_path / "demo", "demo")
    (package / "CMakeLists.txt").write_text(
        "install(DIRECTORY description/urdf description/ros2_control\n"
        "        DESTINATION share/${PROJECT_NAME})\n")
    _write(package / "description/urdf/robot.urdf.xacro", "robot",
           "$(find demo)/ros2_control/robot.ros2_control.xacro")
    _write(package / "description/ros2_control/robot.ros2_control.xacro", "control")
    _write(package / "other/ros2_control/robot.ros2_control.xacro", "not_installed")
    assert _walked(package) == ["description/urdf/robot.urdf.xacro",
                                "other/ros2_control/robot.ros2_control.xacro"]


def test_find_of_another_package_or_a_computed_name_names_nothing_here(tmp_path):
    package = _package(tmp_path / "foo", "foo")
    _write(package / "urdf/a.urdf.xacro", "a", "$(find bar)/urdf/b.xacro")
    _write(package / "urdf/b.xacro", "b")
    _write(package / "urdf/c.urdf.xacro", "c", "$(arg parts)/b.xacro")
    assert _walked(package) == ["urdf/a.urdf.xacro", "urdf/b.xacro", "urdf/c.urdf.xacro"]


NESTED = ('<robot name="gripper" xmlns:xacro="http://www.ros.org/wiki/xacro">'
          '<xacro:macro name="gripper" params="prefix">'
          '<xacro:macro name="finger" params="side"><link name="${prefix}${side}"/>'
          '</xacro:macro>'
          '<link name="${prefix}palm"/><xacro:finger side="l"/>'
          '<joint name="${prefix}j" type="fixed"><parent link="${prefix}palm"/>'
          '<child link="${prefix}l"/></joint>'
          '</xacro:macro>{after}</robot>')


def test_a_macro_library_with_a_macro_inside_a_macro_is_no_robot(tmp_path):
    """clearpath's robotiq_2f_140: the inner </xacro:macro> ended the outer definition."""
    (tmp_path / "nested.urdf.xacro").write_text(NESTED.replace("{after}", ""))
    (tmp_path / "robot.urdf.xacro").write_text(NESTED.replace("{after}", '<link name="base"/>'))
    assert _walked(tmp_path) == ["robot.urdf.xacro"]


def test_a_nested_macro_library_checked_by_name_is_an_include(run, tmp_path):
    path = tmp_path / "nested.urdf.xacro"
    path.write_text(NESTED.replace("{after}", ""))
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    assert "SB018" in result.stdout and "SB109" not in result.stdout
