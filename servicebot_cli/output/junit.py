"""``check`` findings as JUnit XML: one test case per checked file.

A file fails when it has findings at the failing level (errors; warnings too with
--strict); each such finding is one ``<failure>``. Other findings go to ``<system-out>``. A
file xacro could not expand (a walk passes no argument, a package is not there) is
``<skipped>`` when nothing fails it: nothing in it was checked.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.result import CheckResult


def junit_text(result: CheckResult) -> str:
    """The JUnit XML report of a run."""
    failing = [any(result.fails(f) for f in r.findings) for r in result.reports]
    # a file xacro could not expand, which nothing fails: nothing in it was checked
    skipped = [not r.expanded and not fails for r, fails in zip(result.reports, failing,
                                                                  strict=True)]
    counts = {"name": "servicebot check", "tests": str(len(result.reports)),
              "failures": str(sum(failing)), "errors": "0", "skipped": str(sum(skipped))}
    suites = ET.Element("testsuites", counts)
    suite = ET.SubElement(suites, "testsuite", counts)
    for report, skip in zip(result.reports, skipped, strict=True):
        case = ET.SubElement(suite, "testcase", classname="servicebot.check", name=report.file,
                             file=report.file)
        other = []
        for finding in report.findings:
            line = f"{finding.location()}: {finding.severity.value} {finding.code} " \
                   f"[{RULES[finding.code].name}] {finding.message}"
            if finding.fix:
                line += f" (fix: {finding.fix})"
            if result.fails(finding):
                failure = ET.SubElement(case, "failure", type=finding.code,
                                        message=f"{finding.code} {finding.message}")
                failure.text = line
            else:
                other.append(line)
        if skip:
            reason = report.findings[0].message if report.findings else "not expanded"
            ET.SubElement(case, "skipped", message=f"not expanded: {reason}")
        if other:
            ET.SubElement(case, "system-out").text = "\n".join(other)
    ET.indent(suites)
    text = ET.tostring(suites, "unicode")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + _NOT_XML.sub(_escaped, text) + "\n"


# what XML 1.0 has no way to hold, even as a reference: a control character in a file name
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def _escaped(char: re.Match[str]) -> str:
    """A character XML cannot hold, written as Python would: ``\\x01``."""
    return char[0].encode("unicode_escape", "backslashreplace").decode("ascii")
