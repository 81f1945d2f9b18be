"""Shared test helpers: repository paths and a CLI runner.

Each area of the tool keeps its tests (and any fixtures of its own) in a subdirectory:
``foundation/``, ``check/``, ``inspect/``, ``kinematics/``, ``simulate/``, ``drive/``.
"""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from servicebot_cli.cli import main

REPO = Path(__file__).resolve().parents[1]
ROBOTS = REPO / "robots"
FIXTURES = REPO / "tests" / "fixtures"
SIM_URDF = ROBOTS / "service_robot.urdf.xml"
REAL_URDF = ROBOTS / "service_robot_real.urdf.xml"
XACRO_SOURCE = ROBOTS / "service_robot.urdf.xacro"
CONTROLLERS_YAML = ROBOTS / "controllers.yaml"

RunCli = Callable[..., Result]

_READY_LOOP = """
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.frames import link_names
from servicebot_cli.kinematics.inverse import IkSolver
robot = load(RobotSource.bundled("sim"))
solver = IkSolver(Chain(robot.model, robot.joint_space, "arm_tool_link", link_names(robot)))
solver.prepare()
# a batch's chunks run the loop over a series of targets, a loop of its own in numba's cache
solver._compiled.ready(series=True)
"""


@pytest.fixture(scope="session", autouse=True)
def compiled_ik_loop(tmp_path_factory: pytest.TempPathFactory) -> None:
    """Batch ik's loops (one target, a series) compiled before any test, as on a machine that
    has run them once.

    The first batch on a machine compiles it (seconds, and a line on stderr saying so); tests
    of what a batch prints must not depend on which of them ran first. Readied here for this
    checkout and, from a directory outside it, for the installed copy that commands started
    elsewhere import (each keeps its own numba cache).
    """
    subprocess.run([sys.executable, "-c", _READY_LOOP], check=True, cwd=REPO)
    subprocess.run([sys.executable, "-c", _READY_LOOP], check=True,
                   cwd=tmp_path_factory.mktemp("elsewhere"))


@pytest.fixture
def run() -> RunCli:
    """Run ``servicebot ARGS...`` in-process; stdout and stderr are kept apart."""
    runner = CliRunner()

    def _run(*args: object, input: str | None = None, env: dict[str, str] | None = None) -> Result:
        return runner.invoke(main, [str(a) for a in args], input=input, env=env,
                             prog_name="servicebot", catch_exceptions=False)

    return _run


def run_servicebot(*args: object, env: dict[str, str] | None = None, timeout: float = 60,
                   **kwargs: object) -> subprocess.CompletedProcess[str]:
    """Run ``servicebot ARGS...`` as a real process (``python -m servicebot_cli``)."""
    full_env = {**os.environ, **(env or {})}
    return subprocess.run(
        [sys.executable, "-m", "servicebot_cli", *map(str, args)],
        capture_output=True, text=True, env=full_env, timeout=timeout, **kwargs,
    )


def assert_one_line_error(result: Result | subprocess.CompletedProcess[str], code: int = 2,
                          *needles: str) -> str:
    """The command failed with ``code`` and exactly one ``Error:`` line; returns that line."""
    exit_code = result.exit_code if isinstance(result, Result) else result.returncode
    stderr = result.stderr
    stdout = result.stdout
    assert exit_code == code, f"exit {exit_code}, stderr: {stderr!r}"
    lines = stderr.splitlines()
    assert len(lines) == 1, f"expected one stderr line, got {lines!r}"
    assert lines[0].startswith("Error: "), lines[0]
    assert "Traceback" not in stderr + stdout
    for needle in needles:
        assert needle in lines[0], f"{needle!r} not in {lines[0]!r}"
    return lines[0]
