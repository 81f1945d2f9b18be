"""Errors met while reading a description, as issues: SB001-SB007, SB015.

The loader raises one error for a file it cannot read, parse or expand; ``check`` reports
it as a finding with the file, line and column the error names.
"""

from __future__ import annotations

import dataclasses
import os
import re

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.syntax import not_a_robot
from servicebot_cli.common.accidents import accident_fix
from servicebot_cli.common.errors import (
    DescriptionError,
    PackageNotFound,
    UnsafeXmlError,
    XacroError,
    XmlError,
    split_location,
)
from servicebot_cli.common.inputs import not_a_file, read_again
from servicebot_cli.description.loader import comments_blanked
from servicebot_cli.description.safe_xml import MAX_BYTES, parse_xml

_LIMITS = ("limit for a robot description", "elements; refused", "deep; refused",
           "MB limit; is it the right file?")  # the last: a device read to the limit
# xacro adds " when evaluating expression '...'" when a property read the argument lazily
_QUOTED = re.compile(r"'([^']*)'")
_GAP = re.compile(r"[^/:]//|/[._](?=[^/]*$)")  # "a//b"; a last part that starts "." or "_"
_ARG_DECLARATION = re.compile(rb"<xacro:arg\b([^>]*)>")
_ARG_NAME = re.compile(rb"\bname\s*=\s*[\"']([^\"']+)[\"']")
_EMPTY_DEFAULT = re.compile(rb"\bdefault\s*=\s*(?:\"\"|'')")
_ARG_USE = re.compile(rb"\$\(arg\s+([^)\s]+)\s*\)")
_UNDEFINED_ARG = re.compile(r"Undefined substitution argument (\S+)"
                            r"(?: when evaluating expression '.*')?(?: \(in macro '.*)?$",
                            re.DOTALL)


def root_not_robot(path: str, display: str) -> Issue | None:
    """SB008 for a file xacro could not expand whose root element is no ``<robot>``.

    A ROS 1 launch file named ``.urdf.xacro`` (``<launch>``) fails xacro on its ``$(find)``
    first; that failure (a package not found, a warning) hid that it is no robot at all.
    """
    data = read_again(path, MAX_BYTES + 1)  # a pipe: what it gave, never opened again
    try:
        if data is None:
            if not_a_file(path) is not None:
                return None
            with open(path, "rb") as handle:
                data = handle.read(MAX_BYTES + 1)
        root = parse_xml(data, display).root
    except (OSError, DescriptionError):
        return None
    if root.tag == "robot":
        return None
    return dataclasses.replace(not_a_robot(root), element=None,
                               where=(display, root.sourceline, root.column))


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
        return Issue(_xml_code(error.reason), error.reason, where=where,
                     fix=accident_fix(error.reason))
    file, line, column, text = split_location(str(error), display)
    if isinstance(error, PackageNotFound):
        return Issue("SB007", text, where=(file, line, column),
                     fix="pass --package NAME=DIR, or source the workspace that holds it")
    if isinstance(error, XacroError) and text.startswith(("cannot read included file",
                                                          "cannot read file")):
        if walked and _built_from_empty_arguments(text, file, line, column):
            return Issue("SB001", f"{text}: the name looks built from launch arguments the file "
                         "leaves empty (default=\"\"), as its launch file fills them; a "
                         "directory walk passes none, so it is not checked here",
                         where=(file, line, column), severity=Severity.WARNING,
                         fix="check it by name with its arguments (NAME:=VALUE)")
        missing = text.endswith("No such file or directory")
        return Issue("SB001", text, where=(file, line, column),
                     fix="fix the path, or add the file" if missing else None)
    if any(limit in text for limit in _LIMITS):
        return Issue("SB015", text, where=(file, line, column))
    text = text.removeprefix("xacro: ")
    undefined = _UNDEFINED_ARG.search(text)
    early = _read_before_declared(undefined[1], text, (file, line, column), display, walked) \
        if undefined is not None else None
    if early is not None:
        return early
    if walked and undefined is not None:
        name = undefined[1]
        return Issue("SB006", f"{text}: the file reads {name} with no default, as a launch file "
                     "passes it; a directory walk passes none, so it is not checked here",
                     where=(file, line, column), severity=Severity.WARNING,
                     fix=f"check it by name with {name}:=VALUE (and its other arguments)")
    name = _UNDEFINED_NAME.search(text)
    later = _defined_after(file, line, name[1], "property") \
        if name and not _IN_MACRO.search(text) else None
    if name is not None and later is not None:  # defined below: xacro knows it from there on
        return Issue("SB006", f"{text}; {file}:{later} defines it, after this line",
                     where=(file, line, column), fix=f"move the definition of '{name[1]}' "
                     f"(line {later}) above line {line}: xacro knows a property only from "
                     "where it is defined on")
    return Issue("SB006", text, where=(file, line, column), fix=_xacro_fix(text, undefined))


