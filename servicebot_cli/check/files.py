"""Which files ``check urdf`` reads: the ones given, and robot files found in directories."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

SUFFIXES = (".urdf", ".urdf.xml", ".xacro")
SKIPPED_DIRS = {"build", "install", "log", "node_modules", "__pycache__", "site-packages"}
_ROBOT_TAG = re.compile(rb"<robot\b[^>]*>", re.DOTALL)
_MACRO_BLOCK = re.compile(rb"<xacro:macro\b.*?</xacro:macro>", re.DOTALL)
_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)
_CONTENT = re.compile(rb"<(?:link|joint|xacro:(?!include\b|property\b|arg\b|macro\b)[\w.-]+)\b")


def is_robot_file(path: Path) -> bool:
    """True for ``*.urdf``, ``*.urdf.xml`` and ``*.xacro`` names."""
    return path.name.lower().endswith(SUFFIXES)


def is_fragment(path: Path) -> bool:
    """True for a xacro include, checked through the files that include it.

    Its ``<robot>`` has no name, or it only defines macros: no link, joint or macro call
    outside its ``<xacro:macro>`` definitions (a macro library such as ``panda_arm.xacro``).
    """
    if path.suffix != ".xacro":
        return False
    try:
        with path.open("rb") as handle:
            head = handle.read(1 << 20)
    except OSError:
        return False  # reading it again will report the problem
    match = _ROBOT_TAG.search(head)
    if match is None:
        return False
    if b"name=" not in match.group(0):
        return True
    text = _COMMENT.sub(b"", head)
    outside = _MACRO_BLOCK.sub(b"", text)
    return outside != text and _CONTENT.search(outside) is None


def walk(directory: Path) -> Iterator[Path]:
    """Robot files under ``directory``, sorted, skipping hidden and build directories."""
    for root, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS)
        for name in sorted(files):
            path = Path(root) / name
            if is_robot_file(path) and not is_fragment(path):
                yield path
