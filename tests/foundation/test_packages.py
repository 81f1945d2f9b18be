"""Packages are found as ROS finds them, and as the common loaders do, with no ROS sourced."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from servicebot_cli.common.errors import PackageNotFound
from servicebot_cli.description.packages import PackageResolver, is_remote
from tests.conftest import run_servicebot

NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def _package(directory: Path, name: str) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
        "  <version>1.0.0</version>\n</package>\n")
    return directory


def _resolver(**kwargs) -> PackageResolver:
    return PackageResolver.from_environment(environ=NO_ROS, **kwargs)


@pytest.fixture
def workspace(tmp_path):
    """ws/src/{foo_description, bar_description, ignored/baz_description (COLCON_IGNORE)}."""
    src = tmp_path / "ws" / "src"
    foo = _package(src / "foo_description", "foo_description")
    (foo / "urdf").mkdir()
    (foo / "meshes").mkdir()
    (foo / "meshes" / "link.stl").write_text("solid x\nendsolid x\n")
    _package(src / "group" / "bar_description", "bar_description")
    _package(src / "ignored" / "baz_description", "baz_description")
    (src / "ignored" / "COLCON_IGNORE").touch()
    return tmp_path / "ws"


def test_the_package_that_holds_the_file(workspace, monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)  # anywhere: the file's place decides
    urdf_dir = workspace / "src" / "foo_description" / "urdf"
    resolver = _resolver()
    path = resolver.resolve_uri("package://foo_description/meshes/link.stl", urdf_dir)
    assert path == workspace / "src" / "foo_description" / "meshes" / "link.stl"
    location = resolver.found["foo_description"]
    assert location.ros_finds_it and "holding the file" in location.how
    assert resolver.warnings() == []


def test_another_package_of_the_workspace(workspace):
    bar_dir = workspace / "src" / "group" / "bar_description"
    resolver = _resolver()
    path = resolver.resolve_uri("package://foo_description/meshes/link.stl", bar_dir)
    assert path.exists()
    assert resolver.found["foo_description"].how.startswith("workspace ")


@pytest.mark.parametrize("made", ["build", "install", "log"])
def test_a_workspace_built_without_src_is_found_by_what_colcon_made(tmp_path, made):
    """ws/{turtlebot4, create3_sim} built with colcon: the packages of one repository find
    those of the other, as colcon's base path ws finds them."""
    ws = tmp_path / "ws"
    _package(ws / "create3_sim" / "irobot_create_description", "irobot_create_description")
    tb4 = _package(ws / "turtlebot4" / "turtlebot4_description", "turtlebot4_description")
    resolver = _resolver()
    with pytest.raises(PackageNotFound):
        resolver.resolve_uri("package://irobot_create_description/urdf/x.xacro", tb4)
    (ws / made).mkdir()
    (ws / made / "COLCON_IGNORE").touch()
    path = _resolver().resolve_uri("package://irobot_create_description/urdf/x.xacro", tb4)
    assert path == ws / "create3_sim" / "irobot_create_description" / "urdf" / "x.xacro"


def test_a_stray_colcon_build_above_a_repository_is_no_workspace(tmp_path):
    """colcon build run by mistake in a home directory leaves build/COLCON_IGNORE there; a
    repository under it keeps its own root, and a stale copy in the home is not found."""
    from servicebot_cli.description.package_dirs import workspace_root

    home = tmp_path / "home"
    (home / "build").mkdir(parents=True)
    (home / "build" / "COLCON_IGNORE").touch()
    _package(home / "backup" / "my_desc", "my_desc")
    repo = home / "work" / "robot_repo"
    (repo / ".git").mkdir(parents=True)
    mine = _package(repo / "my_desc", "my_desc")
    other = _package(repo / "other_desc", "other_desc")
    assert workspace_root(other / "urdf") == repo
    path = _resolver().resolve_uri("package://my_desc/meshes/m.stl", other / "urdf")
    assert path == mine / "meshes" / "m.stl"


def test_colcon_ignore_hides_a_package(workspace):
    with pytest.raises(PackageNotFound, match="package 'baz_description' not found"):
        _resolver(context=workspace / "src" / "foo_description").find("baz_description")


def test_explicit_package_wins_and_relative_directories_resolve_once(workspace, monkeypatch):
    monkeypatch.chdir(workspace / "src")
    resolver = _resolver(explicit={"foo_description": Path("group/bar_description")})
    os.chdir(workspace)  # a later change of directory does not move it
    assert resolver.find("foo_description") == workspace / "src" / "group" / "bar_description"


def test_relative_ros_package_path(workspace, monkeypatch):
    monkeypatch.chdir(workspace)
    resolver = PackageResolver.from_environment(environ={"ROS_PACKAGE_PATH": "src"})
    os.chdir("/")
    assert resolver.find("bar_description") == workspace / "src" / "group" / "bar_description"


def test_a_directory_named_like_the_package_above_the_file(tmp_path):
    """example-robot-data: package://example-robot-data/... while package.xml says
    example_robot_descriptions. Pinocchio and yourdfpy find it by directory name; ROS does not."""
    share = tmp_path / "share" / "example-robot-data"
    _package(share, "example_robot_descriptions")
    urdf_dir = share / "robots" / "ur_description" / "urdf"
    urdf_dir.mkdir(parents=True)
    resolver = _resolver()
    path = resolver.resolve_uri("package://example-robot-data/robots/ur_description/m.dae",
                                urdf_dir)
    assert path == share / "robots" / "ur_description" / "m.dae"
    [warning] = resolver.warnings()
    assert "'example-robot-data'" in warning and "ROS tools would not find it" in warning