def _read_before_declared(name: str, text: str, where: tuple[str, int, int], display: str,
                          walked: bool) -> Issue | None:
    """SB006 for argument ``name`` read where xacro does not know it yet; None if not so.

    Declared below the line that reads it, inside the <robot> whose own attribute reads it,
    or in the named file after the include that reads it.
    """
    file, line, _ = where
    severity = Severity.WARNING if walked else Severity.ERROR
    root = _opens_robot(file, line)
    declared = _defined_after(file, line - 1 if root else line, name, "arg")
    if declared is None:  # an included file reads what its includer declares
        later = _defined_after(display, 0, name, "arg") \
            if os.path.abspath(file) != os.path.abspath(display) else None
        if later is None:
            return None
        return Issue("SB006", f"{text}; {display}:{later} declares it, after the include that "
                     "reads it, and xacro knows an argument only from there on", where=where,
                     severity=severity, fix=f"move <xacro:arg name=\"{name}\"> ({display}:"
                     f"{later}) above the <xacro:include> of {os.path.basename(file)}")
    if root:  # the root's attributes come before any of its children
        return Issue("SB006", f"{text}; {file}:{declared} declares it inside <robot>, whose "
                     "own attributes xacro expands first: its default serves none of them",
                     where=where, severity=severity, fix=f"pass {name}:=VALUE (as a launch "
                     f"file does), or write the <robot> name without $(arg {name})")
    return Issue("SB006", f"{text}; {file}:{declared} declares it, after this line, and xacro "
                 "knows an argument only from there on", where=where, severity=severity,
                 fix=f"move <xacro:arg name=\"{name}\"> (line {declared}) above line {line}, "
                 f"or pass {name}:=VALUE")


def _opens_robot(file: str, line: int) -> bool:
    """Whether line ``line`` of ``file`` holds the ``<robot`` start tag."""
    try:
        with open(file, "rb") as handle:
            lines = handle.read(1 << 20).decode("utf-8", "replace").splitlines()
    except OSError:
        return False
    return 0 < line <= len(lines) and "<robot" in lines[line - 1]


def _defined_after(file: str, line: int, name: str, kind: str) -> int | None:
    """The line of the first ``<xacro:KIND name=NAME>`` (property, arg) of ``file`` below
    ``line``; None where the first is above it, or there is none.
    """  # noqa: D205
    try:
        with open(file, "rb") as handle:
            source = comments_blanked(handle.read(1 << 20)).decode("utf-8", "replace")
    except OSError:
        return None
    pattern = re.compile(rf"<xacro:{kind}\b[^>]*\bname\s*=\s*[\"']" + re.escape(name)
                         + r"[\"']")
    for found in pattern.finditer(source):
        at = source.count("\n", 0, found.start()) + 1
        if at > line:
            return at
        return None  # defined above (in another scope): not this case
    return None


