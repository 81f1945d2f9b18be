"""``check`` in one shape: a request, one click-free run, a rendered result, one way to say no."""

from __future__ import annotations

import pytest

from servicebot_cli.check.run import (
    CheckRequest,
    ControllerTargets,
    SettingsChoice,
    UrdfTargets,
)
from servicebot_cli.check.run import run as run_check
from servicebot_cli.description.loader import RobotSource
from tests.check.helpers import codes, fixture
from tests.conftest import CONTROLLERS_YAML, REAL_URDF, SIM_URDF, assert_one_line_error
from tests.foundation.test_cli_shape import HEAVY, _imported

ISOLATED = SettingsChoice(isolated=True)


def test_the_domain_run_needs_no_command_line():
    path = fixture("SB205")
    result = run_check(CheckRequest(UrdfTargets((str(path),)), ISOLATED))
    assert result.failed
    assert [r.file for r in result.reports] == [str(path)]
    assert "SB205" in {f.code for f in result.findings}
    clean = run_check(CheckRequest(UrdfTargets(default=RobotSource.bundled("real")), ISOLATED))
    assert not clean.failed and clean.reports[0].file.endswith("service_robot_real.urdf.xml")


def test_the_domain_run_applies_the_settings_choice():
    path = str(fixture("SB209"))
    only = run_check(CheckRequest(UrdfTargets((path,)),
                                  SettingsChoice(select=("SB2",), isolated=True)))
    assert {f.code[:3] for f in only.findings} == {"SB2"}
    ignored = run_check(CheckRequest(UrdfTargets((path,)),
                               SettingsChoice(ignore=("SB209",), isolated=True)))
    assert "SB209" not in {f.code for f in ignored.findings} and not ignored.failed


def test_the_domain_run_checks_controllers_against_each_urdf():
    targets = ControllerTargets(str(CONTROLLERS_YAML), (RobotSource.of(SIM_URDF),
                                                        RobotSource.of(REAL_URDF)))
    result = run_check(CheckRequest(targets, ISOLATED))
    assert [r.file for r in result.reports] == [
        f"{CONTROLLERS_YAML} against {SIM_URDF}", f"{CONTROLLERS_YAML} against {REAL_URDF}"]
    assert not result.failed


def test_a_failing_check_is_exit_1_with_the_summary_and_no_error_line(run):
    result = run("check", fixture("SB205"), "--isolated")
    assert result.exit_code == 1
    assert result.stderr == ""
    assert result.stdout.splitlines()[-1].endswith("; failed")


def test_a_failing_check_written_to_a_file_says_so_once_on_stderr(run, tmp_path):
    out = tmp_path / "report.sarif"
    result = run("check", fixture("SB205"), "--isolated", "--format", "sarif", "-o", out)
    assert result.exit_code == 1
    assert result.stderr.splitlines() == ["1 file checked: 1 error, 0 warnings, 2 info; failed"]
    assert '"SB205"' in out.read_text()


@pytest.mark.parametrize(("args", "needles"), [
    (["--list-rules", "--explain", "SB301"], ["--list-rules and --explain", "one of them"]),
    (["--explain", "SB301", "--list-rules"], ["--list-rules and --explain"]),
    (["urdf", "--explain", "SB301", "--strict"], ["--explain", "checks nothing", "drop --strict"]),
    (["urdf", SIM_URDF, "--list-rules"], ["--list-rules", "drop FILE"]),
    # the short form too: the FILE, or check urdf's own option, was silently ignored
    (["--list-rules", SIM_URDF], ["--list-rules", "drop FILE"]),
    (["--list-rules", "no_such.urdf"], ["--list-rules", "drop FILE"]),
    (["--explain", "SB301", SIM_URDF], ["--explain", "drop FILE"]),
    (["--list-rules", "--format", "json"], ["--list-rules", "drop --format"]),
    (["controllers", "--format", "json", "--explain", "SB601"], ["drop --format"]),
    ([SIM_URDF, "--config", "pyproject.toml", "--isolated"], ["--config", "--isolated"]),
    (["controllers", "--package", "pkg=."], ["--package has no effect without --urdf FILE"]),
    (["controllers", "--robot", "real", "--package", "pkg=."], ["--package", "--urdf FILE"]),
])
def test_options_that_would_do_nothing_are_refused(run, args, needles):
    assert_one_line_error(run("check", *args), 2, *needles)


def test_the_catalogue_options_still_answer_alone(run):
    assert run("check", "--list-rules").exit_code == 0
    assert run("check", "controllers", "--explain", "SB601").stdout.startswith("SB601 ")


def test_the_output_path_is_checked_before_any_file_is_read(run, tmp_path):
    """A missing input would be exit 2 too: the message shows which was looked at first."""
    missing_input = tmp_path / "nope.urdf"
    assert_one_line_error(run("check", missing_input, "-o", tmp_path), 2, "--output",
                          "is a directory")
    assert_one_line_error(run("check", missing_input, "-o", tmp_path / "a" / "r.json"), 2,
                          "--output", "does not exist")
    assert list(tmp_path.iterdir()) == []


def test_dash_is_stdout(run):
    result = run("check", SIM_URDF, "--isolated", "-o", "-", "--format", "json")
    assert result.exit_code == 0 and codes(result.stdout) <= {"SB309"}


def _complete(*words: str) -> tuple[list[str], set[str]]:
    """Bash completion of the last word, through Click's machinery in a real process."""
    env = {"_SERVICEBOT_COMPLETE": "bash_complete", "COMP_WORDS": " ".join(words),
           "COMP_CWORD": str(len(words) - 1)}
    modules, stdout = _imported([], env=env)
    values = [line.split(",", 1)[1] for line in stdout.splitlines() if "," in line]
    return values, modules


def test_select_completes_codes_and_prefixes_without_heavy_imports():
    values, modules = _complete("servicebot", "check", "--select", "SB3")
    assert values[0] == "SB3" and "SB301" in values
    assert all(v.startswith("SB3") for v in values)
    assert not HEAVY & modules, HEAVY & modules


def test_select_completes_after_a_comma_and_offers_all_first():
    assert _complete("servicebot", "check", "--ignore", "SB1,sb20")[0][:2] == [
        "SB1,SB201", "SB1,SB202"]
    assert _complete("servicebot", "check", "urdf", "--select", "")[0][:2] == ["ALL", "SB0"]
    assert "ALL" not in _complete("servicebot", "check", "--ignore", "")[0]


def test_explain_completes_codes_then_rule_names():
    assert _complete("servicebot", "check", "--explain", "SB30")[0][:2] == ["SB301", "SB302"]
    assert "inertia-mismatch" in _complete("servicebot", "check", "controllers", "--explain",
                                           "inertia-m")[0]
