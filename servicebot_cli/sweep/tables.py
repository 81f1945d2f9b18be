"""The sweep's tables: ``runs.csv`` (and ``runs.parquet``) and ``summary.json``.

One row per finished run, in the sweep's order: its index, key, grid point, draw, seed, the
values it ran with, every metric of its summary, and the expectations it failed (typed
columns: :mod:`servicebot_cli.sweep.columns`). The summary counts runs, lists the failed
expectations and runs, and gives per grid point the statistics of every metric over its
draws and seeds. Every file is written atomically.

``runs.parquet`` is written when pyarrow is installed (the ``parquet`` extra). Without it, a
``runs.parquet`` left by an earlier sweep in the directory is removed, with a note, rather
than left to disagree with ``runs.csv``.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.files import OutputError, atomic_output, write_atomic
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.sweep.columns import Column, arrow_table, csv_text, run_columns
from servicebot_cli.sweep.metrics import describe

if TYPE_CHECKING:
    from servicebot_cli.sweep.session import RunResult, SweepReport

PARQUET_EXTRA = "pip install 'servicebot[parquet]' (pyarrow)"


@dataclass(frozen=True)
class Written:
    """The tables written, and anything the user should know about them.

    Attributes:
        files: The files written, ``runs.csv`` first.
        notes: Lines for stderr (``note: ...``), e.g. an old ``runs.parquet`` removed.
    """

    files: tuple[Path, ...]
    notes: tuple[str, ...] = ()


def write_tables(report: SweepReport, out_dir: Path) -> Written:
    """Write ``runs.csv``, ``runs.parquet`` (when pyarrow is installed) and ``summary.json``.

    Raises:
        OutputError: A file cannot be written (or an old ``runs.parquet`` removed).
    """
    columns = run_columns(report.results)
    files = [out_dir / "runs.csv", out_dir / "summary.json"]
    write_atomic(files[0], csv_text(columns))
    write_atomic(files[1], dumps(summary(report)))
    parquet = out_dir / "runs.parquet"
    if _write_parquet(columns, parquet):
        return Written((files[0], parquet, files[1]))
    if not os.path.exists(parquet):
        return Written(tuple(files))
    try:
        parquet.unlink()
    except OSError as exc:
        raise OutputError(f"{parquet}: an earlier sweep's table, out of date, cannot be "
                          f"removed: {exc.strerror or exc}") from None
    return Written(tuple(files), (f"note: removed {parquet}, an earlier sweep's table: "
                                  f"pyarrow is not installed to rewrite it; {PARQUET_EXTRA}",))


def _write_parquet(columns: list[Column], path: Path) -> bool:
    """Write ``path``; False when pyarrow is missing."""
    try:
        import pyarrow.parquet as pq

        table = arrow_table(columns)
    except ImportError:
        return False
    with atomic_output(path, "wb") as handle:
        pq.write_table(table, handle)
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
