"""LoadWarning: what reading a description warned of, where, and what to change.

xacro prints three kinds of lines while it expands: its own warnings and those a file writes
with ``xacro.warning()`` (``warning: ...``), a file's ``xacro.error()`` (``error: ...``, after
which xacro goes on and writes the robot), and a file's ``xacro.message()`` (the text alone).
The loader adds its own warnings, each with the place it is about and its advice.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from servicebot_cli.description.sources import SourceRef

Said = Literal["warning", "error", "message", "package", "installed"]


@dataclass(frozen=True)
class LoadWarning:
    """One warning (or message) from reading a description.

    Attributes:
        text: What it says, without a place or xacro's ``warning: `` prefix.
        file: The file it is about; None when xacro did not say (its own warnings).
        line: The line it is about (1-based), 0 when unknown.
        column: The column (1-based), 0 when unknown.
        fix: What to change, when the producer knows.
        said_as: How xacro printed it: a warning, a file's ``xacro.error()`` or a file's
            ``xacro.message()``; ``package``: the loader's, a ``$(find)`` of a package that
            is nowhere, left as written; ``installed``: the loader's, an include that holds
            in the sources only.
    """

    text: str
    file: str | None = None
    line: int = 0
    column: int = 0
    fix: str | None = None
    said_as: Said = "warning"

    def __str__(self) -> str:
        return f"{self.where}{self.text}"

    @property
    def where(self) -> str:
        """``file:line:column: `` (``file: `` without a line; empty without a file)."""
        if self.file is None:
            return ""
        return f"{self.file}: " if not self.line else f"{self.file}:{self.line}:{self.column}: "


def said_by_xacro(said: Sequence[tuple[str, SourceRef | None]]) -> tuple[LoadWarning, ...]:
    """A warning, error or message per text xacro printed, at its element (None: none).

    Without a terminal, xacro writes ``warning: `` or ``error: `` before a warning or an
    error, and a message as it is; a text of several lines (``inconsistent namespace
    redefinitions`` gives the old and the new URI on lines of their own) is one.
    """
    out = []
    for printed, ref in said:
        text = " ".join(line.strip() for line in printed.splitlines() if line.strip())
        kind: Said = "message"
        if text.startswith("warning: "):
            text, kind = text.removeprefix("warning: "), "warning"
        elif text.startswith("error: "):
            text, kind = text.removeprefix("error: "), "error"
        out.append(LoadWarning(text, ref.file, ref.line, ref.column, said_as=kind)
                   if ref is not None else LoadWarning(text, said_as=kind))
    return tuple(out)
