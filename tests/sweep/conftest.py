"""Sweep files written into a temporary directory, and a quick scenario for them."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

QUICK = {"duration_s": 8}
"""Eight simulated seconds of the default scenario: the robot drives and the arm moves."""


@pytest.fixture
def write_sweep(tmp_path: Path):
    """Write a sweep document (a dict, or YAML text) as ``sweep.yaml``; return its path."""

    def write(document: dict | str, name: str = "sweep.yaml") -> Path:
        path = tmp_path / name
        path.write_text(document if isinstance(document, str) else yaml.safe_dump(document))
        return path

    return write
