"""Files a package holds only once installed: ``$(find PKG)/ros2_control/x.xacro`` in a source tree.

``$(find PKG)`` is the package's install directory (``install/PKG/share/PKG``). A CMake
package lays its files out there as its ``install(DIRECTORY ...)`` rules say, which may differ
from the source tree: ros2_control_demos' examples install ``description/ros2_control`` as
``share/PKG/ros2_control`` and include ``$(find PKG)/ros2_control/...``. Checked from sources
(no build, no ROS), such an include names no file, yet the description is fine once built.
This module finds the source file an install-space path comes from.
"""

from __future__ import annotations

import os
import posixpath
import re
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from servicebot_cli.description.package_dirs import holding_package

_COMMENT = re.compile(r"#[^\n]*")
_INSTALL = re.compile(r"\binstall\s*\(([^)]*)\)", re.IGNORECASE)
_AUTO_PACKAGE = re.compile(r"\bament_auto_package\s*\(([^)]*)\)", re.IGNORECASE)
_SHARE = re.compile(r"^share/(?:\$\{PROJECT_NAME\}|(?P<name>[\w.-]+))(?:/(?P<sub>.*?))?/*$")
_KEYWORDS = {"DESTINATION", "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "PERMISSIONS",
             "USE_SOURCE_PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "OPTIONAL",
             "MESSAGE_NEVER", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS", "EXCLUDE_FROM_ALL"}


@dataclass(frozen=True)
class InstalledFrom:
    """Where an install-space path of a package comes from in its source tree.

    Attributes:
        package: The package name.
        package_dir: The package's source directory (holding package.xml).
        source: The source file the path is installed from.
        source_dir: The rule's source directory, relative to the package (``description/urdf``).
        installed_dir: Where the rule installs it, relative to ``share/PKG`` (``urdf``).
    """

    package: str
    package_dir: Path
    source: Path
    source_dir: str
    installed_dir: str


def installed_from(missing: Path) -> InstalledFrom | None:
    """The source file that ``missing``, a path inside a source package, is installed from.

    None when ``missing`` is in no package, or no ``install(DIRECTORY ...)`` rule of the
    package's CMakeLists.txt installs an existing source file at that place.
    """
    existing = next((p for p in missing.parents if os.path.isdir(p)), None)
    placed = _placed(missing, existing) if existing is not None else None
    if placed is None:
        return None
    name, package_dir, relative, rules = placed
    for source_dir, installed_dir in rules:
        rest = _below(relative, installed_dir)
        if rest is None:
            continue
        source = package_dir / source_dir / rest
        if os.path.isfile(source):
            return InstalledFrom(name, package_dir, source, source_dir, installed_dir)
    return None


def _below(path: PurePosixPath, directory: str) -> PurePosixPath | None:
    """``path`` relative to ``directory``, a rule's side; None where it is not under it.

    ``directory`` "" is the top (of the package, or of its share directory).
    """
    try:
        return path.relative_to(directory) if directory else path
    except ValueError:
        return None


def _placed(path: Path, directory: Path
            ) -> tuple[str, Path, PurePosixPath, list[tuple[str, str]]] | None:
    """The package holding ``directory``, ``path`` relative to it, and its install rules.

    None outside a package, or where its CMakeLists.txt cannot be read.
    """
    holder = holding_package(directory)
    if holder is None:
        return None
    name, package_dir = holder
    try:
        relative = PurePosixPath(path.relative_to(package_dir).as_posix())
        cmake = (package_dir / "CMakeLists.txt").read_text(encoding="utf-8", errors="replace")
    except (ValueError, OSError):
        return None
    return name, package_dir, relative, directory_rules(cmake, name)


def directory_rules(cmake: str, package: str) -> list[tuple[str, str]]:
    """``(source directory, directory under share/PKG)`` for each installed directory.

    ``install(DIRECTORY a/b c/ DESTINATION share/${PROJECT_NAME}/x)`` gives ``("a/b", "x/b")``
    and ``("c", "x")``: without a trailing slash the directory itself is installed, with
    one its contents. Rules to other destinations, or to another package's share, are left out.
    """
    cmake = _COMMENT.sub("", cmake)
    bodies = _INSTALL.findall(cmake) + [  # ament_cmake_auto installs each as install() would
        f"DIRECTORY {' '.join(words)} DESTINATION share/${{PROJECT_NAME}}"
        for words in map(_to_share, _AUTO_PACKAGE.findall(cmake)) if words]
    rules = []
    for body in bodies:
        words = body.replace('"', " ").split()
        if not words or words[0].upper() != "DIRECTORY" or "DESTINATION" not in words:
            continue
        at = words.index("DESTINATION")
        share = _SHARE.match(words[at + 1]) if at + 1 < len(words) else None
        if share is None or share["name"] not in (None, package):
            continue
        destination = PurePosixPath(share["sub"] or "")
        for source in words[1:at]:
            if source.upper() in _KEYWORDS or "$" in source:
                break
            stripped = source.rstrip("/")
            installed = destination if source.endswith("/") else destination / Path(stripped).name
            rules.append((stripped, "" if str(installed) == "." else str(installed)))
    return rules


def _to_share(body: str) -> list[str]:
    """The directories ``ament_auto_package(INSTALL_TO_SHARE ...)`` names."""
    words = body.replace('"', " ").split()
    if "INSTALL_TO_SHARE" not in words:
        return []
    listed = words[words.index("INSTALL_TO_SHARE") + 1:]
    end = next((i for i, word in enumerate(listed) if word.isupper() and "_" in word), None)
    return listed[:end]


def included_when_installed(includer: Path, relative: str) -> Path | None:
    """The source file a relative include of ``includer`` names once both are installed.

    ``includer`` is a source file its package's install rules put under ``share/PKG``; its
    include ``relative`` is read from there, and the file found there mapped back to its
    source. None where ``includer`` is installed by no rule, or the include leaves
    ``share/PKG``, or names no file installed from the sources.
    """
    landed = _installed_include(includer, relative)
    if landed is None:
        return None
    _, package_dir, target = landed
    if target == ".." or target.startswith("../") or posixpath.isabs(target):
        return None  # out of share/PKG: nothing installed there
    found = installed_from(package_dir / target)
    return None if found is None else found.source


def lands_outside(includer: Path, relative: str) -> str | None:
    """Where a relative include of ``includer`` lands once installed, when out of its share.

    ``includer`` is a source file its package's install rules put under ``share/PKG``; an
    include written against the source tree (``../../../other_pkg/x.xacro``) may climb out of
    ``share/PKG`` from there. The place it lands, relative to the install prefix
    (``other_pkg/x.xacro``, ``share/config/x.xacro``); None where ``includer`` is installed
    by no rule read here, or the include stays within ``share/PKG``.
    """
    landed = _installed_include(includer, relative)
    if landed is None:
        return None
    name, _, target = landed
    if not (target == ".." or target.startswith("../")):
        return None
    return posixpath.normpath(posixpath.join("share", name, target))


def _installed_include(includer: Path, relative: str) -> tuple[str, Path, str] | None:
    """Where the relative include ``relative`` of ``includer`` lands once installed.

    The package's name and directory, and the place under ``share/PKG`` (normalised: it may
    start with ``..``). None where no install rule of the package puts ``includer`` under
    ``share/PKG``.
    """
    placed = _placed(includer, includer.parent)
    if placed is None:
        return None
    name, package_dir, inside, rules = placed
    for source_dir, installed_dir in rules:
        rest = _below(inside, source_dir)
        if rest is not None:
            return name, package_dir, posixpath.normpath(
                str(PurePosixPath(installed_dir or ".") / rest.parent / relative))
    return None


def installed_source(path: str) -> str:
    """``path`` if it exists; else the source file it is installed from, when there is one.

    ``$(find PKG)`` of a package found as sources names its source directory, while the
    description means the install directory: ``$(find PKG)/ros2_control/x.xacro`` is
    ``description/ros2_control/x.xacro`` in the sources of ros2_control_demos' examples.
    """
    if os.path.exists(path):
        return path
    found = installed_from(Path(path))
    return path if found is None else str(found.source)
