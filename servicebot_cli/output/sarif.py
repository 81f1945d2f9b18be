"""``check`` findings as SARIF 2.1.0, the format GitHub code scanning uploads.

Valid against the OASIS schema (a test validates every run against it). Locations are
relative URIs (from the current directory) when the file is below it, else ``file://`` URIs.
"""

from __future__ import annotations

from pathlib import Path
from urllib.parse import quote

from servicebot_cli import __version__
from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.findings import Finding, Severity
from servicebot_cli.check.result import CheckResult
from servicebot_cli.common.jsonable import dumps

SCHEMA = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"
_LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def sarif_text(result: CheckResult) -> str:
    """The SARIF log of a run, with the whole catalogue as the driver's rules."""
    codes = list(RULES)
    rules = [
        {
            "id": code,
            "name": rule.name,
            "shortDescription": {"text": rule.summary},
            "fullDescription": {"text": rule.explanation},
            "help": {"text": rule.explanation + (f" Fix: {rule.fix}" if rule.fix else "")},
            "defaultConfiguration": {"level": _LEVELS[rule.severity]},
            "properties": {"family": rule.family},
        }
        for code, rule in RULES.items()
    ]
    log = {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {
                "name": "servicebot check",
                "version": __version__,
                "informationUri": "https://pypi.org/project/servicebot/",
                "rules": rules,
            }},
            "results": [_result(f, codes.index(f.code), result) for f in result.findings],
            "columnKind": "unicodeCodePoints",
        }],
    }
    return dumps(log)


def _result(finding: Finding, index: int, result: CheckResult) -> dict[str, object]:
    text = finding.message + (f" Fix: {finding.fix}" if finding.fix else "")
    location: dict[str, object] = {"artifactLocation": {"uri": _uri(finding.file)}}
    if finding.line:
        region: dict[str, int] = {"startLine": finding.line}
        if finding.column:
            region["startColumn"] = finding.column
        location["region"] = region
    entry: dict[str, object] = {
        "ruleId": finding.code,
        "ruleIndex": index,
        "level": "error" if result.fails(finding) else _LEVELS[finding.severity],
        "message": {"text": text},
        "locations": [{"physicalLocation": location}],
    }
    if finding.calls:
        entry["relatedLocations"] = [_via(call, index)
                                     for index, call in enumerate(finding.calls)]
    return entry


def _via(via: str, index: int = 0) -> dict[str, object]:
    file, _, rest = via.rpartition(":")
    line = 0
    if rest.isdigit() and ":" in file:
        file, _, line_text = file.rpartition(":")
        line = int(line_text) if line_text.isdigit() else 0
    location: dict[str, object] = {"artifactLocation": {"uri": _uri(file or via)}}
    if line:
        location["region"] = {"startLine": line}
    text = ("the xacro macro call that produced the element" if index == 0
            else "a xacro macro call around it")
    return {"id": index, "physicalLocation": location, "message": {"text": text}}


def _uri(file: str) -> str:
    """``file`` as a percent-encoded URI reference, relative where it lies under here.

    A ``#`` or a space in a file name is then no fragment or separator.
    """
    path = Path(file)
    if not path.is_absolute():
        return quote(path.as_posix())
    try:
        return quote(path.relative_to(Path.cwd()).as_posix())
    except ValueError:
        return path.as_uri()
