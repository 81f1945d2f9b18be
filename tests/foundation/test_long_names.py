"""Mesh names longer than the file system takes, and package searches through link loops.

Python 3.11's ``Path.exists()`` raises for a name over 255 bytes (ENAMETOOLONG) where
``os.path.exists`` says False. A robot file holds whatever names its author wrote: no
command may end with an internal error on one.
"""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

LONG = "a" * 300  # one name over the 255 bytes of Linux file systems

ROBOT = """<robot name="r">
  <link name="base">
    <visual><geometry><mesh filename="{uri}"/></geometry></visual>
    <collision><geometry><mesh filename="{uri}"/></geometry></collision>
    <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/>
    </inertial>
  </link>
  <link name="arm">
    <collision><geometry><mesh filename="{uri}"/></geometry></collision>
    <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/>
    </inertial>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><origin xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""

URIS = {"package name": f"package://{LONG}/m.stl", "relative": f"meshes/{LONG}.stl",
        "absolute": f"/tmp/{LONG}.stl", "file URI": f"file:///tmp/{LONG}.stl"}
COMMANDS = {"check": ("check", "urdf", "{robot}", "--isolated"),
            "inspect": ("inspect", "{robot}"),
            "fk": ("fk", "{robot}", "-f", "arm"),
            "ik": ("ik", "{robot}", "-f", "arm", "--position", "0", "0", "1"),
            "simulate": ("simulate", "{robot}", "--headless", "--duration", "0.2", "-o",
                         "{out}")}


@pytest.mark.parametrize("uri", list(URIS))
@pytest.mark.parametrize("command", list(COMMANDS))
def test_a_mesh_name_too_long_is_a_finding_or_a_line_never_an_internal_error(
        tmp_path, uri, command):
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(uri=URIS[uri]))
    args = [a.format(robot=robot, out=tmp_path / "run") for a in COMMANDS[command]]
    result = run_servicebot(*args, timeout=120)
    assert result.returncode in (0, 1, 2), result.stderr
    assert "internal error" not in result.stderr and "Traceback" not in result.stderr
    if command == "check":  # no such mesh: not found (SB401), or its package (SB408)
        assert any(code in result.stdout + result.stderr for code in ("SB401", "SB408"))


def test_a_package_search_passes_a_loop_of_links(tmp_path):
    """ROS_PACKAGE_PATH's trees are searched for packages: a link to itself is no directory."""
    tree = tmp_path / "tree"
    (tree / "deeper").mkdir(parents=True)
    (tree / "deeper" / "loop").symlink_to("loop")
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(uri="package://nowhere/m.stl"))
    result = run_servicebot("check", "urdf", robot, "--format", "json",
                            env={"ROS_PACKAGE_PATH": str(tree)}, timeout=60)
    assert result.returncode in (0, 1), result.stderr
    assert "'nowhere' not found" in result.stdout


@pytest.mark.parametrize("args", [
    ("check", "urdf", "{long}.urdf"), ("inspect", "{long}.urdf"), ("fk", "{long}.urdf"),
    ("check", "controllers", "{long}.yaml"), ("fk", "--configs", "{long}.csv"),
    ("check", "urdf", "{robot}", "--isolated", "-o", "{long}.json"),
    ("expand", "{robot}", "-o", "{long}.urdf"),
    ("simulate", "--headless", "--duration-s", "0.2", "--out", "{long}"),
    ("simulate", "--headless", "--duration-s", "0.2", "--plot", "{long}.png"),
])
def test_a_named_file_too_long_is_one_line(tmp_path, args):
    robot = tmp_path / "robot.urdf"
    robot.write_text(ROBOT.format(uri="m.stl"))
    long = tmp_path / LONG
    result = run_servicebot(*(a.format(long=long, robot=robot) for a in args), timeout=120)
    line = assert_one_line_error(result, 2)
    assert "too long" in line or "no such file" in line, line
    assert sorted(p.name for p in tmp_path.iterdir()) == ["robot.urdf"]
