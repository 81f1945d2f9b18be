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
