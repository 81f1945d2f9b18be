"""One batch run, for ``fk --configs`` and ``ik --targets``: read, convert, write, count.

A stage turns input rows into result rows; this module wires it between a reader and a
sink, applies the ``--on-error`` policy, and reports what it skipped. The sink (a file
written atomically, or stdout) is passed in: it belongs to ``output``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from typing import Literal, Protocol, TypeAlias, TypeVar

from servicebot_cli.batch.policy import OnError, Tally, handled
from servicebot_cli.batch.reading import BatchInputError, Row, Source, open_source
from servicebot_cli.kinematics.json_types import JsonObject

RowKind: TypeAlias = Literal["csv", "jsonl"]
"""The shape of result rows: flat CSV columns, or nested JSON Lines objects."""


class WriteRow(Protocol):
    """Writes result rows: one at a time, or a block of rows already formatted."""

    @property
    def delimiter(self) -> str:
        """The CSV delimiter of the output."""

    def __call__(self, row: JsonObject) -> None:
        """Write one row (a dict with the columns as keys)."""

    def text(self, rows: str) -> None:
        """Write rows already formatted in the output's format, each ending in a newline."""


Warn = Callable[[str], None]
"""Where a batch says what it skipped or changed: one line each (stderr)."""
T = TypeVar("T")


class RowSink(Protocol):
    """Where result rows go, one at a time, as they are computed."""

    @property
    def kind(self) -> RowKind:
        """The row shape the sink writes."""

    def open(self, columns: Sequence[str]) -> AbstractContextManager[WriteRow]:
        """Start writing rows with ``columns`` (the CSV header); the block's end commits."""


class Stage(Protocol[T]):
    """What a command does with each line."""

    def columns(self) -> list[str]:
        """CSV header of the results."""

    def check_header(self, columns: Sequence[str]) -> None:
        """Refuse a CSV input header the stage cannot use (raise a ServicebotError)."""

    def parse(self, row: Row) -> T:
        """The usable content of a line (raise a ServicebotError when there is none)."""

    def results(self, items: Iterable[tuple[Row, T]], kind: RowKind) -> Iterator[JsonObject]:
        """One result row per parsed line, lazily."""


@dataclass(frozen=True)
class BatchSummary:
    """What a batch run did.

    Attributes:
        source: The input's name for messages (``<stdin>`` for ``-``).
        rows: Lines read (not blank, not comments).
        skipped: Lines skipped under ``--on-error skip``.
        failed: Line numbers whose answer is no (targets not reached).
    """

    source: str
    rows: int
    skipped: int = 0
    failed: tuple[int, ...] = ()


def stream(stage: Stage[T], path: str, sink: RowSink, *, on_error: OnError, warn: Warn,
           chunked_csv: Callable[..., BatchSummary] | None = None) -> BatchSummary:
    """Run ``stage`` over every line of ``path``, writing results to ``sink`` as they come.

    The sink is opened after the input's header is read and checked, so a bad input
    leaves no output file. A CSV input goes to ``chunked_csv`` when the stage has one (its
    own reader, a chunk of lines at a time: ``(stage, source, handle, sink, on_error=,
    warn=)``).

    Raises:
        BatchInputError: The input cannot be opened or its header is unusable.
        BadLine: An unusable line under ``--on-error stop``.
    """
    source, handle = open_source(path)
    with handle:
        if source.kind == "csv" and chunked_csv is not None:
            return chunked_csv(stage, source, handle, sink, on_error=on_error, warn=warn)
        return stream_source(stage, source, sink, on_error=on_error, warn=warn)


def stream_source(stage: Stage[T], source: Source, sink: RowSink, *, on_error: OnError,
                  warn: Warn) -> BatchSummary:
    """:func:`stream` on an input already open (the caller closes it).

    Raises:
        JointNotFound, BadTarget: A CSV header the stage cannot use.
        BadLine: An unusable line under ``--on-error stop``.
    """
    tally = Tally()
    if source.kind == "csv":
        stage.check_header(source.columns)
    with sink.open(stage.columns()) as write:
        write_results(stage, source.rows, source.display, write, sink.kind,
                      on_error=on_error, warn=warn, tally=tally)
        refuse_no_lines(source.display, tally)
    return summarise(source.display, tally, warn)


def write_results(stage: Stage[T], rows: Iterable[Row], display: str, write: WriteRow,
                  kind: RowKind, *, on_error: OnError, warn: Warn, tally: Tally) -> None:
    """Parse ``rows`` one by one through ``stage`` and write its results (the per-line path).

    Raises:
        BadLine: An unusable line under ``--on-error stop``.
    """
    items = handled(display, rows, stage.parse, on_error=on_error, warn=warn, tally=tally)
    for result in stage.results(items, kind):
        write(result)


def refuse_no_lines(display: str, tally: Tally) -> None:
    """Refuse a file of a header alone, as an empty one is: nothing to compute; and a run
    that skipped every line (``--on-error skip``), which computed nothing either.

    Raises:
        BatchInputError: No data line was read, or none was used.
    """  # noqa: D205
    if not tally.rows:
        raise BatchInputError(f"{display}: has no data lines below its header; give one "
                              "line per item")
    if tally.skipped == tally.rows:
        raise BatchInputError(f"{display}: every one of its {tally.rows} lines was skipped, "
                              "so nothing was computed; fix the lines named above")


def summarise(display: str, tally: Tally, warn: Warn) -> BatchSummary:
    """The summary of a run; says on ``warn`` how many lines were skipped."""
    if tally.skipped:
        warn(f"skipped {tally.skipped} of {tally.rows} lines of {display}")
    return BatchSummary(display, tally.rows, tally.skipped)
