"""A relative include is read as xacro reads it: from the sources, or from where the install
rules put the file that includes it, and nowhere else.

main.xacro (description/urdf, installed as share/PKG/urdf) includes '../../urdf/part.xacro':
no such file in the sources nor in the install space, and xacro fails in both; the include
was mapped as if its source path were an install path, and the robot passed.
"""

from __future__ import annotations

from tests.check.helpers import findings

_XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def _package(root, rules: str, files: dict[str, str]):
    root.mkdir(parents=True)
    (root / "package.xml").write_text(f"<package><name>{root.name}</name></package>")
    (root / "CMakeLists.txt").write_text(f"project({root.name})\n{rules}\n")
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)


def _main(include: str) -> str:
    return (f'<robot name="r" {_XACRO}><link name="base"/><xacro:include filename="{include}"/>'
            '<xacro:part/></robot>')


_PART = (f'<robot {_XACRO}><xacro:macro name="part"><link name="part"/><joint name="j" '
         'type="fixed"><parent link="base"/><child link="part"/></joint></xacro:macro></robot>')


def test_an_include_in_neither_layout_is_missing(run, tmp_path):
    package = tmp_path / "mypkg"
    _package(package, "install(DIRECTORY description/urdf DESTINATION share/${PROJECT_NAME})",
             {"description/urdf/main.xacro": _main("../../urdf/part.xacro"),
              "description/urdf/part.xacro": _PART})
    result = run("expand", package / "description/urdf/main.xacro")
    assert result.exit_code == 2
    assert "cannot read included file" in result.output


def test_an_include_that_holds_once_installed_is_read_from_its_source(run, tmp_path):
    """share/mypkg/urdf/main.xacro includes ../ros2_control/part.xacro, installed from the
    package's ros2_control/ directory, not description/ros2_control."""
    package = tmp_path / "mypkg"
    _package(package, "install(DIRECTORY description/urdf ros2_control "
                      "DESTINATION share/${PROJECT_NAME})",
             {"description/urdf/main.xacro": _main("../ros2_control/part.xacro"),
              "ros2_control/part.xacro": _PART})
    result = run("check", "urdf", package / "description/urdf/main.xacro", "--format", "json",
                 "--isolated")
    assert result.exit_code == 0, result.output
    assert all(f["severity"] != "error" for f in findings(result.stdout))


def test_an_include_that_holds_in_the_sources_only_is_an_error(run, tmp_path):
    """ros2_control_demos' example_1 installs description/urdf as share/PKG/urdf: an include
    of '../../../other/part.xacro' finds the sibling package from the sources, and from the
    install space names <prefix>/other/part.xacro, where real xacro fails."""
    repository = tmp_path / "demos"
    _package(repository / "mypkg", "install(DIRECTORY description/urdf "
             "DESTINATION share/${PROJECT_NAME})",
             {"description/urdf/main.xacro": _main("../../../other/urdf/part.xacro")})
    _package(repository / "other", "install(DIRECTORY urdf DESTINATION share/${PROJECT_NAME})",
             {"urdf/part.xacro": _PART})
    result = run("check", "urdf", repository / "mypkg/description/urdf/main.xacro",
                 "--format", "json", "--isolated")
    assert result.exit_code == 1
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
    assert found["severity"] == "error" and found["line"] == 1
    assert "'../../../other/urdf/part.xacro' is read from the sources only" in found["message"]
    assert "<install prefix>/other/urdf/part.xacro" in found["message"]


def test_an_include_of_a_sibling_package_that_holds_installed_too_passes(run, tmp_path):
    """From share/mypkg/urdf, '../../other/urdf/part.xacro' is share/other/urdf/part.xacro:
    both layouts hold it."""
    workspace = tmp_path / "src"
    _package(workspace / "mypkg", "install(DIRECTORY urdf DESTINATION share/${PROJECT_NAME})",
             {"urdf/main.xacro": _main("../../other/urdf/part.xacro")})
    _package(workspace / "other", "install(DIRECTORY urdf DESTINATION share/${PROJECT_NAME})",
             {"urdf/part.xacro": _PART})
    result = run("check", "urdf", workspace / "mypkg/urdf/main.xacro", "--format", "json",
                 "--isolated")
    assert result.exit_code == 0, result.output


def test_an_include_that_lands_in_a_share_no_package_has_is_an_error(run, tmp_path):
    """description/urdf and config both installed in share/mypkg: '../../config/x' from the
    sources is share/config/x once installed, which no package 'config' fills."""
    package = tmp_path / "src" / "mypkg"
    _package(package, "install(DIRECTORY description/urdf config DESTINATION "
             "share/${PROJECT_NAME})",
             {"description/urdf/main.xacro": _main("../../config/part.xacro"),
              "config/part.xacro": _PART})
    result = run("check", "urdf", package / "description/urdf/main.xacro", "--format", "json",
                 "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
    assert result.exit_code == 1 and "<install prefix>/share/config/part.xacro" in \
        found["message"]


def test_ament_auto_package_install_to_share_is_an_install_rule(run, tmp_path):
    repository = tmp_path / "demos"
    _package(repository / "mypkg", "find_package(ament_cmake_auto REQUIRED)\n"
             "ament_auto_package(INSTALL_TO_SHARE description config)",
             {"description/urdf/main.xacro": _main("../../../common/part.xacro")})
    (repository / "common").mkdir()
    (repository / "common" / "part.xacro").write_text(_PART)
    result = run("check", "urdf", repository / "mypkg/description/urdf/main.xacro",
                 "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
    assert result.exit_code == 1 and "<install prefix>/share/common/part.xacro" in \
        found["message"]
