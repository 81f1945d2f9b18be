"""An output option never replaces a file the command reads; a device is written into."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from tests.conftest import SIM_URDF, assert_one_line_error

CONTROLLERS = Path(SIM_URDF).parent / "controllers.yaml"


@pytest.fixture
def robot(tmp_path) -> Path:
    copy = tmp_path / "robot.urdf"
    shutil.copy(SIM_URDF, copy)
    return copy


@pytest.mark.parametrize("command", [
    ["check", "urdf", "{robot}", "--isolated", "-o", "{robot}"],
    ["check", "urdf", "{dir}", "--isolated", "-o", "{robot}"],
    ["check", "controllers", "{yaml}", "--urdf", "{robot}", "--isolated", "-o", "{yaml}"],
    ["expand", "{robot}", "-o", "{robot}"],
    ["fk", "{robot}", "--configs", "{csv}", "-o", "{csv}"],
], ids=["check a file", "check its directory", "check controllers", "expand", "fk batch"])
def test_an_output_that_is_an_input_is_refused_and_the_input_kept(run, tmp_path, robot,
                                                                   command):
    yaml = tmp_path / "controllers.yaml"
    shutil.copy(CONTROLLERS, yaml)
    csv = tmp_path / "configs.csv"
    csv.write_text("arm_base_to_link1\n0.1\n")
    before = {p: p.read_bytes() for p in (robot, yaml, csv)}
    args = [a.format(robot=robot, dir=tmp_path, yaml=yaml, csv=csv) for a in command]
    target = args[-1]
    assert_one_line_error(run(*args), 2, f"-o {target} is the file it reads; give another name")
    assert {p: p.read_bytes() for p in before} == before


def test_a_report_beside_the_robot_files_is_written(run, tmp_path, robot):
    report = tmp_path / "report.txt"
    result = run("check", "urdf", tmp_path, "--isolated", "-o", report)
    assert result.exit_code == 0, result.stderr
    assert "robot.urdf" in report.read_text()


def test_expand_writes_into_a_device_as_a_shell_would(run, robot):
    """README: a device or a named pipe, such as /dev/stdout, is written into as '>' would."""
    result = run("expand", robot, "-o", "/dev/null")
    assert result.exit_code == 0, result.stderr
    assert_one_line_error(run("expand", robot, "-o", "/dev/full"), 2, "No space left on device")
