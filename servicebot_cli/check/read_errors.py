"""Errors met while reading a description, as issues: SB001-SB007, SB015.

The loader raises one error for a file it cannot read, parse or expand; ``check`` reports
it as a finding with the file, line and column the error names. An include that exists only
once its package is built (``$(find PKG)`` names the install tree) is SB007, not SB001.
"""

from __future__ import annotations

import re
from pathlib import Path

from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import (
    DescriptionError,
    PackageNotFound,
    UnsafeXmlError,
    XacroError,
    XmlError,
)
from servicebot_cli.description.install_layout import installed_from

_WHERE = re.compile(r"^(?P<file>.+?):(?P<line>\d+)(?::(?P<column>\d+))?: (?P<rest>.*)$", re.DOTALL)
_LIMITS = ("limit for a robot description", "elements; refused", "deep; refused")
_INCLUDED = re.compile(r"cannot read included file '(?P<path>[^']+)': No such file")


def issue_of(error: DescriptionError, display: str) -> Issue:
    """The issue for an error raised while reading ``display``."""
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
    if isinstance(error, XacroError) and "cannot read included file" in text:
        return _install_only(text, (file, line, column)) or Issue(
            "SB001", text, where=(file, line, column))
    if any(limit in text for limit in _LIMITS):
        return Issue("SB015", text, where=(file, line, column))
    return Issue("SB006", text.removeprefix("xacro: "), where=(file, line, column))


def _install_only(text: str, where: tuple[str, int, int]) -> Issue | None:
    """SB007 for an include that exists once its package is built, not in its sources.

    ``$(find PKG)`` is PKG's install directory; from a source tree, a file its CMakeLists.txt
    installs under another name is not found, yet the description is fine once built: the
    environment, not the file (as for a package that is nowhere, SB007 is a warning).
    """
    match = _INCLUDED.search(text)
    if match is None:
        return None
    missing = Path(match["path"])
    found = installed_from(missing)
    if found is None:
        return None
    name, installed = found.package, missing.relative_to(found.package_dir)
    target = f"share/{name}/{found.installed_dir}".rstrip("/")
    return Issue(
        "SB007", f"package '{name}' is here only as sources ({_shown(found.package_dir)}), and "
        f"$(find {name}) means its install directory: the include '{installed.as_posix()}' "
        f"exists once built (CMakeLists.txt installs {found.source_dir} as {target}); nothing "
        "in the file is checked", where=where,
        fix=f"build the workspace and pass --package {name}=install/{name}/share/{name}, or "
        "source install/setup.bash")


def _shown(path: Path) -> str:
    """``path`` relative to the current directory when inside it."""
    try:
        return path.relative_to(Path.cwd()).as_posix() or "."
    except ValueError:
        return str(path)


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
