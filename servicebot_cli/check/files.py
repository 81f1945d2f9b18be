"""Which files ``check urdf`` reads: the ones given, and robot files found in directories.

In a directory, a xacro include is checked through the files that include it, not alone: a
file that only defines macros or properties, a robot file with an unnamed ``<robot>``
(husky's ``empty.urdf``, the default of ``$(optenv HUSKY_URDF_EXTRAS empty.urdf)``), a
xacro file whose root is not ``<robot>`` (PR2's ``<root xmlns:xacro=...>`` sensors), and a
file another robot file of the same walk includes (``turtlebot3_burger.gazebo.xacro``,
``common_properties.xacro``). MoveIt's ``*.srdf.xacro`` are semantic descriptions, not URDF,
and so are the files they include.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from servicebot_cli.check.names import SRDF_ELEMENTS
from servicebot_cli.common.inputs import read_again
from servicebot_cli.description.install_layout import installed_source
from servicebot_cli.description.loader import without_comments
from servicebot_cli.description.package_dirs import holding_package
from servicebot_cli.description.robot import is_xacro_name

SUFFIXES = (".urdf", ".urdf.xml", ".xacro")
NOT_URDF_SUFFIXES = (".srdf.xacro",)
SKIPPED_DIRS = {"build", "install", "log", "node_modules", "__pycache__", "site-packages"}
_ROBOT_TAG = re.compile(rb"<robot\b[^>]*>", re.DOTALL)
_XACRO_ROOT = re.compile(rb"<[\w.:-]+\b[^>]*\bxmlns:xacro\s*=", re.DOTALL)
_MACRO_TAG = re.compile(rb"<xacro:macro\b[^>]*?(/?)>|</xacro:macro\s*>")


def without_macros(text: bytes) -> bytes:
    """``text`` without its ``<xacro:macro>`` definitions: what runs where a macro is called.

    Macros defined inside a macro (clearpath's robotiq_2f_140) end with their outer one.
    """
    kept, depth, start = [], 0, 0
    for tag in _MACRO_TAG.finditer(text):
        if tag[0].startswith(b"</"):
            if depth:
                depth -= 1
                if not depth:
                    start = tag.end()
        elif not tag[1]:  # <xacro:macro ...> opens a body; <xacro:macro .../> has none
            if not depth:
                kept.append(text[start:tag.start()])
            depth += 1
        elif not depth:
            kept.append(text[start:tag.start()])
            start = tag.end()
    if not depth:
        kept.append(text[start:])
    return b"".join(kept)
_CONTENT = re.compile(rb"<(?:link|joint|xacro:(?!include\b|property\b|arg\b|macro\b)[\w.-]+)\b")
_INCLUDE = re.compile(rb"<xacro:include\b[^>]*?\bfilename\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_FIND = re.compile(r"^\$\(find\s+([^)\s]+)\s*\)/*(.*)$")
_HEAD_BYTES = 1 << 20
_SRDF_ELEMENT = re.compile(rb"<(?:" + "|".join(SRDF_ELEMENTS).encode() + rb")\b")
_JOINT_DEFINITION = re.compile(rb"<joint\b[^>]*\btype\s*=")


def head_without_comments(path: Path) -> bytes | None:
    """The first MiB of ``path`` with its XML comments removed; None: it cannot be read."""
    head = head_of(path)
    return None if head is None else without_comments(head)


def head_of(path: Path) -> bytes | None:
    """The first MiB of ``path``; None: it cannot be read."""
    once = read_again(path, _HEAD_BYTES)
    if once is not None:
        return once
    try:
        with path.open("rb") as handle:
            return handle.read(_HEAD_BYTES)
    except OSError:
        return None


def is_robot_file(path: Path) -> bool:
    """True for ``*.urdf``, ``*.urdf.xml`` and ``*.xacro`` names, but not ``*.srdf.xacro``."""
    name = path.name.lower()
    return name.endswith(SUFFIXES) and not name.endswith(NOT_URDF_SUFFIXES)


def is_fragment(path: Path) -> bool:
    """True for an include, checked through the files that include it.

    Its ``<robot>`` has no name (in a ``.urdf``: and it has no link, or holds xacro elements,
    so a robot that only lacks its name is still checked); or it is a xacro file whose root
    is another element that declares the xacro namespace; or a xacro file that only defines
    macros or properties: no link, joint or macro call outside its ``<xacro:macro>``
    definitions (a macro library such as ``panda_arm.xacro``, kobuki's
    ``common_properties.urdf.xacro``), and, when it defines no macro, no include either
    (``robot.urdf.xacro`` may only include its parts).
    """
    head = head_without_comments(path)
    if head is None:
        return False  # reading it again will report the problem
    match = _ROBOT_TAG.search(head)
    xacro = is_xacro_name(path)
    if match is None:
        return xacro and _XACRO_ROOT.search(head) is not None
    if b"name=" not in match.group(0):
        return xacro or b"<link" not in head or b"<xacro:" in head
    if not xacro:
        return False
    outside = without_macros(head)
    if _CONTENT.search(outside) is not None:
        return False
    return outside != head or _INCLUDE.search(head) is None


def walk(directory: Path) -> Iterator[Path]:
    """Robot files under ``directory``, sorted, skipping hidden and build directories.

    Includes are left out: macro libraries, unnamed robots, and files that another file of
    the walk includes (a robot file, or an include itself).
    """
    yield from walk_robots(directory)[0]


def walk_robots(directory: Path) -> tuple[list[Path], dict[Path, set[Path]]]:
    """:func:`walk`'s files, and the named robots it leaves out with the files that include them.

    A named robot left out is checked through those includers (of the walk, or includes
    themselves); when none of them expands, it is checked alone after all (andino's
    description, included by a Gazebo file that needs a launch argument).
    """
    robots: list[Path] = []
    fragments: list[Path] = []
    semantic: list[Path] = []
    for path in _files(directory, lambda p: is_robot_file(p) or is_semantic_name(p)):
        if is_semantic_name(path):
            semantic.append(path)
        else:
            (fragments if is_fragment(path) else robots).append(path)
    # an include of an include is an include too (VRX: the robot includes a macro file,
    # which includes a file of includes that names a robot but holds no link)
    by_robots = every_includer(robots, by=[*robots, *fragments])
    included = set(by_robots)
    if semantic:  # what only a *.srdf.xacro includes is left out when it is SRDF itself
        included |= {path for path in set(includers(robots, by=semantic)) - included
                     if _semantic_content(path)}
    return ([path for path in robots if path not in included],
            {path: by_robots.get(path, set()) for path in robots if path in included})


def robot_file_count(directory: Path) -> int:
    """How many robot files ``directory`` holds, includes too.

    pal_urdf_utils holds only xacro libraries: nothing to check alone, and nothing wrong.
    """
    return sum(1 for _ in robot_files(directory))


def semantic_file_count(directory: Path) -> int:
    """How many MoveIt semantic descriptions (``*.srdf.xacro``) ``directory`` holds."""
    return sum(1 for _ in _files(directory, is_semantic_name))


def robot_files(directory: Path) -> Iterator[Path]:
    """Every robot file under ``directory`` (includes too), as :func:`walk` finds them."""
    yield from _files(directory, is_robot_file)


def is_semantic_name(path: Path) -> bool:
    """A MoveIt semantic description (``*.srdf.xacro``), never checked as a robot."""
    return path.name.lower().endswith(NOT_URDF_SUFFIXES)


def _semantic_content(path: Path) -> bool:
    """Whether ``path`` holds SRDF elements and defines no joint (no ``<joint type=...>``).

    husky_manipulation's ``config/arm.xacro``, which ``panda.srdf.xacro`` includes: the arm's
    ``<group>``, ``<group_state>`` and ``<disable_collisions>``. A robot file an SRDF
    includes (for its macros or arguments) is still a robot.
    """
    head = head_without_comments(path)
    return head is not None and _SRDF_ELEMENT.search(head) is not None \
        and _JOINT_DEFINITION.search(head) is None


def _files(directory: Path, wanted: Callable[[Path], bool]) -> Iterator[Path]:
    """The ``wanted`` files under ``directory``, through links to directories as colcon goes.

    colcon builds a package linked into ``src/`` (it walks with ``followlinks`` and keeps
    each real directory once): each directory is entered once, by the first way to it, so a
    link back up the tree is no loop.
    """
    entered = {os.path.realpath(directory)}
    for root, dirs, files in os.walk(directory, followlinks=True):
        dirs[:] = [d for d in sorted(dirs) if not d.startswith(".") and d not in SKIPPED_DIRS
                   and _first_visit(os.path.join(root, d), entered)]
        # a named pipe or a device among the files is no robot file (a stale pipe would
        # block the walk): left out, as the walk leaves out what is not a robot file
        yield from (path for name in sorted(files)
                    if wanted(path := Path(root) / name) and os.path.isfile(path))


def _first_visit(directory: str, entered: set[str]) -> bool:
    """Whether ``directory`` is a way into a real directory not ``entered`` yet (noted now)."""
    real = os.path.realpath(directory)
    if real in entered:
        return False
    entered.add(real)
    return True


def included_by(paths: list[Path]) -> set[Path]:
    """Which of ``paths`` another of them includes with ``<xacro:include filename>``."""
    return set(includers(paths))


def includers(paths: list[Path], by: list[Path] | None = None, *,
               in_comments: bool = False) -> dict[Path, Path]:
    """Each of ``paths`` another of them includes, and the first of them that includes it.

    With ``by``, the includers looked at are those files instead of ``paths``; with
    ``in_comments``, includes inside XML comments count too.

    A filename is read as xacro reads it, through :mod:`install_layout`: relative to the
    including file, or ``$(find PKG)/REL`` under the directory of package PKG (a package
    holding one of ``paths``), or the source file its install rules put there
    (``$(find PKG)/urdf/x.xacro`` from ``description/urdf/x.xacro``). Computed names
    (``${...}``, ``$(arg ...)``) name nothing.
    """
    included: dict[Path, Path] = {}
    for found, path in _inclusions(paths, by, in_comments):
        included.setdefault(found, path)
    return included


def every_includer(paths: list[Path], by: list[Path] | None = None) -> dict[Path, set[Path]]:
    """Each of ``paths`` another includes, and every file that does (see :func:`includers`)."""
    included: dict[Path, set[Path]] = {}
    for found, path in _inclusions(paths, by, in_comments=False):
        included.setdefault(found, set()).add(path)
    return included


def _inclusions(paths: list[Path], by: list[Path] | None,
                in_comments: bool) -> Iterator[tuple[Path, Path]]:
    """``(included, includer)`` for each of ``paths`` that another of ``by`` includes."""
    sources = paths if by is None else by
    by_location = {_location(path): path for path in paths}
    packages = _packages([*paths, *(by or ())])
    for path in sources:
        for target in _include_targets(path, in_comments=in_comments):
            for named in _named(target, path, packages):
                found = by_location.get(_location(named))
                if found is not None and found != path:
                    yield found, path


def included_files(paths: list[Path], most: int = 500) -> list[Path]:
    """``paths``, then every file their ``<xacro:include>`` elements name, taken or not.

    Followed through what they include in turn, as :func:`includers` reads the names;
    at most ``most`` files.
    """
    found = {_location(path): path for path in paths}
    queue = list(paths)
    packages = _packages(paths)
    while queue and len(found) < most:
        path = queue.pop(0)
        for target in _include_targets(path):
            for named in _named(target, path, packages):
                location = _location(named)
                if location not in found and os.path.isfile(Path(named)) and len(found) < most:
                    found[location] = Path(named)
                    queue.append(Path(named))
    return list(found.values())


def includer_nearby(path: Path, *, in_comments: bool = False) -> Path | None:
    """A robot file of ``path``'s package that includes ``path``, or None.

    The package is the nearest one at or above ``path`` (its robot files, found as
    :func:`walk` finds them, includes too); a file in no package is looked for beside it,
    in its own directory only, so that a file in ``/tmp`` does not walk all of it. With
    ``in_comments``, includes inside XML comments count too (an alternative part, switched
    in by moving a comment).
    """
    holder = holding_package(path.parent.absolute())
    if holder is not None:
        around = list(robot_files(holder[1]))
    else:
        try:
            around = sorted(entry for entry in path.parent.iterdir()
                            if is_robot_file(entry) and os.path.isfile(entry))
        except OSError:
            return None
    here = _location(path)
    others = [other for other in around if _location(other) != here]
    return includers([*others, path], in_comments=in_comments).get(path)


def _location(path: Path | str) -> str:
    return os.path.normpath(os.path.abspath(path))


def _packages(paths: list[Path]) -> dict[str, set[Path]]:
    """The directories of the packages holding ``paths``, by package name."""
    packages: dict[str, set[Path]] = {}
    for directory in {path.parent.absolute() for path in paths}:
        holder = holding_package(directory)
        if holder is not None:
            packages.setdefault(holder[0], set()).add(holder[1])
    return packages


def _named(target: str, includer: Path, packages: dict[str, set[Path]]) -> list[str]:
    """The files the include ``target`` written in ``includer`` can name."""
    match = _FIND.match(target)
    if match is None:
        return [] if "$(" in target else [str(includer.parent / target)]
    package, relative = match.groups()
    if not relative:
        return []
    return [installed_source(str(directory / relative))
            for directory in sorted(packages.get(package, ()))]


def _include_targets(path: Path, *, in_comments: bool = False) -> list[str]:
    """The filenames of the ``<xacro:include>`` elements of a robot file.

    A ``.urdf`` file's too: one with xacro in it is expanded with xacro by the launch files
    that load it (roverrobotics_ros2's ``max.urdf`` includes its payloads), so what it
    includes is a part of it, not a robot. Those inside XML comments only with
    ``in_comments``.
    """
    text = head_of(path)
    if text is None or (not is_xacro_name(path) and b"xacro:include" not in text):
        return []
    if not in_comments:
        text = without_comments(text)
    targets = ((double or single).decode("utf-8", "replace").strip()
               for double, single in _INCLUDE.findall(text))
    return [t for t in targets if t and "${" not in t and "$(arg" not in t]
