"""What a bad input line does: stop the run (the default) or skip it and go on.

``stop`` ends the run with one ``Error: FILE:LINE: reason`` line and exit code 2; an output
file is then not created. ``skip`` reports each skipped line on stderr, goes on, and the
command ends with a count of what it skipped.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Literal, TypeAlias, TypeVar

from servicebot_cli.batch.reading import Row
from servicebot_cli.common.errors import ServicebotError

T = TypeVar("T")
OnError: TypeAlias = Literal["stop", "skip"]
"""What a bad line does: ``stop`` the run, or ``skip`` the line and go on."""
POLICIES: tuple[OnError, ...] = ("stop", "skip")


class BadLine(ServicebotError):
    """A batch input line that cannot be used, under ``--on-error stop``."""


class RowError(ServicebotError):
    """Raised by a row handler: this line's content is unusable (the message says why)."""


@dataclass
class Tally:
    """Counts of a batch run.

    Attributes:
        rows: Lines read (meaningful ones: not blank, not comments).
        skipped: Lines skipped under ``--on-error skip``.
    """

    rows: int = 0
    skipped: int = 0


def handled(display: str, rows: Iterable[Row], handle: Callable[[Row], T], *,
            on_error: OnError, warn: Callable[[str], None],
            tally: Tally) -> Iterator[tuple[Row, T]]:
    """``(row, handle(row))`` for every usable row of ``rows``, lazily.

    Args:
        display: The input's name for messages.
        rows: The rows of the open input.
        handle: Turns a row into a result; raises a ServicebotError for unusable content.
        on_error: ``stop`` or ``skip``.
        warn: Where skipped lines are reported (stderr).
        tally: Updated as rows are read and skipped.

    Raises:
        BadLine: The first unusable line, under ``stop``.
    """
    for row in rows:
        tally.rows += 1
        try:
            if row.error:
                raise RowError(row.error)
            result = handle(row)
        except ServicebotError as exc:
            where = f"{display}:{row.line}"
            if on_error == "stop":
                raise BadLine(f"{where}: {exc} (--on-error skip goes on without the line)") \
                    from None
            tally.skipped += 1
            warn(f"skipped {where}: {exc}")
            continue
        yield row, result
