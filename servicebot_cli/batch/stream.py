"""One batch run, for ``fk --configs`` and ``ik --targets``: read, convert, write, count.

A stage turns input rows into results; this module wires it between a reader and a writer,
applies the ``--on-error`` policy, and reports what it skipped.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, Protocol

from servicebot_cli.batch.policy import Tally, handled
from servicebot_cli.batch.reading import Row, open_source
from servicebot_cli.batch.writing import output_kind, row_writer


class Stage(Protocol):
    """What a command does with each line."""

    def columns(self) -> list[str]:
        """CSV header of the results."""

    def check_header(self, columns: Sequence[str]) -> None:
        """Refuse a CSV input header the stage cannot use (raise a ServicebotError)."""

    def parse(self, row: Row) -> Any:
        """The usable content of a line (raise a ServicebotError when there is none)."""

    def results(self, items: Iterable[tuple[Row, Any]], kind: str) -> Iterator[dict[str, Any]]:
        """One result row per parsed line, lazily."""


def stream(stage: Stage, path: str, *, output: str | None, fmt: str, on_error: str,
           warn: Callable[[str], None]) -> tuple[Tally, str]:
    """Run ``stage`` over every line of ``path``, writing results as they come.

    Returns:
        The counts, and the input's name for messages.
    """
    kind = output_kind(output, fmt)
    source, handle = open_source(path)
    tally = Tally()
    with handle:
        if source.kind == "csv":
            stage.check_header(source.columns)
        items = handled(source, stage.parse, on_error=on_error, warn=warn, tally=tally)
        with row_writer(output, kind, stage.columns()) as write:
            for result in stage.results(items, kind):
                write(result)
    if tally.skipped:
        warn(f"skipped {tally.skipped} of {tally.rows} lines of {source.display}")
    return tally, source.display
