"""SB401 for a mesh written as another machine's path names the package:// that finds it.

A URDF exported on Windows, or written on a colleague's machine, names its meshes by paths
that exist only there; the package of this workspace that holds the file gives the name ROS
finds everywhere. A ROS 2 workspace as users lay it out, with a real binary STL.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings, ros2_package, tetrahedron_stl

_ROBOT = ('<robot name="r"><link name="base_link"><visual><geometry><mesh filename="{mesh}"/>'
          '</geometry></visual></link></robot>')


def _workspace(tmp_path, mesh: str):
    package = ros2_package(tmp_path / "ws", "bot_description")
    (package / "meshes" / "visual").mkdir(parents=True)
    (package / "meshes" / "visual" / "base.stl").write_bytes(tetrahedron_stl(0.1))
    robot = package / "urdf" / "bot.urdf"
    robot.write_text(_ROBOT.format(mesh=mesh))
    return robot


def _sb401(run, robot):
    result = run("check", "urdf", robot, "--format", "json", "--select", "SB401")
    [found] = [f for f in findings(result.stdout) if f["code"] == "SB401"]
    return result.exit_code, found


_FOUND = ("write package://bot_description/meshes/visual/base.stl: a package of this "
          "workspace holds it, and ROS finds it on every machine")


@pytest.mark.parametrize("mesh", [
    "C:\\Users\\me\\bot\\meshes\\visual\\base.stl",  # exported on Windows
    "C:/Users/me/Desktop/bot_description/meshes/visual/base.stl",
    "file:///home/alice/ros2_ws/src/bot_description/meshes/visual/base.stl",
    "/home/alice/cad/export/meshes/visual/base.stl",  # its last parts are in the package
])
def test_another_machines_path_gets_the_package_name(run, tmp_path, mesh):
    code, found = _sb401(run, _workspace(tmp_path, mesh))
    assert code == 1 and found["fix"] == _FOUND
    windows = mesh.startswith("C:")
    assert ("is a Windows path, which names no file elsewhere" in found["message"]) == windows


def test_a_file_no_package_holds_keeps_the_plain_fix(run, tmp_path):
    code, found = _sb401(run, _workspace(tmp_path, "/home/alice/cad/other.stl"))
    assert code == 1 and found["fix"] == ("fix the path: the package or directory holds no "
                                          "such file")
    code, found = _sb401(run, _workspace(tmp_path / "w", "C:\\cad\\other.stl"))
    assert found["fix"] == "write it as package://PKG/... from the package that holds it"


def test_the_package_named_in_a_windows_path_wins_in_any_case(run, tmp_path):
    """bot_description holds meshes/visual/BASE.STL (Windows ignores case); another package
    holds a meshes/visual/base.stl of its own: the named package's file is the one meant."""
    robot = _workspace(tmp_path, "C:\\Users\\me\\bot_description\\meshes\\visual\\base.stl")
    package = robot.parent.parent
    (package / "meshes" / "visual" / "base.stl").rename(package / "meshes" / "visual" / "BASE.STL")
    other = ros2_package(tmp_path / "ws", "alpha_sensors")
    (other / "meshes" / "visual").mkdir(parents=True)
    (other / "meshes" / "visual" / "base.stl").write_bytes(tetrahedron_stl(0.1))
    _, found = _sb401(run, robot)
    assert found["fix"].startswith("write package://bot_description/meshes/visual/BASE.STL:")


def test_a_tail_two_packages_hold_is_no_guess(run, tmp_path):
    robot = _workspace(tmp_path, "C:\\cad\\meshes\\visual\\base.stl")
    other = ros2_package(tmp_path / "ws", "alpha_sensors")
    (other / "meshes" / "visual").mkdir(parents=True)
    (other / "meshes" / "visual" / "base.stl").write_bytes(tetrahedron_stl(0.1))
    _, found = _sb401(run, robot)
    assert found["fix"] == "write it as package://PKG/... from the package that holds it"
