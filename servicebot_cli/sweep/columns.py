"""The runs table: one row per finished run, one type per column, the same in CSV and Parquet.

Columns come in a fixed order: ``run key point draw seed``, the swept values (file order),
the metrics (summary order), then ``passed`` and ``failed_expectations``. Each column has one
kind, read from its cells: ``bool``, ``int``, ``float`` (ints and floats mixed, e.g. a grid
``[0, 0.5]``) or ``str`` (text, and anything mixed with text, as text). A run without a
value in a column (a metric its summary lacks) has ``None``: an empty CSV field, a Parquet
null. So ``runs.csv`` read with the column's kind and ``runs.parquet`` hold the same values.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from servicebot_cli.sweep.session import RunResult

FIXED_COLUMNS = ("run", "key", "point", "draw", "seed")
VERDICT_COLUMNS = ("passed", "failed_expectations")
KINDS = ("bool", "int", "float", "str")
_INT64 = (-(2**63), 2**63 - 1)


@dataclass(frozen=True)
class Column:
    """One column of the runs table.

    Attributes:
        name: The header, e.g. ``slip.track_factor`` or ``odometry_drift.final_position_m``.
        kind: One of :data:`KINDS`.
        cells: One value per run, of that kind, or None where the run has none.
    """

    name: str
    kind: str
    cells: tuple[Any, ...]


def run_columns(results: Sequence[RunResult]) -> list[Column]:
    """The table of ``results``, column by column."""
    values = _names(r.run.values for r in results)
    metrics = _names(r.metrics.items() for r in results)
    raw: dict[str, list[Any]] = {
        "run": [r.run.index for r in results], "key": [r.run.key for r in results],
        "point": [r.run.point for r in results], "draw": [r.run.draw for r in results],
        "seed": [r.run.seed for r in results]}
    for name in values:
        raw[name] = [_cell(dict(r.run.values).get(name)) for r in results]
    for name in metrics:
        raw.setdefault(name, [r.metrics.get(name) for r in results])
    raw["passed"] = [not r.failed for r in results]
    raw["failed_expectations"] = ["; ".join(r.failed) or None for r in results]
    return [typed(name, cells) for name, cells in raw.items()]


def _names(rows: Iterable[Iterable[tuple[str, Any]]]) -> list[str]:
    """Every name, each row's order kept.

    A name first seen in a later row goes after the name before it in that row
    (``closest_time_s`` stays beside ``min_obstacle_distance_m`` when the first runs had no
    obstacle).
    """
    order: list[str] = []
    seen_rows: set[tuple[str, ...]] = set()
    for row in rows:
        names = tuple(name for name, _ in row)
        if names in seen_rows:
            continue
        seen_rows.add(names)
        at = 0
        for name in names:
            if name not in order:
                order.insert(at, name)
            at = order.index(name) + 1
    return order


def _cell(value: Any) -> Any:
    """A swept value as one cell: numbers and text as they are, anything else as JSON."""
    if isinstance(value, str | int | float | bool) or value is None:
        return value
    return json.dumps(value, default=str)


def typed(name: str, cells: Sequence[Any]) -> Column:
    """A column whose cells all have the kind its values share (None stays None)."""
    kind = column_kind(cells)
    converters: dict[str, Callable[[Any], Any]] = {"bool": bool, "int": int, "float": float,
                                                   "str": _text}
    convert = converters[kind]
    return Column(name, kind, tuple(None if c is None else convert(c) for c in cells))


def column_kind(cells: Iterable[Any]) -> str:
    """``bool``, ``int``, ``float`` or ``str``: the narrowest kind that holds every cell."""
    present = [c for c in cells if c is not None]
    if present and all(isinstance(c, bool) for c in present):
        return "bool"
    if any(isinstance(c, bool) or not isinstance(c, int | float) for c in present):
        return "str"
    if all(isinstance(c, int) and _INT64[0] <= c <= _INT64[1] for c in present):
        return "int" if present else "str"
    return "float"


def _text(value: Any) -> str:
    return value if isinstance(value, str) else json.dumps(value)


def csv_text(columns: Sequence[Column]) -> str:
    """The table as CSV text.

    Floats as Python writes them (``0.5``, ``1.0``, ``inf``), bools as ``True``/``False``,
    no value as an empty field.
    """
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([c.name for c in columns])
    for row in zip(*(c.cells for c in columns), strict=True):
        writer.writerow(["" if v is None else repr(v) if isinstance(v, float) else v
                         for v in row])
    return buffer.getvalue()


def arrow_table(columns: Sequence[Column]) -> Any:
    """The table as a ``pyarrow.Table`` with one Arrow type per kind (pyarrow imported here).

    Raises:
        ImportError: pyarrow is not installed.
    """
    import pyarrow as pa

    types = {"bool": pa.bool_(), "int": pa.int64(), "float": pa.float64(), "str": pa.string()}
    return pa.table({c.name: pa.array(c.cells, type=types[c.kind]) for c in columns})
