"""The outcome of a run: every file's findings, the counts, and whether the run fails."""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.check.findings import Finding, Severity
from servicebot_cli.check.runner import FileReport


@dataclass(frozen=True)
class CheckResult:
    """Findings of every checked file, in the order the files were given.

    Attributes:
        reports: One per file.
        strict: Warnings fail the run.
        includes_only: Each named directory that holds only xacro includes (macro
            libraries, parts of robots), with how many: nothing in it is a robot alone.
    """

    reports: tuple[FileReport, ...]
    strict: bool = False
    includes_only: tuple[tuple[str, int], ...] = ()

    @property
    def findings(self) -> tuple[Finding, ...]:
        """Every finding, file by file."""
        return tuple(f for report in self.reports for f in report.findings)

    def count(self, severity: Severity) -> int:
        """How many findings have ``severity``."""
        return sum(1 for f in self.findings if f.severity is severity)

    def fails(self, finding: Finding) -> bool:
        """True when ``finding`` fails the run (errors; warnings too with --strict)."""
        return finding.severity is Severity.ERROR or (
            self.strict and finding.severity is Severity.WARNING)

    @property
    def failed(self) -> bool:
        """True when any finding fails the run."""
        return any(self.fails(f) for f in self.findings)

    def summary(self) -> str:
        """``2 files: 1 error, 3 warnings, 1 info`` (and what that means)."""
        files = f"{len(self.reports)} file{'s' if len(self.reports) != 1 else ''}"
        parts = [_plural(self.count(Severity.ERROR), "error"),
                 _plural(self.count(Severity.WARNING), "warning"),
                 f"{self.count(Severity.INFO)} info"]
        verdict = "failed" if self.failed else "passed"
        if self.strict:
            verdict += " (strict: warnings fail)"
        aside = "".join(f" ({directory} holds only xacro includes, {_plural(count, 'file')}, "
                        "checked through the robot files that include them)"
                        for directory, count in self.includes_only)
        if self.unexpanded:  # read only as far as xacro failed: nothing in them was checked
            aside += (f" ({_plural(self.unexpanded, 'file')} not expanded, so not checked: see "
                      f"{'its finding' if self.unexpanded == 1 else 'their findings'})")
        return f"{files} checked{aside}: {', '.join(parts)}; {verdict}"

    @property
    def unexpanded(self) -> int:
        """How many files could not be read as robots (xacro failed): nothing in them checked."""
        return sum(1 for report in self.reports if not report.expanded)


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"