_UNDEFINED_NAME = re.compile(r"name '([^']+)' is not defined")
_BARE_DEFINITION = re.compile(r'\(<(\w+) name="([^"]*)">(?: at \S+)? has no xacro: prefix')
_INVALID_PARAMETER = re.compile(r"Invalid parameter \"([^\"]*)\" of macro '([^']+)'")
_IN_MACRO = re.compile(r"\(in macro '([^']+)'")
_UNDEFINED_PARAMETERS = re.compile(r"Undefined parameters \[([^\]]*)\]")


def _xacro_fix(text: str, undefined: re.Match[str] | None) -> str | None:
    """What to do about xacro's ``text``: an argument is passed, a property defined.

    A property is no argument: ``NAME:=VALUE`` does not define it (roverrobotics_ros2's
    payload parts read their includer's ``payload_z_offset``).
    """
    bare = _BARE_DEFINITION.search(text)
    if bare is not None:
        return f"write <xacro:{bare[1]} name=\"{bare[2]}\" .../>"
    if undefined is not None:
        return f"pass {undefined[1]}:=VALUE, or give the argument a default"
    parameters = _UNDEFINED_PARAMETERS.search(text)
    if parameters is not None:
        names = [n.strip() for n in parameters[1].split(",") if n.strip()]
        written = " ".join(f'{n}="..."' for n in names)
        return (f"write {written} in this call, or give the macro's parameter a default "
                f"(params=\"... {names[0]}:=VALUE\"); NAME:=VALUE on the command line sets "
                "arguments, not parameters")
    if text.startswith("an empty expression ${}"):
        return "write the expression inside ${...}, or remove the ${}"
    invalid = _INVALID_PARAMETER.search(text)
    if invalid is not None:
        return (f"write one of the parameters of macro '{invalid[2]}' instead of '{invalid[1]}', "
                f"or add '{invalid[1]}' to its params")
    name = _UNDEFINED_NAME.search(text)
    macro = _IN_MACRO.search(text)
    if name is not None and macro is not None:
        return (f"give macro '{macro[1]}' a parameter '{name[1]}' (params=\"... {name[1]}\") "
                f"and pass {name[1]}=\"...\" in the call, or define the property "
                f"'{name[1]}' before the call")
    if name is not None:
        return (f"define '{name[1]}' (<xacro:property name=\"{name[1]}\" value=\"...\"/>) "
                "before this line, or include the file that defines it; a property is not an "
                "argument, so NAME:=VALUE does not define it")
    return None


def _built_from_empty_arguments(text: str, file: str, line: int, column: int) -> bool:
    """Whether a missing include's name has the gap an empty launch argument leaves there.

    The element at ``file:line:column`` (the include, or the macro call that reaches it) must read
    an argument its file declares with ``default=""``, outside comments:
    kortex_dual_robots.xacro calls ``<xacro:load_robot arm="$(arg left_arm)" ...>`` with
    every argument empty by default, and the include becomes ``arms//dof/urdf/_macro.xacro``.
    """
    named = _QUOTED.search(text)
    if named is None or not _GAP.search(named[1]) or line < 1:
        return False
    try:
        with open(file, "rb") as handle:
            source = handle.read(1 << 20)
    except OSError:
        return False
    source = comments_blanked(source)
    lines = source.split(b"\n")
    element = b"\n".join(lines[line - 1:line + 30])[max(column - 1, 0):]
    element = element[:element.find(b">") + 1] if b">" in element else element
    empty = {name[1] for declared in _ARG_DECLARATION.finditer(source)
             if _EMPTY_DEFAULT.search(declared[1]) and (name := _ARG_NAME.search(declared[1]))}
    return any(m[1] in empty for m in _ARG_USE.finditer(element))


def _xml_code(reason: str) -> str:
    if reason.startswith("file is empty"):
        return "SB002"
    if reason.startswith("invalid UTF-8"):
        return "SB003"
    if any(limit in reason for limit in _LIMITS):
        return "SB015"
    return "SB004"
