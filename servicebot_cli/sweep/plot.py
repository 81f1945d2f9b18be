"""A picture of a sweep: each metric against each swept value, every run a dot.

One row per metric (the headline ones, then every field an expectation names), one column
per swept field (grid and sample; the seed when nothing is swept). Runs at one value spread
over seeds and draws; for a grid field the median at each value is joined by a line, and an
expectation's bound is drawn as a dashed line. Drawn on a bare Figure, saved atomically.
"""

from __future__ import annotations

import json
import statistics
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.files import OutputError, atomic_output

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from servicebot_cli.sweep.session import RunResult, SweepReport

HEADLINE = ("distance_m", "odometry_drift.final_position_m", "odometry_drift.final_yaw_rad",
            "min_obstacle_distance_m", "collisions")
FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}
_NO_METADATA: dict[str, dict[str, None]] = {
    "png": {"Software": None}, "svg": {"Date": None, "Creator": None},
    "pdf": {"CreationDate": None, "Creator": None, "Producer": None}}


def plotted_metrics(report: SweepReport) -> list[str]:
    """The headline metrics, then those the expectations name, without repeats."""
    from servicebot_cli.simulate.expectations import parse_expectation

    named = [_dotted(parse_expectation(text).field) for text in report.expectations]
    present = {name for r in report.results for name in r.metrics}
    return [m for m in dict.fromkeys((*HEADLINE, *named)) if m in present]


def _dotted(path: Sequence[str | int]) -> str:
    from servicebot_cli.simulate.scenario.located import dotted

    return dotted(tuple(path))


def swept_fields(report: SweepReport) -> list[str]:
    """Fields that take more than one value across the runs; ``seed`` when none does."""
    names = list(dict.fromkeys(name for r in report.results for name, _ in r.run.values))
    varying = [n for n in names
               if len({repr(dict(r.run.values).get(n)) for r in report.results}) > 1]
    return varying or ["seed"]


def write_plot(report: SweepReport, path: str | Path) -> None:
    """Save the figure as PNG, SVG or PDF (by the extension), atomically.

    Raises:
        OutputError: An unknown extension, or the file cannot be written.
    """
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fmt = FORMATS.get(Path(path).suffix.lower())
    if fmt is None:
        raise OutputError(f"{path}: a plot is written as {', '.join(FORMATS)}; name the file "
                          "with one of these extensions")
    metrics, fields = plotted_metrics(report), swept_fields(report)
    fig = Figure(figsize=(3.2 * len(fields) + 0.8, 2.3 * max(len(metrics), 1) + 0.6),
                 layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(max(len(metrics), 1), len(fields), squeeze=False)
    bounds = _bounds(report)
    for row, metric in enumerate(metrics):
        for column, name in enumerate(fields):
            _panel(axes[row][column], report.results, name, metric, bounds.get(metric, []))
            if column == 0:
                axes[row][column].set_ylabel(metric, fontsize=8)
            if row == len(metrics) - 1:
                axes[row][column].set_xlabel(name, fontsize=8)
    fig.suptitle(f"{report.robot}, scenario {report.scenario}: {len(report.results)} runs",
                 fontsize=10)
    with matplotlib.rc_context({"svg.hashsalt": "servicebot"}), \
            atomic_output(path, "wb") as handle:
        fig.savefig(handle, format=fmt, metadata=_NO_METADATA[fmt], dpi=100)


def _bounds(report: SweepReport) -> dict[str, list[float]]:
    from servicebot_cli.simulate.expectations import parse_expectation

    bounds: dict[str, list[float]] = {}
    for text in report.expectations:
        expectation = parse_expectation(text)
        bounds.setdefault(_dotted(expectation.field), []).append(expectation.number)
    return bounds


def _x(result: RunResult, name: str) -> Any:
    return result.run.seed if name == "seed" else dict(result.run.values).get(name)


def _label(value: Any) -> str:
    """A category as text: strings as they are, anything else as compact JSON."""
    return value if isinstance(value, str) else json.dumps(value, separators=(",", ":"))


def _short(label: str, width: int = 18) -> str:
    """At most ``width`` characters, so long values (a world, a list) do not overlap."""
    return label if len(label) <= width else label[:width - 1] + "\u2026"


def _panel(ax: Axes, results: Sequence[RunResult], name: str, metric: str,
           bounds: Sequence[float]) -> None:
    xs = [_x(r, name) for r in results]
    ys = [r.metrics.get(metric, float("nan")) for r in results]
    numeric = all(isinstance(x, int | float) and not isinstance(x, bool) for x in xs)
    if not numeric:  # categories (a saturation mode, a list) at 0, 1, 2, ...
        labels = list(dict.fromkeys(_label(x) for x in xs))
        xs = [labels.index(_label(x)) for x in xs]
        ax.set_xticks(range(len(labels)), [_short(label) for label in labels], fontsize=7)
    colors = ["#c0392b" if r.failed else "#2c7fb8" for r in results]
    ax.scatter(xs, ys, s=10, c=colors, alpha=0.6, linewidths=0)
    groups: dict[float, list[float]] = {}
    for x, y in zip(xs, ys, strict=True):
        groups.setdefault(float(x), []).append(y)
    if len(groups) < len(results):  # repeated values: a grid field, spread over seeds
        centres = sorted(groups)
        ax.plot(centres, [statistics.median(groups[c]) for c in centres], color="#333333",
                linewidth=1)
    for bound in bounds:
        ax.axhline(bound, color="#c0392b", linestyle="--", linewidth=0.8)
    ax.ticklabel_format(axis="y", useOffset=False)
    ax.tick_params(labelsize=7)
    ax.grid(alpha=0.3)
