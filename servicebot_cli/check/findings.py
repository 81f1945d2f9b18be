"""What a rule reports: a Finding with a code, a severity and where it is."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET


class Severity(str, Enum):
    """How much a finding matters; ``error`` fails a run, ``warning`` fails it with --strict."""

    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        """0 for errors, 1 for warnings, 2 for info: the order findings are listed in."""
        return ("error", "warning", "info").index(self.value)


@dataclass(frozen=True)
class Finding:
    """One problem, at one place.

    Attributes:
        code: The rule's stable code, ``SB301``.
        severity: As configured for this run (the rule's default unless overridden).
        message: What is wrong, naming the element and the values.
        file: The file to edit (the xacro source for xacro input).
        line: 1-based line, 0 when the problem is the whole file.
        column: 1-based column, 0 when unknown.
        fix: What to do instead, with the values to use where there are some.
        calls: Every xacro macro call that produced the element, ``file:line:column``, from
            the innermost (the call in another macro's body that passed the values) out to
            :attr:`via`; empty without xacro macros.
    """

    code: str
    severity: Severity
    message: str
    file: str
    line: int = 0
    column: int = 0
    fix: str | None = None
    calls: tuple[str, ...] = ()

    @property
    def via(self) -> str | None:
        """The outermost macro call that produced the element (in the file the user named)."""
        return self.calls[-1] if self.calls else None

    def location(self) -> str:
        """``file:line:column`` (shorter when line or column is unknown)."""
        if not self.line:
            return self.file
        if self.column:
            return f"{self.file}:{self.line}:{self.column}"
        return f"{self.file}:{self.line}"

    def sort_key(self) -> tuple[str, int, int, str]:
        """Order within a file: by position, then code."""
        return (self.file, self.line, self.column, self.code)


@dataclass(frozen=True)
class Issue:
    """What a rule function yields: a finding before it is placed and configured.

    The runner turns it into a :class:`Finding`: the position comes from ``element``
    (the xacro source line for xacro input) or from ``where``, the severity from the
    catalogue and the settings.

    Attributes:
        code: The rule's code.
        message: What is wrong.
        element: The XML element it is about, when there is one.
        fix: What to do instead.
        where: An explicit ``(file, line, column)``, for problems found before parsing.
        severity: This occurrence's severity when the settings do not set the rule's, for
            rules whose weight depends on the file (SB303 is an error only in a description
            meant for a simulator); None for the catalogue's.
        attribute: The attribute of ``element`` it is about: placed at the attribute's own
            line where the element spans several (an exporter's one attribute a line).
    """

    code: str
    message: str
    element: ET.Element | None = None
    fix: str | None = None
    where: tuple[str, int, int] | None = None
    severity: Severity | None = None
    attribute: str | None = None
