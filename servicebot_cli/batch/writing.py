"""Writing batch results one line at a time: JSON Lines or CSV, to stdout or a file.

A file is written atomically (see :mod:`servicebot_cli.common.files`): if the run stops on a
bad line or is interrupted, the file is not created (or keeps its old content). Results
stream: each is written as soon as it is computed.
"""

from __future__ import annotations

import contextlib
import csv
import json
import sys
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from servicebot_cli.batch.reading import CSV_SUFFIXES, JSONL_SUFFIXES
from servicebot_cli.common.files import OutputError, atomic_output

WriteRow = Callable[[dict[str, Any]], None]


def output_kind(output: str | None, fmt: str) -> str:
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


@contextlib.contextmanager
def row_writer(output: str | None, kind: str, columns: Sequence[str]) -> Iterator[WriteRow]:
    """A function that writes one result row (a dict with ``columns`` as keys).

    Args:
        output: File to write atomically, or None / ``-`` for stdout.
        kind: ``csv`` (a header of ``columns``, then one line per row) or ``jsonl``.
        columns: The keys of every row, in order.
    """
    if not output or output == "-":
        yield _writer(sys.stdout, kind, columns)
        sys.stdout.flush()
        return
    with atomic_output(output) as handle:
        yield _writer(handle, kind, columns)


def _writer(handle: Any, kind: str, columns: Sequence[str]) -> WriteRow:
    if kind == "jsonl":
        dumps, write = json.dumps, handle.write

        def write_json(row: dict[str, Any]) -> None:
            write(dumps(row, allow_nan=False) + "\n")

        return write_json
    writer = csv.writer(handle, lineterminator="\n")
    writer.writerow(columns)
    keys = list(columns)

    def write_csv(row: dict[str, Any]) -> None:
        writer.writerow([_cell(row.get(key)) for key in keys])

    return write_csv


def _cell(value: Any) -> Any:
    if isinstance(value, bool):
        return "true" if value else "false"
    return "" if value is None else value
