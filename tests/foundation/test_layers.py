"""The layer contract in pyproject.toml holds, and it would catch an upward import."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import REPO

LINT_IMPORTS = Path(sys.executable).with_name("lint-imports")


def _lint(root: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(LINT_IMPORTS), "--no-logo", "--no-cache"], cwd=root,
                          capture_output=True, text=True, timeout=120,
                          env={"PYTHONPATH": str(root), "PATH": "/usr/bin:/bin"})


def test_the_layers_hold():
    result = _lint(REPO)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "1 kept, 0 broken" in result.stdout


@pytest.mark.parametrize(("module", "upward"), [
    ("description/loader.py", "servicebot_cli.output.table"),    # a lower layer imports up
    ("check/findings.py", "servicebot_cli.simulate.summary"),   # one feature imports another
    ("common/files.py", "servicebot_cli.description.resources"),
])
def test_an_upward_import_breaks_the_build(tmp_path, module, upward):
    shutil.copytree(REPO / "servicebot_cli", tmp_path / "servicebot_cli",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(REPO / "pyproject.toml", tmp_path)
    path = tmp_path / "servicebot_cli" / module
    path.write_text(path.read_text() + f"\nimport {upward}  # noqa\n")
    result = _lint(tmp_path)
    assert result.returncode != 0
    assert "BROKEN" in result.stdout and upward in result.stdout
