"""Helpers shared by the check tests: fixture paths and JSON runs."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

FIXTURES = Path(__file__).resolve().parent / "fixtures"


def fixture(code: str) -> Path:
    """The one fixture of rule ``code``."""
    (found,) = [p for p in FIXTURES.iterdir() if p.name.startswith(f"{code}_")]
    return found


def findings(stdout: str) -> list[dict[str, Any]]:
    """Every finding of a ``--format json`` run."""
    document = json.loads(stdout)
    return [f for file in document["files"] for f in file["findings"]]


def codes(stdout: str) -> set[str]:
    """The codes found by a ``--format json`` run."""
    return {f["code"] for f in findings(stdout)}
