"""Errors met while reading a description, as issues: SB001-SB007, SB015.

The loader raises one error for a file it cannot read, parse or expand; ``check`` reports
it as a finding with the file, line and column the error names.
"""

from __future__ import annotations

import re

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.common.errors import (
    DescriptionError,
    PackageNotFound,
    UnsafeXmlError,
    XacroError,
    XmlError,
)

_WHERE = re.compile(r"^(?P<file>.+?):(?P<line>\d+)(?::(?P<column>\d+))?: (?P<rest>.*)$", re.DOTALL)
_LIMITS = ("limit for a robot description", "elements; refused", "deep; refused",
           "MB limit; is it the right file?")  # the last: a device read to the limit
# xacro adds " when evaluating expression '...'" when a property read the argument lazily
_QUOTED = re.compile(r"'([^']*)'")
_GAP = re.compile(r"[^/:]//|/[._](?=[^/]*$)")  # "a//b"; a last part that starts "." or "_"
_EMPTY_DEFAULT = re.compile(rb"<xacro:arg\b[^>]*\bdefault\s*=\s*(?:\"\"|'')")
_UNDEFINED_ARG = re.compile(r"Undefined substitution argument (\S+)"
                            r"(?: when evaluating expression '.*')?$", re.DOTALL)


def issue_of(error: DescriptionError, display: str, walked: bool = False) -> Issue:
    """The issue for an error raised while reading ``display``.

    ``walked``: the file was found in a directory, not named. A xacro file that reads an
    argument it gives no default (``$(arg robot_model)`` in universal_robot's ``ur.xacro``,
    ``$(arg enable_crane)`` in talos_description) is expanded by its launch file, which
    passes it; a walk passes none, so its SB006 is a warning there, and an error when the
    file is named without the argument.
    """
    if isinstance(error, XmlError):
        where = (error.file, error.line, error.column)
        if isinstance(error, UnsafeXmlError):
            return Issue("SB005", error.reason, where=where,
                         fix="remove the DOCTYPE; use xacro properties for repeated values")
        return Issue(_xml_code(error.reason), error.reason, where=where)
    file, line, column, text = _split(str(error), display)
    if isinstance(error, PackageNotFound):
        return Issue("SB007", text, where=(file, line, column),
                     fix="pass --package NAME=DIR, or source the workspace that holds it")
    if isinstance(error, XacroError) and text.startswith(("cannot read included file",
                                                          "cannot read file")):
        if walked and _built_from_empty_arguments(text, display):
            return Issue("SB001", f"{text}: the name looks built from launch arguments the file "
                         "leaves empty (default=\"\"), as its launch file fills them; a "
                         "directory walk passes none, so it is not checked here",
                         where=(file, line, column), severity=Severity.WARNING,
                         fix="check it by name with its arguments (NAME:=VALUE)")
        return Issue("SB001", text, where=(file, line, column))
    if any(limit in text for limit in _LIMITS):
        return Issue("SB015", text, where=(file, line, column))
    text = text.removeprefix("xacro: ")
    undefined = _UNDEFINED_ARG.search(text)
    if walked and undefined is not None:
        name = undefined[1]
        return Issue("SB006", f"{text}: the file reads {name} with no default, as a launch file "
                     "passes it; a directory walk passes none, so it is not checked here",
                     where=(file, line, column), severity=Severity.WARNING,
                     fix=f"check it by name with {name}:=VALUE (and its other arguments)")
    return Issue("SB006", text, where=(file, line, column))


def _built_from_empty_arguments(text: str, display: str) -> bool:
    """Whether a missing include's name has a gap an empty argument leaves (see below).

    The file must declare an argument that defaults to nothing:
    kortex_dual_robots.xacro declares every argument with ``default=""`` and includes
    ``arms/$(arg arm)/$(arg dof)dof/urdf/...``: walked, that is ``arms//dof/urdf/_macro.xacro``
    (interbotix's locobot: ``arms/.urdf.xacro``).
    """
    named = _QUOTED.search(text)
    if named is None or not _GAP.search(named[1]):
        return False
    try:
        with open(display, "rb") as handle:
            head = handle.read(1 << 20)
    except OSError:
        return False
    return _EMPTY_DEFAULT.search(head) is not None


def _xml_code(reason: str) -> str:
    if reason.startswith("file is empty"):
        return "SB002"
    if reason.startswith("invalid UTF-8"):
        return "SB003"
    if any(limit in reason for limit in _LIMITS):
        return "SB015"
    return "SB004"


def _split(message: str, display: str) -> tuple[str, int, int, str]:
    """``file:line:col: text`` into its parts (line and column 0 when absent)."""
    match = _WHERE.match(message)
    if match:
        return (match["file"], int(match["line"]), int(match["column"] or 0), match["rest"])
    if message.startswith(display + ": "):
        return display, 0, 0, message[len(display) + 2:]
    return display, 0, 0, message
