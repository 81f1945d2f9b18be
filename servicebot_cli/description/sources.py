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
        calls: For elements produced by xacro macros, the macro calls that did it, from the
            innermost (the call in another macro's body that passed the values) out to the
            call in the file the user named.
    """

    file: str
    line: int
    column: int = 0
    calls: tuple[SourceRef, ...] = ()

    @property
    def via(self) -> SourceRef | None:
        """The outermost macro call that produced the element, or None."""
        return self.calls[-1] if self.calls else None

    def location(self) -> str:
        """``file:line:column``, the form editors and CI annotations understand."""
        if self.column:
            return f"{self.file}:{self.line}:{self.column}"
        return f"{self.file}:{self.line}"

    def __str__(self) -> str:
        if self.via is None:
            return self.location()
        return f"{self.location()} (from the macro call at {self.via.location()})"
