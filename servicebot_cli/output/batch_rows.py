"""Writing batch results one line at a time: JSON Lines or CSV, to stdout or a file.

A file is written atomically (see :mod:`servicebot_cli.common.files`): if the run stops on a
bad line or is interrupted (Ctrl-C, SIGTERM, SIGHUP), the file is not created (or keeps its
old content). Results stream: each is written as soon as it is computed.
"""

from __future__ import annotations

import contextlib
import csv
import json
import sys
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import IO

from servicebot_cli.batch.reading import CSV_SUFFIXES, JSONL_SUFFIXES
from servicebot_cli.batch.stream import RowKind, WriteRow
from servicebot_cli.common.files import OutputError, atomic_output
from servicebot_cli.kinematics.json_types import JsonObject, JsonValue

OUTPUT_SUFFIXES = (*CSV_SUFFIXES, *JSONL_SUFFIXES)
"""Extensions ``-o/--output`` accepts: the format comes from them."""


def output_kind(output: str | None, fmt: str) -> RowKind:
    """``csv`` or ``jsonl``: from the output file's extension, else from ``--format``.

    On stdout, ``--format json`` gives JSON Lines and ``text`` gives CSV.

    Raises:
        OutputError: An output file whose extension names neither format.
    """
    if output and output != "-":
        suffix = Path(output).suffix.lower()
        if suffix in CSV_SUFFIXES:
            return "csv"
        if suffix in JSONL_SUFFIXES:
            return "jsonl"
        raise OutputError(f"{output}: cannot tell the format from '{suffix or 'no extension'}'; "
                          "name it .csv or .jsonl")
    return "jsonl" if fmt == "json" else "csv"


class RowFile:
    """A batch's results: a file written atomically, or stdout (None or ``-``)."""

    def __init__(self, output: str | None, fmt: str) -> None:
        """Write to ``output`` in the format its extension names, or per ``fmt`` on stdout.

        Raises:
            OutputError: An output file whose extension names neither format.
        """
        self.output = None if output in (None, "-") else output
        self._kind = output_kind(self.output, fmt)

    @property
    def kind(self) -> RowKind:
        """``csv`` or ``jsonl``."""
        return self._kind

    @contextlib.contextmanager
    def open(self, columns: Sequence[str]) -> Iterator[WriteRow]:
        """A function that writes one result row (a dict with ``columns`` as keys).

        A file appears (replacing an old one) only when the block ends without an error.
        """
        if self.output is None:
            writer = _Writer(sys.stdout, self._kind, columns, ",")
            yield writer
            writer.finish()
            sys.stdout.flush()
            return
        delimiter = "\t" if self.output.lower().endswith(".tsv") else ","
        with atomic_output(self.output) as handle:
            writer = _Writer(handle, self._kind, columns, delimiter)
            yield writer
            writer.finish()


class _Writer:
    """Writes rows to ``handle``: JSON Lines, or CSV after a header of ``columns``.

    The header goes out with the first row (or at :meth:`finish`): a run refused before
    any result leaves nothing on stdout, not a header alone.
    """

    def __init__(self, handle: IO[str], kind: RowKind, columns: Sequence[str],
                 delimiter: str) -> None:
        self.delimiter, self._kind, self._keys = delimiter, kind, list(columns)
        self._handle = handle
        self._dumps = json.dumps
        self._csv = csv.writer(handle, delimiter=delimiter, lineterminator="\n")
        self._header_due = kind == "csv"

    def finish(self) -> None:
        """End a run that succeeded: its header, if no row wrote it."""
        self._begin()

    def _begin(self) -> None:
        if self._header_due:
            self._header_due = False
            self._csv.writerow(self._keys)

    def __call__(self, row: JsonObject) -> None:
        """Write one row."""
        self._begin()
        if self._kind == "jsonl":
            self._handle.write(self._dumps(row, allow_nan=False) + "\n")
        else:
            self._csv.writerow([_cell(row.get(key)) for key in self._keys])

    def text(self, rows: str) -> None:
        """Write rows already formatted, each ending in a newline."""
        self._begin()
        self._handle.write(rows)


def _cell(value: JsonValue) -> JsonValue:
    if isinstance(value, bool):
        return "true" if value else "false"
    return "" if value is None else value
