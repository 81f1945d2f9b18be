"""``servicebot check`` from the command line: shapes, exit codes, settings, suppression."""

from __future__ import annotations

import os
import pty
import shutil
import subprocess
import sys

import pytest

from servicebot_cli.check import tree
from tests.check.helpers import codes, findings, fixture
from tests.conftest import (
    REPO,
    ROBOTS,
    SIM_URDF,
    XACRO_SOURCE,
    assert_one_line_error,
    run_servicebot,
)
from tests.foundation.test_cli_shape import HEAVY, _imported

DOC_INERTIA = REPO / "tests" / "fixtures" / "doc_inertia.urdf.xacro"


@pytest.mark.parametrize("args", [["check", "urdf"], ["check"], ["check", "--robot", "real"],
                                  ["check", "urdf", XACRO_SOURCE, "hardware:=real"],
                                  ["check", "urdf", ROBOTS]])
def test_the_bundled_robot_passes_with_no_warning(run, args):
    result = run(*args, "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    severities = {f["severity"] for f in findings(result.stdout)}
    assert severities <= {"info"}, result.stdout
    assert codes(result.stdout) <= {"SB309"}


def test_a_directory_is_walked_and_xacro_includes_are_skipped(run):
    result = run("check", "urdf", ROBOTS, "--format", "json", "--isolated")
    import json

    files = [f["file"] for f in json.loads(result.stdout)["files"]]
    assert [os.path.basename(f) for f in files] == [
        "service_robot.urdf.xacro", "service_robot.urdf.xml", "service_robot_real.urdf.xml"]


def test_check_file_is_short_for_check_urdf_file(run):
    path = fixture("SB205")
    assert run("check", path).stdout == run("check", "urdf", path).stdout


def test_text_is_compiler_style_with_the_summary_last(run):
    result = run("check", fixture("SB205"), "--isolated", "--ignore", "SB309")
    lines = result.stdout.splitlines()
    assert result.exit_code == 1
    assert lines[0] == (f"{fixture('SB205')}:26:3: error SB205 [negative-effort-velocity] "
                        "joint 'shoulder' has effort limit -10")
    assert lines[1] == '    fix: effort="10"'
    assert lines[-1] == "1 file checked: 1 error, 0 warnings, 1 info; failed"
    assert "\x1b[" not in result.stdout


def test_xacro_findings_point_into_the_xacro_source_and_the_macro_call(run):
    result = run("check", DOC_INERTIA, "--format", "json", "--isolated")
    wheel = next(f for f in findings(result.stdout) if "front_left_wheel" in f["message"])
    assert (wheel["file"], wheel["line"], wheel["column"]) == (str(DOC_INERTIA), 31, 7)
    assert wheel["via"] == f"{DOC_INERTIA}:57:3"


def test_the_documentation_inertia_values_are_flagged_with_the_geometry_values(run):
    result = run("check", DOC_INERTIA, "--isolated")
    assert result.exit_code == 0  # warnings only
    assert result.stdout.count("warning SB301") == 5
    assert "fix: use ixx=0.00135833 iyy=0.00245 izz=0.00135833 (ixy=ixz=iyz=0)" in result.stdout
    assert "fix: use ixx=0.241667 iyy=0.241667 izz=0.416667 (ixy=ixz=iyz=0)" in result.stdout
    assert run("check", DOC_INERTIA, "--strict", "--isolated").exit_code == 1


def test_strict_select_and_ignore(run):
    path = fixture("SB208")  # a warning
    assert run("check", path, "--isolated").exit_code == 0
    assert run("check", path, "--strict", "--isolated").exit_code == 1
    assert codes(run("check", path, "--ignore", "SB208,SB309", "--format", "json",
                     "--isolated").stdout) == set()
    only = run("check", fixture("SB301"), "--select", "SB3", "--ignore", "SB309", "--format",
               "json", "--isolated")
    assert codes(only.stdout) == {"SB301"}


def test_unknown_rule_code_is_one_line(run):
    assert_one_line_error(run("check", SIM_URDF, "--select", "SB999"), 2, "no rule 'SB999'")
    assert_one_line_error(run("check", "--explain", "SB99"), 2, "did you mean")


def test_list_rules_and_explain(run):
    listed = run("check", "--list-rules")
    assert listed.exit_code == 0
    assert "SB301  warning   inertia-mismatch" in listed.stdout
    explained = run("check", "urdf", "--explain", "inertia-mismatch")
    assert explained.stdout.startswith("SB301 inertia-mismatch (warning, Inertia)")
    assert "<!-- servicebot: ignore SB301 -->" in explained.stdout


@pytest.mark.parametrize("args", [["check", "--list-rules"], ["check", "--explain", "SB107"],
                                  ["check", "controllers", "--help"]])
def test_catalogue_answers_import_nothing_heavy(args):
    modules, stdout = _imported(args)
    assert stdout
    assert not HEAVY & modules, HEAVY & modules


def _write_settings(directory, table):
    (directory / "pyproject.toml").write_text(f"[tool.servicebot.check]\n{table}\n")


def test_settings_from_the_nearest_pyproject(tmp_path):
    _write_settings(tmp_path, 'strict = true\nseverity = { SB309 = "error" }')
    nested = tmp_path / "a" / "b"
    nested.mkdir(parents=True)
    robot = shutil.copy(fixture("SB208"), nested / "robot.urdf")
    result = run_servicebot("check", "robot.urdf", "--format", "json", cwd=nested)
    assert result.returncode == 1
    severities = {f["code"]: f["severity"] for f in findings(result.stdout)}
    assert severities == {"SB208": "warning", "SB309": "error", "SB702": "info"}
    assert run_servicebot("check", robot, "--isolated", cwd=nested).returncode == 0
    assert run_servicebot("check", robot, "--no-strict", "--ignore", "SB309",
                          cwd=nested).returncode == 0


@pytest.mark.parametrize(("table", "needle"), [
    ("colour = true", "has no setting 'colour'"),
    ('select = "SB1"', "must be a list"),
    ('ignore = ["SB3O1"]', "no rule 'SB3O1'"),
    ('severity = { SB301 = "fatal" }', "must be error, warning or info"),
    ("inertia-factor = 0.5", "above 1"),
    ("inertia-factor = inf", "a finite number above 1"),  # SB301 silently off otherwise
    ("strict = [", "cannot read settings"),
])
def test_bad_settings_are_one_line(tmp_path, table, needle):
    _write_settings(tmp_path, table)
    result = run_servicebot("check", SIM_URDF, cwd=tmp_path)
    assert_one_line_error(result, 2, "pyproject.toml", needle)


@pytest.mark.parametrize(("text", "needle"), [
    ("[tool.servicebot]\nstrict = true\n", "[tool.servicebot] has 'strict'"),
    ("[tool.servicebot.checks]\nstrict = true\n", "[tool.servicebot] has 'checks'"),
])
def test_settings_outside_the_check_table_are_refused_not_dropped(tmp_path, text, needle):
    (tmp_path / "pyproject.toml").write_text(text)
    result = run_servicebot("check", SIM_URDF, cwd=tmp_path)
    assert_one_line_error(result, 2, "pyproject.toml", needle)
    assert "[tool.servicebot.check]" in result.stderr


def test_inline_comment_silences_one_rule_on_one_element(run, tmp_path):
    text = fixture("SB301").read_text()
    silenced = tmp_path / "silenced.urdf"
    silenced.write_text(text.replace('  <link name="arm">',
                                     '  <!-- servicebot: ignore SB301 -->\n  <link name="arm">'))
    assert "SB301" not in codes(run("check", silenced, "--format", "json").stdout)
    other = tmp_path / "other.urdf"
    other.write_text(text.replace('  <link name="arm">',
                                  '  <!-- servicebot: ignore SB302 -->\n  <link name="arm">'))
    assert "SB301" in codes(run("check", other, "--format", "json").stdout)


def test_inline_comment_inside_a_xacro_macro(run, tmp_path):
    text = DOC_INERTIA.read_text().replace(
        '    <link name="${prefix}_wheel">',
        '    <!-- servicebot: ignore SB301 -->\n    <link name="${prefix}_wheel">')
    (tmp_path / "doc.urdf.xacro").write_text(text)
    result = run("check", tmp_path / "doc.urdf.xacro", "--format", "json")
    messages = [f["message"] for f in findings(result.stdout) if f["code"] == "SB301"]
    assert len(messages) == 1 and "base_link" in messages[0]


def test_output_file_is_written_atomically_with_the_summary_on_stderr(run, tmp_path):
    out = tmp_path / "report.json"
    result = run("check", fixture("SB205"), "--format", "json", "-o", out, "--isolated")
    assert result.exit_code == 1 and result.stdout == ""
    assert result.stderr.strip() == "1 file checked: 1 error, 0 warnings, 2 info; failed"
    assert codes(out.read_text()) == {"SB205", "SB309", "SB702"}
    missing = tmp_path / "nope" / "report.json"
    assert_one_line_error(run("check", SIM_URDF, "-o", missing), 2, "does not exist")
    assert not missing.parent.exists()


def test_colour_only_on_a_terminal():
    piped = run_servicebot("check", fixture("SB205"), "--isolated")
    assert "\x1b[" not in piped.stdout
    leader, follower = pty.openpty()
    process = subprocess.Popen([sys.executable, "-m", "servicebot_cli", "check",
                                str(fixture("SB205")), "--isolated"], stdout=follower,
                               stderr=subprocess.DEVNULL)
    os.close(follower)
    output = b""
    while True:
        try:
            chunk = os.read(leader, 4096)
        except OSError:
            break
        if not chunk:
            break
        output += chunk
    os.close(leader)
    assert process.wait(timeout=60) == 1
    assert b"\x1b[31m" in output and b"error" in output


@pytest.mark.parametrize("args", [["controllers"], ["controllers", "--robot", "real"],
                                  ["controllers", ROBOTS / "controllers.yaml", "--urdf",
                                   XACRO_SOURCE, "hardware:=real"]])
def test_the_bundled_controllers_agree_with_the_bundled_robots(run, args):
    result = run("check", *args, "--isolated")
    assert result.exit_code == 0, result.stdout
    assert result.stdout.splitlines()[-1].endswith("0 errors, 0 warnings, 0 info; passed")


def test_controllers_bad_input(run, tmp_path):
    assert_one_line_error(run("check", "controllers", tmp_path / "nope.yaml"), 2, "no such file",
                          "controllers YAML")
    assert_one_line_error(run("check", "controllers", "a.yaml", "b.yaml"), 2, "one controllers")
    assert_one_line_error(run("check", "controllers", "--urdf", SIM_URDF, "--robot", "sim"), 2,
                          "not both")


def test_an_internal_error_is_exit_3_without_traceback(run, monkeypatch):
    def broken(robot):
        raise RuntimeError("rule bug")
        yield

    monkeypatch.setattr(tree, "check", broken)
    result = run("check", SIM_URDF)
    assert_one_line_error(result, 3, "internal error: RuntimeError: rule bug", "--debug")
