"""``ik`` results for people (text) and programs (JSON). Rendering only.

JSON (documented in README.md, stable)::

    {"robot": "...", "frame": "...", "relative_to": "base_link", "success": true,
     "target": {"position_m": [x, y, z], "rpy_rad": [r, p, y] | null,
                "orientation_axes": ["pitch", ...]},
     "angle_unit": "rad", "joints": {"name": value, ...},
     "base": {"x_m": ..., "y_m": ..., "yaw_rad": ...} | null,
     "position_error_m": ..., "orientation_error_rad": ... | null,
     "iterations": n, "attempts": n, "solutions": n, "solve_time_s": ..., "hint": null | "..."}
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from servicebot_cli.output.table import format_number, table


def _headline(report: Mapping[str, Any]) -> str:
    axes = report["target"]["orientation_axes"]
    kind = "position only" if not axes else "full pose" if len(axes) == 3 else \
        "position and " + ", ".join(axes)
    attempts = report["attempts"]
    effort = (f"{report['iterations']} iterations, {attempts} attempt{'s' if attempts != 1 else ''}"
              f", {report['solve_time_s'] * 1e3:.3g} ms")
    verdict = "reached" if report["success"] else "NOT reached (best found below)"
    return f"{report['frame']} {verdict}: {kind}; {effort}"


def ik_text(report: Mapping[str, Any], units: Sequence[str], lower: Sequence[float | None],
            upper: Sequence[float | None]) -> Iterator[str]:
    """The ``ik`` answer as text: a headline, the joints with their limits, the errors.

    Args:
        report: The JSON report.
        units: Unit of each joint's value, in ``report["joints"]`` order.
        lower: Lower limit of each joint in its unit (None: continuous).
        upper: Upper limit of each joint in its unit (None: continuous).
    """
    yield _headline(report)
    rows = [[name, value, unit, lo, hi] for (name, value), unit, lo, hi in
            zip(report["joints"].items(), units, lower, upper, strict=True)]
    yield from table(["joint", "value", "unit", "lower", "upper"], rows)
    base = report.get("base")
    if base:
        yaw_key = next(k for k in base if k.startswith("yaw_"))
        yield (f"base: x {format_number(base['x_m'])} m, y {format_number(base['y_m'])} m, "
               f"yaw {format_number(base[yaw_key])} {yaw_key[4:]}")
    yield f"position error     {format_number(report['position_error_m'], 3)} m"
    orientation = report["orientation_error_rad"]
    shown = "- (position only)" if orientation is None else f"{format_number(orientation, 3)} rad"
    yield f"orientation error  {shown}"
