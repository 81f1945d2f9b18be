"""SB521: a ros2_control Gazebo plugin's <parameters> file that does not exist.

A ROS 2 workspace as users lay it out (``ws/src/PKG/{package.xml, urdf/, config/}``), the
path written as ``$(find PKG)/config/...`` and expanded by real xacro; the bundled robot's
controllers file is the one the plugin names. open_manipulator's omy_l100 names a
``config/om_y_leader`` its bringup package does not have: Gazebo starts no controller there.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings, ros2_package
from tests.conftest import REPO

_PLUGIN = ('<gazebo><plugin filename="{filename}" name="ros2_control">'
           '<parameters>{parameters}</parameters></plugin></gazebo>')


def _workspace(tmp_path, parameters: str, filename: str = "gz_ros2_control-system"):
    package = ros2_package(tmp_path / "ws", "bot_description")
    (package / "config" / "controllers.yaml").write_text(
        (REPO / "robots" / "controllers.yaml").read_text())
    robot = (REPO / "robots" / "service_robot_real.urdf.xml").read_text()
    plugin = _PLUGIN.format(filename=filename, parameters=parameters)
    xacro = package / "urdf" / "bot.urdf.xacro"
    xacro.write_text(robot.replace('<robot name="service_robot">',
                                   '<robot name="service_robot" '
                                   'xmlns:xacro="http://www.ros.org/wiki/xacro">', 1)
                     .replace("</robot>", plugin + "\n</robot>"))
    assert 'xmlns:xacro' in xacro.read_text()
    return xacro


def _sb521(run, xacro):
    result = run("check", "urdf", xacro, "--format", "json", "--select", "SB521")
    return result.exit_code, [f for f in findings(result.stdout) if f["code"] == "SB521"]


@pytest.mark.parametrize("parameters", [
    "$(find bot_description)/config/controllers.yaml",
    "../config/controllers.yaml",  # from the description's directory
    "$(arg controllers)",  # left to the launch file: xacro fails without it, so a default
])
def test_a_file_that_exists_passes(run, tmp_path, parameters):
    xacro = _workspace(tmp_path, parameters)
    if "$(arg" in parameters:
        xacro.write_text(xacro.read_text().replace(
            "<gazebo><plugin", '<xacro:arg name="controllers" default="$(find bot_description)'
            '/config/controllers.yaml"/><gazebo><plugin', 1))
    assert _sb521(run, xacro) == (0, [])


def test_a_missing_file_is_an_error_at_its_parameters_with_the_close_name(run, tmp_path):
    xacro = _workspace(tmp_path, "$(find bot_description)/config/controller.yaml")
    code, found = _sb521(run, xacro)
    assert code == 1 and len(found) == 1
    line = next(n for n, text in enumerate(xacro.read_text().splitlines(), 1)
                if "<parameters>" in text)
    assert (found[0]["file"], found[0]["line"]) == (str(xacro), line)
    assert found[0]["severity"] == "error"
    assert "config/controller.yaml, which does not exist" in found[0]["message"]
    assert "rcl refuses it ('Couldn't parse params file')" in found[0]["message"]
    assert found[0]["fix"] == ("did you mean "
                               f"{xacro.parent.parent / 'config' / 'controllers.yaml'}?")


def test_a_directory_and_classic_gazebo_ros2_control_too(run, tmp_path):
    xacro = _workspace(tmp_path, "$(find bot_description)/config",
                       filename="libgazebo_ros2_control.so")
    code, found = _sb521(run, xacro)
    assert code == 1 and len(found) == 1
    assert "libgazebo_ros2_control.so" in found[0]["message"]
    assert "which is a directory" in found[0]["message"]


def test_another_plugins_parameters_are_not_read(run, tmp_path):
    xacro = _workspace(tmp_path, "/nowhere/controllers.yaml",
                       filename="libgazebo_ros_diff_drive.so")
    assert _sb521(run, xacro) == (0, [])


def test_a_file_that_cmake_installs_there_passes(run, tmp_path):
    """ros2_control_demos' layout: description/config installed as share/PKG/config."""
    xacro = _workspace(tmp_path, "$(find bot_description)/config/controllers.yaml")
    package = xacro.parent.parent
    (package / "description").mkdir()
    (package / "config").rename(package / "description" / "config")
    (package / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.8)\nproject(bot_description)\n"
        "install(DIRECTORY description/config urdf DESTINATION share/${PROJECT_NAME})\n")
    assert _sb521(run, xacro) == (0, [])


def test_a_relative_name_not_beside_the_description_is_a_warning(run, tmp_path):
    """Gazebo reads a relative <parameters> from its own working directory: it may be there."""
    xacro = _workspace(tmp_path, "controllers.yaml")  # in config/, not beside urdf/
    code, found = _sb521(run, xacro)
    assert code == 0 and len(found) == 1 and found[0]["severity"] == "warning"
    assert "unless Gazebo runs where 'controllers.yaml' is" in found[0]["message"]
    assert "$(find PKG)" in found[0]["fix"]


@pytest.mark.parametrize(("written", "said"), [
    ("file://$(find bot_description)/config/controllers.yaml", "starts with 'file://'"),
    ("~/controllers.yaml", "starts with '~'"),
])
def test_a_file_uri_or_home_is_an_error_as_rcl_opens_it_as_written(run, tmp_path, written,
                                                                  said):
    """gazebo_ros2_control and gz_ros2_control pass the text to rcl, which fopen()s it."""
    (tmp_path / "home").mkdir()
    (tmp_path / "home" / "controllers.yaml").write_text("x: 1\n")
    xacro = _workspace(tmp_path, written)
    result = run("check", "urdf", xacro, "--format", "json", "--select", "SB521",
                 env={"HOME": str(tmp_path / "home")})
    [found] = [f for f in findings(result.stdout) if f["code"] == "SB521"]
    assert result.exit_code == 1 and said in found["message"]
    assert found["fix"].startswith("write the path itself: /")


@pytest.mark.parametrize("cmake", [
    "install(FILES description/config/controllers.yaml DESTINATION share/${PROJECT_NAME}/config)",
    "install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/description/config "
    "DESTINATION share/${PROJECT_NAME})",
    "foreach(dir description/config)\n  install(DIRECTORY ${dir} DESTINATION share/${PROJECT_NAME})"
    "\nendforeach()",
])
def test_a_file_any_install_rule_puts_there_passes(run, tmp_path, cmake):
    """From sources the file is elsewhere in the package, under its own name."""
    xacro = _workspace(tmp_path, "$(find bot_description)/config/controllers.yaml")
    package = xacro.parent.parent
    (package / "description").mkdir()
    (package / "config").rename(package / "description" / "config")
    (package / "CMakeLists.txt").write_text(f"project(bot_description)\n{cmake}\n")
    assert _sb521(run, xacro) == (0, [])
