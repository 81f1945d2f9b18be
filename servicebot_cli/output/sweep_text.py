"""What ``sweep`` prints: counts, expectations, grid points and failing runs; timing on stderr."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

import click

from servicebot_cli.common.jsonable import dumps
from servicebot_cli.output.table import format_number, table

if TYPE_CHECKING:
    from servicebot_cli.sweep.session import RunResult, SweepReport

MAX_FAILING_ROWS = 50
"""Failing runs shown in the text table; all of them are in runs.csv and summary.json."""


def _value(value: object) -> str:
    if isinstance(value, float | int) and not isinstance(value, bool):
        return format_number(value)
    return str(value)


def _values(result: RunResult) -> str:
    return ", ".join(f"{name}={_value(v)}" for name, v in result.run.values) or "-"


def sweep_lines(report: SweepReport) -> Iterator[str]:
    """Lines of text for ``report``: what ran, what held, and the runs that failed."""
    points, draws, seeds = report.shape
    yield (f"{report.robot}, scenario {report.scenario}, {report.planned} "
           f"run{'s' * (report.planned != 1)} "
           f"({points} grid point{'s' * (points != 1)} x {draws} draw{'s' * (draws != 1)} "
           f"x {seeds} seed{'s' * (seeds != 1)})")
    resumed = f" ({report.resumed} found done)" if report.resumed else ""
    failed = len(report.failed)
    yield (f"finished {len(report.results)}{resumed}, {len(report.results) - failed} passed, "
           f"{failed} failed")
    if report.expectations:
        yield ""
        yield from table(["expect", "failed runs"],
                         [[text, sum(text in r.failed for r in report.results)]
                          for text in report.expectations])
    if report.failed:
        yield ""
        yield from failing_runs(report.failed)


def failing_runs(failed: Sequence[RunResult]) -> list[str]:
    """The failing runs: index, seed, values and the expectations they failed."""
    rows = [[r.run.index, r.run.seed, _values(r), "; ".join(r.failed)]
            for r in failed[:MAX_FAILING_ROWS]]
    lines = table(["run", "seed", "values", "failed"], rows, max_width=120)
    if len(failed) > MAX_FAILING_ROWS:
        lines.append(f"... and {len(failed) - MAX_FAILING_ROWS} more (runs.csv has them all)")
    return lines


def failure_line(report: SweepReport, fmt: str = "text") -> str:
    """The stderr line for a sweep whose answer is no (the text report's table lists them)."""
    where = "(table above)" if fmt == "text" else "(failed_runs in the report above)"
    return f"{len(report.failed)} of {len(report.results)} runs failed an expectation {where}"


def speed_line(report: SweepReport) -> str:
    """``ran 48 runs in 12.3 s on 2 local workers``."""
    ran = len(report.results) - report.resumed
    return f"ran {ran} run{'s' * (ran != 1)} in {report.wall_s:.1f} s on {report.workers}"


def show_sweep(report: SweepReport, fmt: str) -> None:
    """The report on stdout as text or as summary.json's JSON, then the speed line on stderr."""
    if fmt == "json":
        from servicebot_cli.sweep.tables import summary

        click.echo(dumps(summary(report)), nl=False)
    else:
        for line in sweep_lines(report):
            click.echo(line)
    click.echo(speed_line(report), err=True)
