"""ROS packages on disk: package.xml names, the holding package, workspaces, crawling.

These are the pieces :class:`~servicebot_cli.description.packages.PackageResolver` searches
with: a package is a directory with a ``package.xml``, named by its ``<name>``; a workspace
is found as colcon finds it, and crawled as colcon crawls it.
"""

from __future__ import annotations

import functools
import os
import re
from pathlib import Path

_NAME_RE = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")
_CRAWL_DEPTH = 8  # src/<group>/<repo>/<pkg> and deeper vendored trees, and still instant
_SKIP_DIRS = {"build", "install", "log", "node_modules", "__pycache__", "site-packages"}
_IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
_CRAWL_BUDGET = 5000  # directories visited under one root: a home directory stays instant


def holding_package(directory: Path) -> tuple[str, Path] | None:
    """The name and directory of the nearest package at or above ``directory``."""
    for ancestor in (directory, *directory.parents):
        name = package_name(ancestor)
        if name is not None:
            return name, ancestor
    return None


_COLCON_MADE = ("build", "install", "log")
"""What ``colcon build`` makes at its workspace's root, each marked ``COLCON_IGNORE``."""
_MOST_LEVELS_ABOVE = 3
"""How far above its package a colcon workspace without ``src/`` may be
(``ws/interbotix_ros_rovers/interbotix_ros_xslocobots/interbotix_xslocobot_descriptions``)."""


def workspace_root(directory: Path) -> Path | None:
    """Where the packages of ``directory``'s workspace are looked for.

    The colcon workspace: the directory whose ``src/`` holds ``directory``, or, for one
    built without ``src/``, the nearest that holds a ``build/``, ``install/`` or ``log/``
    colcon marked with ``COLCON_IGNORE``, when it is close (at most
    :data:`_MOST_LEVELS_ABOVE` above the package, and not above the repository's own
    directory: a stray ``colcon build`` in a home directory is no workspace of a repository
    under it). Else the repository root (the nearest directory with ``.git``), else the
    directory above the package that holds ``directory``; None when there is none of these.
    """
    ancestors = (directory, *directory.parents)
    for ancestor in ancestors:
        if ancestor.name == "src" and ancestor.parent != ancestor:
            return ancestor.parent
    repository = next((a for a in ancestors if os.path.exists(a / ".git")), None)
    holder = holding_package(directory)
    base = holder[1] if holder is not None else directory
    highest = base.parents[min(_MOST_LEVELS_ABOVE, len(base.parents)) - 1] \
        if base.parents else base
    if repository is not None and len(repository.parent.parts) > len(highest.parts):
        highest = repository.parent
    for ancestor in ancestors:
        if len(ancestor.parts) < len(highest.parts):
            break
        if any(os.path.isfile(ancestor / made / "COLCON_IGNORE") for made in _COLCON_MADE):
            return ancestor
    if repository is not None:
        return repository
    return None if holder is None else holder[1].parent


def package_name(directory: Path) -> str | None:
    """The package's ``<name>`` if ``directory`` holds a package.xml, else None."""
    manifest = directory / "package.xml"
    try:
        head = manifest.read_bytes()[:65536]
    except OSError:
        return None
    match = _NAME_RE.search(head)
    return match.group(1).decode("utf-8", "replace") if match else directory.name


def _is_directory(entry: os.DirEntry[str]) -> bool:
    """``entry`` is a directory, or a link to one; not a link that loops or is too deep."""
    try:
        return entry.is_dir()
    except OSError:
        return False


@functools.lru_cache(maxsize=64)
def packages_under(root: Path) -> dict[str, Path]:
    """Every package at or under ``root`` by name, nearest first; packages do not nest.

    Hidden directories, build products and trees marked ``COLCON_IGNORE``, ``AMENT_IGNORE``
    or ``CATKIN_IGNORE`` are skipped, as colcon skips them. Cached for the process.
    """
    found: dict[str, Path] = {}
    frontier = [root]
    budget = _CRAWL_BUDGET
    for _ in range(_CRAWL_DEPTH):
        next_frontier: list[Path] = []
        for directory in frontier:
            budget -= 1
            if budget < 0:
                return found
            if any(os.path.exists(directory / marker) for marker in _IGNORE_MARKERS):
                continue
            name = package_name(directory)
            if name is not None:
                found.setdefault(name, directory)
                continue
            try:
                children = sorted(os.scandir(directory), key=lambda e: e.name)
            except OSError:
                continue
            next_frontier.extend(
                Path(entry.path) for entry in children
                if not entry.name.startswith(".") and entry.name not in _SKIP_DIRS
                and _is_directory(entry))
        frontier = next_frontier
    return found
