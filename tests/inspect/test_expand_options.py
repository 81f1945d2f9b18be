"""``expand``'s options: ``-o`` is a URDF path checked before any work; idle options refused.

(``expand`` is the inspect area's xacro front end; its expansion is tested in foundation/.)
"""

from __future__ import annotations

import pytest

from tests.conftest import REAL_URDF, SIM_URDF, XACRO_SOURCE, assert_one_line_error


@pytest.mark.parametrize("name", ["real.urdf", "real.urdf.xml", "real.xml", "REAL.URDF"])
def test_urdf_names_are_written(run, tmp_path, name):
    result = run("expand", XACRO_SOURCE, "hardware:=real", "-o", tmp_path / name)
    assert result.exit_code == 0, result.stderr
    assert (tmp_path / name).read_text() == REAL_URDF.read_text()


def test_dash_is_stdout(run):
    result = run("expand", "--robot", "sim", "-o", "-")
    assert result.exit_code == 0 and result.stdout == SIM_URDF.read_text()


@pytest.mark.parametrize(("target", "needle"), [
    ("robot.txt", "URDF files end in .urdf or .xml"),
    ("robot.xacro", "name it e.g. 'robot.urdf'"),
])
def test_bad_output_paths_are_refused_before_the_xacro_is_read(run, tmp_path, target, needle):
    result = run("expand", tmp_path / "nope.xacro", "-o", tmp_path / target)
    assert_one_line_error(result, 2, "--output", needle)
    assert list(tmp_path.iterdir()) == []


def test_missing_output_directories_are_created_as_xacro_does(run, tmp_path):
    out = tmp_path / "build" / "urdf" / "robot.urdf"
    result = run("expand", XACRO_SOURCE, "hardware:=real", "-o", out)
    assert result.exit_code == 0, result.stderr
    assert out.read_text() == REAL_URDF.read_text()
    assert [p.name for p in out.parent.iterdir()] == ["robot.urdf"]  # no temporary file left


def test_a_file_in_the_way_of_the_output_directory_is_refused(run, tmp_path):
    (tmp_path / "build").write_text("")
    result = run("expand", XACRO_SOURCE, "-o", tmp_path / "build" / "robot.urdf")
    assert result.exit_code == 2, result.stdout
    assert (tmp_path / "build").read_text() == ""


def test_a_directory_is_not_an_output_file(run, tmp_path):
    (tmp_path / "out.urdf").mkdir()
    assert_one_line_error(run("expand", "-o", tmp_path / "out.urdf"), 2, "is a directory")


def test_robot_and_a_hardware_argument_together_are_refused(run):
    """Without a FILE, --robot picks hardware:=...; both given, one would be ignored."""
    result = run("expand", "--robot", "real", "hardware:=sim")
    assert_one_line_error(result, 2, "hardware:=sim", "--robot real", "not both")


def test_package_without_a_file_is_refused(run, tmp_path):
    result = run("expand", "--package", f"pkg={tmp_path}")
    assert_one_line_error(result, 2, "--package has no effect without a xacro FILE")
    assert run("expand", XACRO_SOURCE, "--package", f"pkg={tmp_path}").exit_code == 0
