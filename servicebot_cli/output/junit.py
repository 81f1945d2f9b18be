"""``check`` findings as JUnit XML: one test case per checked file.

A file fails when it has findings at the failing level (errors; warnings too with
--strict); each such finding is one ``<failure>``. Other findings go to ``<system-out>``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.result import CheckResult


def junit_text(result: CheckResult) -> str:
    """The JUnit XML report of a run."""
    failing = sum(1 for r in result.reports if any(result.fails(f) for f in r.findings))
    counts = {"name": "servicebot check", "tests": str(len(result.reports)),
              "failures": str(failing), "errors": "0", "skipped": "0"}
    suites = ET.Element("testsuites", counts)
    suite = ET.SubElement(suites, "testsuite", counts)
    for report in result.reports:
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
        if other:
            ET.SubElement(case, "system-out").text = "\n".join(other)
    ET.indent(suites)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(suites, "unicode") + "\n"
