"""Helpers for the inspect tests: JSON of a run, and small robots written on the fly."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest


@pytest.fixture
def inspect_json(run):
    """``servicebot inspect ARGS --format json`` parsed; fails on a non-zero exit."""

    def _json(*args: object) -> dict[str, Any]:
        result = run("inspect", *args, "--format", "json")
        assert result.exit_code == 0, result.stderr
        return json.loads(result.stdout)

    return _json


def write_chain(path: Path, n: int, *, name: str = "chain") -> Path:
    """A URDF with ``n`` revolute joints in a row, each link a small box."""
    links = "".join(
        f'<link name="l{i}"><visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>'
        f'<inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
        f"</inertial></link>"
        for i in range(n + 1)
    )
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        f'<origin xyz="0 0 0.1"/><axis xyz="0 1 0"/>'
        f'<limit lower="-1" upper="1" velocity="1" effort="1"/></joint>'
        for i in range(n)
    )
    path.write_text(f'<robot name="{name}">{links}{joints}</robot>')
    return path