def test_a_package_named_after_a_directory_beside_the_file(tmp_path):
    """pybullet_data: package://meshes/... relative to the URDF."""
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "m.stl").touch()
    resolver = _resolver()
    assert resolver.resolve_uri("package://meshes/m.stl", tmp_path) == tmp_path / "meshes" / "m.stl"
    assert len(resolver.warnings()) == 1


def test_package_triple_slash_is_an_absolute_path_with_a_warning(tmp_path):
    resolver = _resolver()
    assert resolver.resolve_uri(f"package://{tmp_path}/m.stl", tmp_path) == tmp_path / "m.stl"
    assert "ROS tools would not find it" in resolver.warnings()[0]


def test_package_triple_slash_then_a_package_name_is_read_as_pinocchio_reads_it(tmp_path):
    """example-robot-data's Talos: package:///example-robot-data/robots/... is no absolute
    path; Pinocchio finds it under a package directory, so the package is looked for."""
    share = tmp_path / "share" / "example-robot-data"
    _package(share, "example_robot_descriptions")
    urdf_dir = share / "robots" / "talos_data" / "robots"
    urdf_dir.mkdir(parents=True)
    resolver = _resolver()
    path = resolver.resolve_uri("package:///example-robot-data/robots/talos_data/m.stl", urdf_dir)
    assert path == share / "robots" / "talos_data" / "m.stl"
    assert any(w.startswith("package:///example-robot-data/... has three slashes") and
               "would not find it" in w for w in resolver.warnings())
    missing = _resolver().resolve_uri("package:///no-such-package/m.stl", urdf_dir)
    assert missing == Path("/no-such-package/m.stl")  # said missing where it was looked for


def test_talos_checks_without_missing_meshes():
    """The real file, with no --package: its package:/// meshes are found."""
    from tests.check.corpus import erd_root

    talos = erd_root() / "robots" / "talos_data" / "robots" / "talos_full_v2.urdf"
    done = run_servicebot("check", "urdf", str(talos), "--format", "json", env=NO_ROS)
    assert done.returncode == 0, done.stdout
    assert "SB401" not in done.stdout and "SB409" in done.stdout


def test_ament_prefix_path_and_directory_names_on_the_paths(tmp_path):
    prefix = tmp_path / "install"
    (prefix / "share" / "qux_description").mkdir(parents=True)
    plain = tmp_path / "plain"
    (plain / "loose_pkg").mkdir(parents=True)
    resolver = PackageResolver.from_environment(
        environ={"AMENT_PREFIX_PATH": str(prefix), "ROS_PACKAGE_PATH": str(plain)})
    assert resolver.find("qux_description") == prefix / "share" / "qux_description"
    assert resolver.find("loose_pkg") == plain / "loose_pkg"
    assert "AMENT_PREFIX_PATH" in resolver.found["qux_description"].how


def test_not_found_says_where_it_looked(workspace):
    with pytest.raises(PackageNotFound) as error:
        _resolver(context=workspace / "src" / "foo_description").find("nowhere_description")
    message = str(error.value)
    assert "the workspace" in message and "--package NAME=DIR" in message


def test_remote_meshes_are_recognised():
    assert is_remote("https://fuel.gazebosim.org/1.0/OpenRobotics/models/X/1/files/m.dae")
    assert not is_remote("package://foo/m.dae")


def test_xacro_find_with_a_relative_package_directory(tmp_path):
    """--package desc=desc (relative, as README shows) resolves once: not desc/urdf/desc/..."""
    desc = tmp_path / "desc"
    (desc / "urdf").mkdir(parents=True)
    (desc / "urdf" / "part.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<link name="part"/></robot>\n')
    (desc / "urdf" / "r.urdf.xacro").write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <link name="base"/>\n'
        '  <xacro:include filename="$(find desc)/urdf/part.xacro"/>\n'
        '  <joint name="j" type="fixed"><parent link="base"/><child link="part"/></joint>\n'
        "</robot>\n")
    result = run_servicebot("expand", "desc/urdf/r.urdf.xacro", "--package", "desc=desc",
                            cwd=tmp_path, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert '<link name="part"/>' in result.stdout


def test_a_ros2_workspace_checks_clean_from_anywhere(workspace, tmp_path):
    urdf = workspace / "src" / "foo_description" / "urdf" / "r.urdf"
    urdf.write_text(
        '<?xml version="1.0"?>\n<robot name="r">\n  <link name="base_footprint"/>\n'
        '  <joint name="fix" type="fixed"><parent link="base_footprint"/>'
        '<child link="base"/></joint>\n'
        '  <link name="base">\n    <visual><geometry>'
        '<mesh filename="package://foo_description/meshes/link.stl"/></geometry></visual>\n'
        "  </link>\n</robot>\n")
    for cwd in (tmp_path, workspace, urdf.parent):
        result = run_servicebot("check", urdf, "--select", "SB4", cwd=cwd, env=NO_ROS)
        assert "SB401" not in result.stdout, (cwd, result.stdout)


def test_a_doubled_slash_after_the_package_stays_in_the_package(workspace):
    """package://foo_description//meshes/link.stl: resource_retriever joins the package's
    directory and '//meshes/link.stl', which is the package's file; read as '/meshes/...',
    it made SB401 'does not exist' on a file that is there."""
    foo = workspace / "src" / "foo_description"
    found = _resolver().resolve_uri("package://foo_description//meshes/link.stl", foo / "urdf")
    assert found == foo / "meshes" / "link.stl" and found.is_file()
