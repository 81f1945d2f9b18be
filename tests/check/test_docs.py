"""docs/rules.md and the pre-commit hook stay in step with the code."""

from __future__ import annotations

import shutil

import yaml

from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.rules_doc import markdown
from tests.conftest import REPO, SIM_URDF, run_servicebot


def test_rules_md_is_generated_from_the_catalogue():
    committed = (REPO / "docs" / "rules.md").read_text()
    assert committed == markdown(), (
        "docs/rules.md is stale: python -m servicebot_cli.check.rules_doc > docs/rules.md")
    for code in RULES:
        assert f"### {code}\n" in committed


def test_list_rules_matches_the_catalogue(run):
    listed = run("check", "--list-rules").stdout.splitlines()[2:]
    assert [line.split()[0] for line in listed] == list(RULES)


def test_pre_commit_hook_runs_check(tmp_path):
    (hook,) = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text())
    assert hook["id"] == "servicebot-check" and hook["language"] == "python"
    entry = hook["entry"].split()
    assert entry[0] == "servicebot"
    shutil.copy(SIM_URDF, tmp_path / "robot.urdf")
    args = entry[1:] + ([] if hook.get("pass_filenames", True) else [])
    result = run_servicebot(*args, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "1 file checked" in result.stdout
    (tmp_path / "broken.urdf").write_text('<robot name="r"><link name="a"/><link name="a"/>'
                                          "</robot>")
    assert run_servicebot(*args, cwd=tmp_path).returncode == 1


def test_readme_counts_the_rules_there_are():
    from servicebot_cli.check.catalogue import RULES

    readme = (REPO / "README.md").read_text()
    assert f"- {len(RULES)} rules, each with a code" in readme
