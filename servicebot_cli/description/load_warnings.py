"""LoadWarning: what reading a description warned of, where, and what to change.

xacro prints three kinds of lines while it expands: its own warnings and those a file writes
with ``xacro.warning()`` (``warning: ...``), a file's ``xacro.error()`` (``error: ...``, after
which xacro goes on and writes the robot), and a file's ``xacro.message()`` (the text alone).
The loader adds its own warnings, each with the place it is about and its advice.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Said = Literal["warning", "error", "message"]


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
            ``xacro.message()``.
    """

    text: str
    file: str | None = None
    line: int = 0
    column: int = 0
    fix: str | None = None
    said_as: Said = "warning"

    def __str__(self) -> str:
        if self.file is None:
            return self.text
        if not self.line:
            return f"{self.file}: {self.text}"
        return f"{self.file}:{self.line}:{self.column}: {self.text}"


_NOISE = ("when processing file:", "included from:", "in file:", "when instantiating macro:",
          "instantiated from:")
"""The trail of files and macros xacro prints after a warning (``xacro.print_location()``)."""


def printed_by_xacro(stderr_text: str) -> tuple[LoadWarning, ...]:
    """The warnings, errors and messages in what xacro printed, one each.

    Without a terminal, xacro writes ``warning: `` or ``error: `` before a warning or an
    error, and a message bare. An indented line continues a warning (``inconsistent namespace
    redefinitions`` gives the old and the new URI on lines of their own).
    """
    said: list[LoadWarning] = []
    for raw in stderr_text.splitlines():
        line = raw.strip()
        if not line or line.startswith(_NOISE):
            continue
        if raw[:1].isspace() and said and said[-1].said_as != "message":
            said[-1] = LoadWarning(f"{said[-1].text} {line}", said_as=said[-1].said_as)
        elif line.startswith("warning: "):
            said.append(LoadWarning(line.removeprefix("warning: ")))
        elif line.startswith("error: "):
            said.append(LoadWarning(line.removeprefix("error: "), said_as="error"))
        else:
            said.append(LoadWarning(line, said_as="message"))
    return tuple(said)
