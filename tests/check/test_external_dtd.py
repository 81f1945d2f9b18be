"""A DOCTYPE naming an external DTD: a warning, as no reader loads it (check_urdf passes it)."""

from __future__ import annotations

from tests.check.corpus import check_urdf_rejects
from tests.check.helpers import findings

ROBOT = ('<?xml version="1.0"?>\n<!DOCTYPE robot SYSTEM "http://example.com/urdf.dtd">\n'
         '<robot name="r"><link name="{name}"/></robot>\n')


def test_an_external_dtd_alone_is_a_warning_at_the_doctype(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(name="a"))
    assert not check_urdf_rejects(path)
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB005"]
    assert found["severity"] == "warning" and (found["line"], found["column"]) == (2, 53)
    assert "never loaded" in found["message"]


def test_an_entity_only_that_dtd_could_declare_is_an_error(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(name="a&suffix;"))
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 1
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB005"]
    assert found["severity"] == "error" and found["line"] == 3
    assert "'&suffix;'" in found["message"]


def test_a_xacro_file_with_an_external_dtd_is_a_warning_too(run, tmp_path):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(ROBOT.format(name="a").replace(
        '<robot name="r">', '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'))
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    assert [f["severity"] for f in findings(result.stdout) if f["code"] == "SB005"] == [
        "warning"]
