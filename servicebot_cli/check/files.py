"""Which files ``check urdf`` reads: the ones given, and robot files found in directories."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

SUFFIXES = (".urdf", ".urdf.xml", ".xacro")
SKIPPED_DIRS = {"build", "install", "log", "node_modules", "__pycache__", "site-packages"}
_ROBOT_TAG = re.compile(rb"<robot\b[^>]*>", re.DOTALL)


def is_robot_file(path: Path) -> bool:
    """True for ``*.urdf``, ``*.urdf.xml`` and ``*.xacro`` names."""
    return path.name.lower().endswith(SUFFIXES)


def is_fragment(path: Path) -> bool:
    """True for a xacro include: its ``<robot>`` has no name (it is checked via its includer)."""
    if path.suffix != ".xacro":
        return False
    try:
        with path.open("rb") as handle:
            head = handle.read(65536)
    except OSError:
        return False  # reading it again will report the problem
    match = _ROBOT_TAG.search(head)
    return match is not None and b"name=" not in match.group(0)


def walk(directory: Path) -> Iterator[Path]:
    """Robot files under ``directory``, sorted, skipping hidden and build directories."""
    for root, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS)
        for name in sorted(files):
            path = Path(root) / name
            if is_robot_file(path) and not is_fragment(path):
                yield path
