"""``check`` findings for people (text), scripts (JSON) and GitHub workflow annotations.

Renderers only render: a CheckResult in, text out. SARIF and JUnit live beside this module;
:func:`show` picks the renderer and writes to stdout or, atomically, to a file.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import click

from servicebot_cli import __version__
from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.findings import Finding, Severity
from servicebot_cli.check.result import CheckResult
from servicebot_cli.common.files import atomic_output
from servicebot_cli.common.jsonable import dumps_plain
from servicebot_cli.output.one_line import one_line

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageLocation

JSON_FORMAT_VERSION = 1
"""Bumped when a key of ``check --format json`` changes meaning or goes away."""
_COLOURS = {Severity.ERROR: "red", Severity.WARNING: "yellow", Severity.INFO: "blue"}


def package_lines(result: CheckResult) -> Iterator[str]:
    """``FILE: package NAME at DIR, found as HOW`` for every package each file uses."""
    for report in result.reports:
        for name, location in sorted(report.packages.items()):
            if location is None:
                yield one_line(f"{report.file}: package {name}: not found")
                continue
            caveat = "" if location.ros_finds_it else "; ROS would not find it this way"
            yield one_line(f"{report.file}: package {name} at {location.path}, "
                           f"found as {location.how}{caveat}")


def text_lines(result: CheckResult, colour: bool = False,
               packages: bool = False) -> Iterator[str]:
    """Compiler-style lines, ``file:line:col: severity CODE message``, then a summary.

    With ``packages``, the packages each file uses come before the summary. Of several
    files, a finding in another file than the one checked (a xacro include's) names the
    one checked, unless its macro calls lead there: two robots including one macro file can
    both fail in it.
    """
    several = len(result.reports) > 1
    for report in result.reports:
        for finding in report.findings:
            level = finding.severity.value
            code = f"{finding.code} [{RULES[finding.code].name}]"
            if colour:
                level = click.style(level, fg=_COLOURS[finding.severity], bold=True)
                code = click.style(code, bold=True)
            yield f"{one_line(finding.location())}: {level} {code} {one_line(finding.message)}"
            yield from map(one_line, _context_lines(finding, report.file if several else None))
            if finding.fix:
                yield f"    fix: {one_line(finding.fix)}"
    if packages:
        yield from package_lines(result)
    summary = result.summary()
    if colour:
        summary = click.style(summary, fg="red" if result.failed else "green", bold=True)
    yield summary


_MOST_CALLS_SHOWN = 4


def _context_lines(finding: Finding, checked: str | None) -> Iterator[str]:
    """Where the finding's element came from: its macro calls, then the file ``checked``.

    ``checked`` (None: one file in the run) is named when the finding lies in another
    file and no macro call leads back to it: two robots including one macro file can both
    fail in it, at one line.
    """
    yield from _call_lines(finding)
    if checked is not None and finding.file != checked and not (
            finding.calls and finding.calls[-1].startswith(f"{checked}:")):
        yield f"    while checking {checked}"


def _call_lines(finding: Finding) -> Iterator[str]:
    """The macro calls that produced the element, innermost first (xacro's own order).

    A deep nest (a recursive macro) shows its innermost calls, then the outermost one.
    """
    calls = finding.calls
    shown = calls if len(calls) <= _MOST_CALLS_SHOWN else calls[:_MOST_CALLS_SHOWN - 1]
    for index, call in enumerate(shown):
        yield f"    {'from' if index == 0 else 'within'} the macro call at {call}"
    if len(calls) > len(shown):
        yield (f"    within {len(calls) - len(shown)} more macro calls, the outermost at "
               f"{calls[-1]}")


def finding_record(finding: Finding, result: CheckResult) -> dict[str, object]:
    """One finding as a JSON object (documented in README.md)."""
    return {
        "code": finding.code,
        "name": RULES[finding.code].name,
        "severity": finding.severity.value,
        "fails": result.fails(finding),
        "message": finding.message,
        "file": finding.file,
        "line": finding.line,
        "column": finding.column,
        "via": finding.via,
        "calls": list(finding.calls),
        "fix": finding.fix,
    }


def package_record(location: PackageLocation | None) -> dict[str, object]:
    """How one package was found (documented in README.md); path null when nowhere."""
    if location is None:
        return {"path": None, "how": "not found", "ros_finds_it": False}
    return {"path": str(location.path), "how": location.how,
            "ros_finds_it": location.ros_finds_it}


def json_text(result: CheckResult) -> str:
    """The versioned JSON document of a run (made of strings, integers, booleans and None)."""
    return dumps_plain({
        "format_version": JSON_FORMAT_VERSION,
        "tool": {"name": "servicebot check", "version": __version__},
        "files": [
            {"file": report.file,
             "findings": [finding_record(f, result) for f in report.findings],
             "packages": {name: package_record(location)
                          for name, location in sorted(report.packages.items())}}
            for report in result.reports
        ],
        "summary": {
            "files": len(result.reports),
            "errors": result.count(Severity.ERROR),
            "warnings": result.count(Severity.WARNING),
            "info": result.count(Severity.INFO),
            "strict": result.strict,
            "failed": result.failed,
            **({"includes_only": [{"directory": directory, "files": count}
                                  for directory, count in result.includes_only]}
               if result.includes_only else {}),
        },
    })


def _escape_data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def github_lines(result: CheckResult) -> Iterator[str]:
    """GitHub Actions workflow commands: ``::error file=F,line=L,col=C,title=T::message``.

    The message's later lines (``%0A``) are the text report's: the macro calls that made
    the element, and the file checked when it is not the finding's own.
    """
    levels = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
    several = len(result.reports) > 1
    for report, finding in ((r, f) for r in result.reports for f in r.findings):
        level = "error" if result.fails(finding) else levels[finding.severity]
        properties = [f"file={_escape_property(finding.file)}"]
        if finding.line:
            properties.append(f"line={finding.line}")
            if finding.column:
                properties.append(f"col={finding.column}")
        title = f"{finding.code} {RULES[finding.code].name}"
        properties.append(f"title={_escape_property(title)}")
        context = [line.strip() for line in _context_lines(finding,
                                                           report.file if several else None)]
        message = "\n".join([finding.message + (f" (fix: {finding.fix})" if finding.fix else ""),
                              *context])
        yield f"::{level} {','.join(properties)}::{_escape_data(message)}"
    yield result.summary()


def report_text(result: CheckResult, fmt: str, colour: bool = False,
                packages: bool = False) -> str:
    """The whole report in ``fmt`` (text, github, json, sarif or junit), ending in a newline.

    ``packages``: the text report lists the packages each file uses (JSON always does).
    """
    from servicebot_cli.output import junit, sarif

    if fmt == "text":
        return "\n".join(text_lines(result, colour=colour, packages=packages)) + "\n"
    if fmt == "github":
        return "\n".join(github_lines(result)) + "\n"
    renderers = {"json": json_text, "sarif": sarif.sarif_text, "junit": junit.junit_text}
    return renderers[fmt](result)


def show(result: CheckResult, fmt: str, output: str, packages: bool = False) -> None:
    """Print the report (``output`` is ``-``) or write it atomically, the summary on stderr.

    Raises:
        OutputError: The file cannot be written.
    """
    if output == "-":
        click.echo(report_text(result, fmt, colour=True, packages=packages), nl=False)
        return
    with atomic_output(output) as handle:
        handle.write(report_text(result, fmt, packages=packages))
    click.echo(result.summary(), err=True)
