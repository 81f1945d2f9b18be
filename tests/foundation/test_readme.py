"""README's set-up commands are the ones CI runs."""

from __future__ import annotations

from tests.conftest import REPO


def _setup_commands() -> list[str]:
    text = (REPO / "README.md").read_text()
    block = text.split("```sh\n", 1)[1].split("```", 1)[0]
    return [line for line in block.splitlines() if line.strip()]


def test_readme_starts_with_two_setup_commands():
    text = (REPO / "README.md").read_text()
    assert text.splitlines()[0] == "# servicebot"
    assert text.split("\n", 2)[2].startswith("```sh\n"), "the commands come first"
    install_and_run, install_and_test = _setup_commands()
    assert install_and_run.endswith("servicebot check urdf")
    assert "'.[test]'" in install_and_test and "pytest" in install_and_test


def test_ci_runs_the_readme_test_command():
    ci = (REPO / ".ci" / "run").read_text().splitlines()
    assert _setup_commands()[1] in ci


def _yaml_blocks() -> list[str]:
    text = (REPO / "README.md").read_text()
    return [part.split("```", 1)[0] for part in text.split("```yaml\n")[1:]]


def test_the_pre_commit_recipe_names_a_hook_and_a_release_that_exist():
    import yaml

    from servicebot_cli import __version__

    recipe = next(yaml.safe_load(b) for b in _yaml_blocks() if "servicebot-check" in b)
    [repo] = recipe["repos"]
    hooks = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text())
    assert [h["id"] for h in repo["hooks"]] == [hooks[0]["id"]]
    assert repo["rev"] == f"v{__version__}"


def test_the_pre_commit_hook_runs_as_written(tmp_path):
    import shlex
    import shutil

    import yaml

    from tests.conftest import SIM_URDF, run_servicebot

    [hook] = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text())
    shutil.copy(SIM_URDF, tmp_path / "robot.urdf")
    program, *args = shlex.split(hook["entry"])
    assert program == "servicebot"
    result = run_servicebot(*args, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "1 file checked" in result.stdout


def test_the_github_actions_recipe_installs_this_project_from_its_repository():
    import re

    from packaging.requirements import Requirement  # matplotlib's dependency

    job = next(b for b in _yaml_blocks() if "pip install" in b)
    line = next(ln for ln in job.splitlines() if "pip install" in ln)
    requirement = Requirement(line.split("pip install", 1)[1].strip().strip("'\""))
    name = re.search(r'^name = "([^"]+)"', (REPO / "pyproject.toml").read_text(), re.M).group(1)
    assert requirement.name == name
    assert requirement.url and requirement.url.startswith("git+https://")
