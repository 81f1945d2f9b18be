"""The command's shape: version, help, subcommands, light imports, shell completion."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from servicebot_cli import __version__
from tests.conftest import REPO, SIM_URDF, run_servicebot

SUBCOMMANDS = ["check", "drive", "emulate", "expand", "fk", "ik", "inspect", "simulate", "sweep"]
HEAVY = {"pinocchio", "trimesh", "yourdfpy", "matplotlib", "numpy", "xacro", "serial", "scipy",
         "lxml"}

_PROBE = """
import atexit, json, sys
atexit.register(lambda: print("MODULES=" + json.dumps(sorted(sys.modules)), file=sys.stderr))
from servicebot_cli.cli import main
main(sys.argv[1:], prog_name="servicebot")
"""


def _imported(args: list[str], env: dict[str, str] | None = None) -> tuple[set[str], str]:
    result = subprocess.run([sys.executable, "-c", _PROBE, *args], capture_output=True, text=True,
                            env={**os.environ, **(env or {})}, timeout=60)
    line = next(ln for ln in result.stderr.splitlines() if ln.startswith("MODULES="))
    modules = {name.split(".")[0] for name in json.loads(line[len("MODULES="):])}
    return modules, result.stdout


def test_version(run):
    result = run("--version")
    assert result.exit_code == 0
    assert result.stdout.strip() == f"servicebot, version {__version__}"


def test_help_lists_every_subcommand_and_the_exit_codes(run):
    result = run("--help")
    assert result.exit_code == 0
    listed = [line.split()[0] for line in result.stdout.split("Commands:")[1].splitlines()
              if line.strip()]
    assert listed == SUBCOMMANDS
    assert "130 interrupted" in result.stdout


@pytest.mark.parametrize("command", SUBCOMMANDS)
def test_each_subcommand_has_help_with_the_robot_arguments(run, command):
    result = run(command, "--help")
    assert result.exit_code == 0
    assert "[NAME:=VALUE]..." in result.stdout
    assert "--robot" in result.stdout and "--package" in result.stdout


@pytest.mark.parametrize("args", [["--help"], ["fk", "--help"], ["check", "--help"],
                                  ["drive", "--help"], ["emulate", "--help"]])
def test_help_imports_nothing_heavy(args):
    modules, stdout = _imported(args)
    assert "Usage:" in stdout
    assert not HEAVY & modules, HEAVY & modules


def test_shell_completion_is_light_and_completes(tmp_path):
    env = {"_SERVICEBOT_COMPLETE": "bash_complete", "COMP_WORDS": "servicebot fk --robot ",
           "COMP_CWORD": "3"}
    modules, stdout = _imported([], env)
    assert not HEAVY & modules, HEAVY & modules
    assert stdout.split() == ["plain,sim", "plain,real"]
    env = {"_SERVICEBOT_COMPLETE": "bash_complete", "COMP_WORDS": "servicebot si",
           "COMP_CWORD": "1"}
    assert _imported([], env)[1].split() == ["plain,simulate"]


@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_completion_scripts_are_up_to_date(shell):
    result = run_servicebot(env={"_SERVICEBOT_COMPLETE": f"{shell}_source"})
    assert result.returncode == 0, result.stderr
    committed = REPO / "completions" / f"servicebot.{shell}"
    assert committed.read_text() == result.stdout, (
        f"completions/servicebot.{shell} is stale; regenerate with "
        f"_SERVICEBOT_COMPLETE={shell}_source servicebot > completions/servicebot.{shell}"
    )


def test_bundled_robot_found_from_an_installed_layout(tmp_path):
    """A wheel puts robots/ inside the package; the resolver must find it there."""
    import shutil

    package = tmp_path / "servicebot_cli"
    shutil.copytree(REPO / "servicebot_cli", package,
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(REPO / "robots", package / "robots")
    code = ("from servicebot_cli.description.resources import bundled_robot;"
            "print(bundled_robot('sim'))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(tmp_path)})
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == str(package / "robots" / "service_robot.urdf.xml")


def test_python_dash_m_runs_the_same_command():
    result = run_servicebot("expand", "--robot", "sim")
    assert result.returncode == 0
    assert result.stdout == SIM_URDF.read_text()


def test_debug_shows_the_traceback():
    result = run_servicebot("--debug", "fk", "/nonexistent")
    assert result.returncode != 0
    assert "Traceback" in result.stderr and "DescriptionError" in result.stderr
