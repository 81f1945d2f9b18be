"""Where an element of a robot description was written."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SourceRef:
    """A position in a source file.

    Attributes:
        file: Path as the user would type it (relative where the user gave it relative).
        line: 1-based line.
        column: 1-based column of the start tag's ``<``.
        via: For elements produced by a xacro macro, the outermost macro call that did it.
    """

    file: str
    line: int
    column: int = 0
    via: SourceRef | None = None

    def location(self) -> str:
        """``file:line:column``, the form editors and CI annotations understand."""
        if self.column:
            return f"{self.file}:{self.line}:{self.column}"
        return f"{self.file}:{self.line}"

    def __str__(self) -> str:
        if self.via is None:
            return self.location()
        return f"{self.location()} (from the macro call at {self.via.location()})"
