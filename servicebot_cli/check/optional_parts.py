"""Where a xacro description defines a link it did not expand: an optional part left out.

A ``<gazebo reference>`` may name a link that only a xacro condition not taken creates
(unitree's a1 ``stick_link`` under ``rolloverProtection``, off by default) or that an
include the robot's options leave out adds (warthog's ``bulkhead_link`` from
``accessories/warthog_bulkhead.urdf.xacro`` with ``WARTHOG_BULKHEAD`` set). Gazebo then
ignores the block, as its author meant. This finds such definitions in the robot's own
sources: the files the expansion read, and those their ``<xacro:include>`` elements name,
taken or not (another robot of the package is not this robot's part); a definition the
expansion expanded, with other values, is no part left out. A definition is a
``<link>`` or a ``<joint>`` with a ``type``: ``<ros2_control>`` and ``<transmission>`` name
joints without one. A ``<link>`` inside a ``<gazebo>`` block is SDF that Gazebo adds to the
model (PR2's gripper), no URDF link a reference could name.
"""

from __future__ import annotations

import os
import re
from collections.abc import Collection, Iterable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.files import head_of, included_files
from servicebot_cli.common.inputs import display_path
from servicebot_cli.description.loader import comments_blanked

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_DEFINITION = re.compile(rb"<(link|joint)\b([^>]*)>")
_GAZEBO_BLOCK = re.compile(rb"<gazebo(?:\b[^>]*[^/>])?>.*?</gazebo\s*>", re.DOTALL)
_NAME = re.compile(rb"\bname\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_TYPE = re.compile(rb"\btype\s*=")
_EXPRESSION = re.compile(rb"\$\{[^}]*\}|\$\([^)]*\)")
_FEWEST_LITERAL = 4
"""Characters a name written with expressions must spell out, words every name has aside."""
_GENERIC = re.compile(rb"[_/.-]|link|joint|frame|base", re.IGNORECASE)


Definition = tuple[str, int, str, str, str | None]
"""Where a name is defined: file, line, kind (``link`` or ``joint``), the name as written, and
the ``<xacro:macro>`` it is written in (None: outside every macro)."""

_MACRO = re.compile(rb"<xacro:macro\b([^>]*?)(/?)>|</xacro:macro\s*>")


def defined_elsewhere(robot: RobotDescription, names: Collection[str]) -> dict[str, Definition]:
    """For each of ``names`` the robot's sources define: where, and as what.

    A name written with xacro expressions (franka's ``${arm_id}_leftfinger``, in a macro its
    ``hand:=false`` leaves out) defines each name it can expand to, when its literal text
    says enough (:data:`_FEWEST_LITERAL` characters besides separators and words such as
    ``link``): ``${prefix}${name}`` and ``${name}_link`` define nothing.
    Nothing for a description that is not expanded from xacro, whose file is all there is.
    """
    if not robot.expanded or not names:
        return {}
    wanted = {name.encode(): name for name in names}
    # where this expansion expanded a definition (with other values)
    expanded = {(os.path.abspath(ref.file), ref.line) for ref in map(
        robot.source_of, (*robot.root.findall("link"), *robot.root.findall("joint")))}
    found: dict[str, Definition] = {}
    sources = _sources(included_files([Path(file) for file in robot.files]))
    texts = [text for _, text in sources]
    for path, text in sources:
        macros = _macro_spans(text)
        for kind, written, line, start in _definitions(text):
            here = (os.path.abspath(path), line) in expanded
            for name in _defined(written, wanted, texts, expanded_here=here):
                found.setdefault(name, (display_path(path), line, kind,
                                        written.decode("utf-8", "replace"),
                                        _macro_at(macros, start)))
    return found


def _sources(paths: Iterable[Path]) -> list[tuple[Path, bytes]]:
    """Each readable file of ``paths`` and its text, comments and Gazebo blocks blanked."""
    sources = []
    for path in paths:
        head = head_of(path)
        if head is not None:
            sources.append((path, _GAZEBO_BLOCK.sub(_line_breaks, comments_blanked(head))))
    return sources


def _definitions(text: bytes) -> Iterator[tuple[str, bytes, int, int]]:
    """Each link and joint ``text`` defines: kind, name as written, line, and offset."""
    for match in _DEFINITION.finditer(text):
        named = _NAME.search(match[2])
        if named is None or (match[1] == b"joint" and not _TYPE.search(match[2])):
            continue  # a <joint> with no type names one (a transmission's, ros2_control's)
        written = named[1] if named[1] is not None else named[2]
        yield match[1].decode(), written, text.count(b"\n", 0, match.start()) + 1, match.start()


_MOST_SIBLINGS = 64  # description files beside the named one that are read


def defined_by_siblings(robot: RobotDescription,
                        written_in: Mapping[str, str]) -> dict[str, Definition]:
    """For each name of ``written_in`` that another robot's description beside this one
    defines, and whose block is written in a file that robot reads too: where.

    A family's descriptions share their Gazebo blocks (interbotix's gazebo_configs macro
    writes one per link of every arm into each arm): a block naming a link of a sibling,
    written in a file the sibling includes too, and of no part of this robot, is one of
    those. ``written_in``: each name and the file its block is written in; a block in the
    robot's own file is its own. Only for descriptions expanded from xacro.
    """  # noqa: D205
    own_file = os.path.abspath(robot.path)
    shared = {name: os.path.realpath(file) for name, file in written_in.items()
              if os.path.abspath(file) != own_file}
    if not robot.expanded or not shared:
        return {}
    names = list(shared)
    own = {os.path.abspath(file) for file in robot.files}
    try:
        beside = sorted(entry.path for entry in os.scandir(robot.path.parent)
                        if entry.name.endswith((".xacro", ".urdf")) and entry.is_file()
                        and os.path.abspath(entry.path) not in own)[:_MOST_SIBLINGS]
    except OSError:
        return {}
    wanted = {name.encode(): name for name in names}
    siblings = _sources(map(Path, beside))
    texts = [text for _, text in (*siblings, *_sources(map(Path, robot.files)))]
    found: dict[str, Definition] = {}
    for path, text in siblings:
        reads: set[str] | None = None  # the files it includes, read once it matters
        for kind, written, line, _ in _definitions(text):
            for name in _defined(written, wanted, texts):
                if reads is None:
                    reads = {os.path.realpath(p) for p in included_files([path])}
                if shared[name] in reads:  # it reads the very file that writes the block
                    found.setdefault(name, (display_path(path), line, kind,
                                            written.decode("utf-8", "replace"), None))
    return found


def _macro_spans(text: bytes) -> list[tuple[int, int, str]]:
    """Each ``<xacro:macro>`` of ``text``: where its body starts and ends, and its name."""
    spans: list[tuple[int, int, str]] = []
    open_macros: list[tuple[int, str]] = []
    for match in _MACRO.finditer(text):
        if match[0].startswith(b"</"):
            if open_macros:
                start, name = open_macros.pop()
                spans.append((start, match.start(), name))
        elif not match[2]:  # <xacro:macro .../> has no body
            named = _NAME.search(match[1])
            raw = (named[1] if named[1] is not None else named[2]) if named else b"?"
            open_macros.append((match.end(), raw.decode("utf-8", "replace")))
    return spans


def _macro_at(spans: list[tuple[int, int, str]], at: int) -> str | None:
    """The innermost macro whose body holds position ``at``; None outside every one."""
    inside = [(start, name) for start, end, name in spans if start <= at < end]
    return max(inside)[1] if inside else None


def _line_breaks(block: re.Match[bytes]) -> bytes:
    """A block replaced by its line breaks alone: later lines keep their numbers."""
    return b"\n" * block[0].count(b"\n")


def _defined(written: bytes, wanted: dict[bytes, str], texts: list[bytes], *,
             expanded_here: bool = False) -> list[str]:
    """The names of ``wanted`` that the name ``written`` in a source defines.

    Of a name written with expressions, only where what the expressions stand for is written
    in the sources (``texts``, comments blanked) as a word of its own: the argument of a call
    the expansion left out. create_robot's ``${prefix}_wheel_link`` is called with left and
    right; its ``rear_wheel_link`` is only in a comment, so a reference to it is a stale one.
    A definition the expansion expanded (``expanded_here``) stands for another name only
    through a call it left out, not by an expression left empty: summit_xl's
    ``${prefix}base_footprint``, expanded as robot_base_footprint, is no optional
    base_footprint.
    """
    if written in wanted:
        return [wanted[written]]
    if b"$" not in written:
        return []
    parts = _EXPRESSION.split(written)
    if sum(len(_GENERIC.sub(b"", part)) for part in parts) < _FEWEST_LITERAL:
        return []  # ${name}_link says nothing of which link: any typo of one would match
    # an expression may expand to nothing (${prefix}tool0 with the usual empty prefix)
    pattern = re.compile(b"(.*)".join(re.escape(part) for part in parts), re.DOTALL)
    return [name for raw, name in wanted.items()
            if (match := pattern.fullmatch(raw)) is not None
            and all(_written(value, texts) if value else not expanded_here
                    for value in match.groups())]


def _written(value: bytes, texts: list[bytes]) -> bool:
    """Whether ``value`` stands as a word of its own in one of ``texts``."""
    word = re.compile(rb"(?<![\w$])" + re.escape(value) + rb"(?!\w)")
    return any(word.search(text) for text in texts)

