"""The sweep's tables: ``runs.csv`` (and ``runs.parquet``) and ``summary.json``.

One row per finished run, in the sweep's order: its index, key, grid point, draw, seed, the
values it ran with, every metric of its summary, and the expectations it failed. The summary
counts runs, lists the failed expectations and runs, and gives per grid point the statistics
of every metric over its draws and seeds. Every file is written atomically.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.files import atomic_output, write_atomic
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.sweep.metrics import describe

if TYPE_CHECKING:
    from servicebot_cli.sweep.session import RunResult, SweepReport

FIXED_COLUMNS = ("run", "key", "point", "draw", "seed")


def rows(report: SweepReport) -> list[dict[str, Any]]:
    """One dict per finished run: fixed columns, values, metrics, then the verdict."""
    return [{"run": r.run.index, "key": r.run.key, "point": r.run.point, "draw": r.run.draw,
             "seed": r.run.seed, **{name: _cell(v) for name, v in r.run.values},
             **r.metrics, "passed": not r.failed, "failed_expectations": "; ".join(r.failed)}
            for r in report.results]


def _cell(value: Any) -> Any:
    """A value as one cell: numbers and text as they are, anything else as JSON."""
    if isinstance(value, str | int | float | bool) or value is None:
        return value
    return json.dumps(value, default=str)


def write_tables(report: SweepReport, out_dir: Path) -> list[Path]:
    """Write ``runs.csv``, ``runs.parquet`` (when pyarrow is installed) and ``summary.json``.

    Returns:
        The files written.

    Raises:
        OutputError: A file cannot be written.
    """
    table = rows(report)
    written = [out_dir / "runs.csv", out_dir / "summary.json"]
    write_atomic(written[0], _csv_text(table))
    write_atomic(written[1], dumps(summary(report)))
    if _write_parquet(table, out_dir / "runs.parquet"):
        written.insert(1, out_dir / "runs.parquet")
    return written


def _csv_text(table: Sequence[dict[str, Any]]) -> str:
    columns: dict[str, None] = {}
    for row in table:
        columns.update(dict.fromkeys(row))
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(columns), lineterminator="\n")
    writer.writeheader()
    for row in table:
        writer.writerow({k: repr(v) if isinstance(v, float) else v for k, v in row.items()})
    return buffer.getvalue()


def _write_parquet(table: Sequence[dict[str, Any]], path: Path) -> bool:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        return False
    with atomic_output(path, "wb") as handle:
        pq.write_table(pa.Table.from_pylist(list(table)), handle)
    return True


def summary(report: SweepReport) -> dict[str, Any]:
    """What ``summary.json`` holds (and ``--format json`` prints)."""
    failed = [r for r in report.results if r.failed]
    return {
        "sweep": report.sweep, "robot": report.robot, "scenario": report.scenario,
        "runs": report.planned, "finished": len(report.results), "resumed": report.resumed,
        "passed": len(report.results) - len(failed), "failed": len(failed),
        "expectations": [{"expect": text, "failed_runs": sum(text in r.failed
                                                             for r in report.results)}
                         for text in report.expectations],
        "failed_runs": [_run_entry(r) for r in failed],
        "points": _points(report),
    }


def _run_entry(result: RunResult) -> dict[str, Any]:
    return {"run": result.run.index, "key": result.run.key, "seed": result.run.seed,
            "values": dict(result.run.values), "failed": list(result.failed)}


def _points(report: SweepReport) -> list[dict[str, Any]]:
    groups: dict[int, list[RunResult]] = {}
    for result in report.results:
        groups.setdefault(result.run.point, []).append(result)
    points = []
    for point, results in sorted(groups.items()):
        names = list(dict.fromkeys(name for r in results for name in r.metrics))
        points.append({
            "point": point, "values": dict(results[0].run.grid), "runs": len(results),
            "failed": sum(bool(r.failed) for r in results),
            "metrics": {name: describe([r.metrics.get(name, float("nan")) for r in results])
                        for name in names},
        })
    return points
