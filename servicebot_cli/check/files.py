"""Which files ``check urdf`` reads: the ones given, and robot files found in directories.

In a directory, a xacro include is checked through the files that include it, not alone: a
file that only defines macros or has an unnamed ``<robot>``, and a file another robot file
of the same walk includes (``turtlebot3_burger.gazebo.xacro``, ``common_properties.xacro``).
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

from servicebot_cli.description.packages import holding_package

SUFFIXES = (".urdf", ".urdf.xml", ".xacro")
SKIPPED_DIRS = {"build", "install", "log", "node_modules", "__pycache__", "site-packages"}
_ROBOT_TAG = re.compile(rb"<robot\b[^>]*>", re.DOTALL)
_MACRO_BLOCK = re.compile(rb"<xacro:macro\b.*?</xacro:macro>", re.DOTALL)
_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)
_CONTENT = re.compile(rb"<(?:link|joint|xacro:(?!include\b|property\b|arg\b|macro\b)[\w.-]+)\b")
_INCLUDE = re.compile(rb"<xacro:include\b[^>]*?\bfilename\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_FIND = re.compile(r"^\$\(find\s+([^)\s]+)\s*\)/*(.*)$")
_HEAD_BYTES = 1 << 20


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
            head = handle.read(_HEAD_BYTES)
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
    """Robot files under ``directory``, sorted, skipping hidden and build directories.

    Includes are left out: macro libraries, unnamed robots, and files that another robot
    file of the walk includes.
    """
    found: list[Path] = []
    for root, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS)
        found.extend(path for name in sorted(files)
                     if is_robot_file(path := Path(root) / name) and not is_fragment(path))
    included = included_by(found)
    yield from (path for path in found if path not in included)


def included_by(paths: list[Path]) -> set[Path]:
    """Which of ``paths`` another of them includes with ``<xacro:include filename>``.

    ``$(find PKG)/REL`` matches a file of package PKG whose path ends with REL (in the
    source tree or as installed: ``description/urdf/x.xacro`` is installed as ``urdf/x.xacro``);
    a relative filename is relative to the including file. Computed names (``${...}``,
    ``$(arg ...)``) match nothing.
    """
    included: set[Path] = set()
    for path in paths:
        for target in _include_targets(path):
            included.update(p for p in paths if p != path and _names(target, path, p))
    return included


def _include_targets(path: Path) -> list[str]:
    """The filenames of the ``<xacro:include>`` elements of a ``.xacro`` (comments removed)."""
    if path.suffix != ".xacro":
        return []
    try:
        with path.open("rb") as handle:
            text = _COMMENT.sub(b"", handle.read(_HEAD_BYTES))
    except OSError:
        return []
    targets = ((double or single).decode("utf-8", "replace").strip()
               for double, single in _INCLUDE.findall(text))
    return [t for t in targets if t and "${" not in t and "$(arg" not in t]


def _names(target: str, includer: Path, candidate: Path) -> bool:
    """Whether the include ``target`` written in ``includer`` can be ``candidate``."""
    match = _FIND.match(target)
    if match is None:
        if "$(" in target:
            return False
        return os.path.normpath(includer.parent / target) == os.path.normpath(candidate)
    package, relative = match.groups()
    if not relative or not candidate.as_posix().endswith("/" + relative):
        return False
    holder = holding_package(candidate.parent.absolute())
    return holder is not None and holder[0] == package
