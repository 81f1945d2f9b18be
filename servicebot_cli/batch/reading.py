"""Reading batch input one line at a time: CSV with a header, or JSON Lines.

Rows are yielded as they are read, so a file of a million lines never sits in memory. Each
row keeps its line number; a line that cannot be read becomes a row with an ``error``
instead of stopping the stream, so the caller decides whether to stop or skip. Blank lines
and lines starting with ``#`` are ignored.

The format comes from the extension (``.csv``, ``.tsv``; ``.jsonl``, ``.ndjson``, ``.json``)
or, failing that, from the first meaningful character: ``{`` means JSON Lines.
"""

from __future__ import annotations

import collections
import csv
import itertools
import json
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.inputs import open_input_text
from servicebot_cli.kinematics.json_types import JsonValue

CSV_SUFFIXES = (".csv", ".tsv")
_JSON_KINDS = {list: "array", str: "string", int: "number", float: "number", bool: "boolean",
               type(None): "null"}
JSONL_SUFFIXES = (".jsonl", ".ndjson", ".json")


class BatchInputError(ServicebotError):
    """A batch input file cannot be opened or has no usable header."""


@dataclass(frozen=True)
class Row:
    """One line of input.

    Attributes:
        line: 1-based line number in the file.
        values: Column (or key) to value: strings from CSV, JSON values from JSON Lines.
        error: Why the line could not be read; ``values`` is then empty.
    """

    line: int
    values: Mapping[str, JsonValue] = field(default_factory=dict)
    error: str = ""


@dataclass(frozen=True)
class Source:
    """An open batch input.

    Attributes:
        display: The file name for messages (``<stdin>`` for ``-``).
        kind: ``csv`` or ``jsonl``.
        columns: CSV header names (empty for JSON Lines).
        rows: The rows, read lazily.
        delimiter: The CSV delimiter (``,``, or a tab for ``.tsv``).
        header_line: The header's line number (0 for JSON Lines). Until ``rows`` is read,
            the handle :func:`open_source` returns stands just after it, so a reader of
            chunks of raw lines (see :mod:`servicebot_cli.batch.fk_chunks`) may take over.
    """

    display: str
    kind: str
    columns: tuple[str, ...]
    rows: Iterator[Row]
    delimiter: str = ","
    header_line: int = 0


def open_source(path: str) -> tuple[Source, IO[str]]:
    """Open ``path`` (``-`` for stdin) and read its header; the caller closes the handle.

    Raises:
        BatchInputError: Missing, a directory, unreadable, empty, or a bad CSV header.
    """
    display = "<stdin>" if path == "-" else path
    handle = open_input_text(path, kind="a CSV or JSON Lines file", error=BatchInputError)
    lines = _numbered(handle)
    first = next(lines, None)
    if first is None:
        handle.close()
        raise BatchInputError(f"{display}: has no data lines; give one line per item")
    if "\x00" in first[1]:  # UTF-16 (Excel's "Unicode text"): every other byte is NUL
        handle.close()
        raise BatchInputError(f"{display}: not UTF-8 text (it holds NUL bytes: UTF-16?); "
                              "save it as UTF-8")
    kind = _kind(path, first[1])
    if kind == "jsonl":
        return Source(display, kind, (), _json_rows(itertools.chain([first], lines))), handle
    delimiter = "\t" if path.endswith(".tsv") else ","
    header = _split(first[1], delimiter)
    _check_header(display, first[0], header)
    return Source(display, kind, tuple(header), csv_rows(lines, header, delimiter), delimiter,
                  first[0]), handle


def meaningful(text: str) -> bool:
    """Whether line ``text`` holds data: not blank, not a ``#`` comment."""
    stripped = text.strip()
    return bool(stripped) and not stripped.startswith("#")


def _numbered(handle: IO[str]) -> Iterator[tuple[int, str]]:
    """``(line number, text)`` of meaningful lines: not blank, not ``#`` comments."""
    for number, text in enumerate(handle, start=1):
        if number == 1:
            text = text.removeprefix("\ufeff")  # Excel's "CSV UTF-8" starts with a BOM
        stripped = text.strip()
        if stripped and not stripped.startswith("#"):
            yield number, text.rstrip("\r\n")


def _kind(path: str, first: str) -> str:
    suffix = Path(path).suffix.lower()
    if suffix in CSV_SUFFIXES:
        return "csv"
    if suffix in JSONL_SUFFIXES:
        return "jsonl"
    return "jsonl" if first.lstrip().startswith("{") else "csv"


def _split(text: str, delimiter: str) -> list[str]:
    return [cell.strip() for cell in next(csv.reader([text], delimiter=delimiter))]


def _check_header(display: str, line: int, header: list[str]) -> None:
    if any(not name for name in header):
        raise BatchInputError(f"{display}:{line}: the CSV header has an empty column name")
    counts = collections.Counter(header)
    repeated = sorted(name for name, count in counts.items() if count > 1)
    if repeated:
        raise BatchInputError(f"{display}:{line}: column '{repeated[0]}' appears twice "
                              "in the CSV header")
    numeric = [name for name in header if _is_number(name)]
    if numeric:
        raise BatchInputError(f"{display}:{line}: the first line must be a header of names, "
                              f"got the number {numeric[0]}")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def csv_rows(lines: Iterable[tuple[int, str]], header: Sequence[str],
             delimiter: str) -> Iterator[Row]:
    """A row per ``(line number, text)`` of a CSV body; a malformed line as an error row."""
    for number, text in lines:
        try:
            cells = _split(text, delimiter)
        except csv.Error as exc:
            yield Row(number, error=f"not CSV: {exc}")
            continue
        if len(cells) != len(header):
            yield Row(number, error=f"has {len(cells)} fields, the header has {len(header)}")
            continue
        values: dict[str, JsonValue] = dict(zip(header, cells, strict=True))
        yield Row(number, values)


class _RepeatedKey(ValueError):
    """A JSON object that names one key twice (json.loads keeps the last, silently)."""


def _object(pairs: list[tuple[str, object]]) -> dict[str, object]:
    keys = [key for key, _ in pairs]
    if len(set(keys)) != len(keys):
        raise _RepeatedKey(next(key for key in keys if keys.count(key) > 1))
    return dict(pairs)


def _json_rows(lines: Iterator[tuple[int, str]]) -> Iterator[Row]:
    for number, text in lines:
        try:
            value = json.loads(text, object_pairs_hook=_object)
        except _RepeatedKey as exc:
            yield Row(number, error=f"names '{exc}' twice; give each once")
            continue
        except json.JSONDecodeError as exc:
            yield Row(number, error=f"not JSON: {exc.msg} at column {exc.colno}")
            continue
        except RecursionError:  # {"a": [[[[...]]]]} 100,000 deep
            yield Row(number, error="not JSON this reads: nested too deep")
            continue
        except ValueError:  # an integer of over 4,300 digits
            yield Row(number, error="not JSON this reads: a number of too many digits")
            continue
        if not isinstance(value, dict):
            kind = _JSON_KINDS.get(type(value), "value")
            yield Row(number, error=f"is a JSON {kind}, not an object of names and values")
            continue
        yield Row(number, value)
