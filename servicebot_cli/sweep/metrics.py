"""A run's summary as flat metrics, and statistics of each metric over a group of runs.

Every number of ``simulate``'s summary becomes one column, named by its dotted path as
``--expect`` names it (``odometry_drift.final_position_m``); ``collisions`` is their count
and ``end_effector.position_m`` gives ``end_effector.position_m[0]`` to ``[2]``. A metric
keeps its type: counts are ``int``, measures ``float``. The fixed fields (robot, scenario,
seed, duration, message counts) are not metrics.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Mapping, Sequence
from typing import Any

NOT_METRICS = ("robot", "scenario", "seed", "duration_s", "messages", "closest_obstacle",
               "closest_link", "controller")
COUNTED = ("collisions", "self_collisions")  # lists of events: a metric by their number
STATISTICS = ("mean", "std", "min", "median", "p95", "max")


def flat_metrics(summary: Mapping[str, Any]) -> dict[str, float]:
    """The summary's numbers by dotted path, in the summary's order (ints and bools kept)."""
    metrics: dict[str, float] = {}
    for key, value in summary.items():
        if key not in NOT_METRICS:
            _flatten(key, value, metrics)
    return metrics


def _flatten(name: str, value: Any, out: dict[str, float]) -> None:
    if name in COUNTED and isinstance(value, list):
        out[name] = len(value)
    elif isinstance(value, int | float):  # bool is an int
        out[name] = value
    elif isinstance(value, Mapping):
        for key, item in value.items():
            _flatten(f"{name}.{key}", item, out)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            _flatten(f"{name}[{i}]", item, out)


def describe(values: Sequence[float]) -> dict[str, float | None]:
    """Mean, standard deviation (n - 1; 0 for one value), min, median, 95th percentile, max.

    Missing values (NaN, e.g. no odometry) are left out; none left gives ``None`` for each.
    An infinite value (no obstacle in the world: ``min_obstacle_distance_m``) makes the
    mean infinite and the standard deviation NaN (``null`` in JSON).
    """
    present = sorted(v for v in values if not math.isnan(v))
    if not present:
        return dict.fromkeys(STATISTICS)
    return {
        "mean": statistics.fmean(present),
        "std": _std(present),
        "min": present[0],
        "median": statistics.median(present),
        "p95": _percentile(present, 0.95),
        "max": present[-1],
    }


def _std(values: Sequence[float]) -> float:
    """Sample standard deviation (n - 1); 0 for one value, NaN with an infinite one."""
    if len(values) == 1:
        return 0.0
    if not all(math.isfinite(v) for v in values):
        return math.nan
    return statistics.stdev(values)


def _percentile(ordered: Sequence[float], q: float) -> float:
    """Linear interpolation between closest ranks (numpy's default)."""
    position = q * (len(ordered) - 1)
    low = math.floor(position)
    high = min(low + 1, len(ordered) - 1)
    if position == low or ordered[high] == ordered[low]:  # also inf == inf: no inf - inf
        return ordered[low]
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)
