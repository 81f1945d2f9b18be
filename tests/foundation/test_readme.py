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
