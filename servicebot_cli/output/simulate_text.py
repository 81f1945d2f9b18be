"""The summary as a few lines of text for people."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from servicebot_cli.output.table import format_number


def _pose(pose: dict[str, float] | None) -> str:
    if pose is None:
        return "-"
    return (f"x {format_number(pose['x_m'])} m, y {format_number(pose['y_m'])} m, "
            f"yaw {format_number(pose['yaw_rad'])} rad")


def summary_lines(summary: dict[str, Any]) -> Iterator[str]:
    """Lines of text for ``summary`` (see :func:`servicebot_cli.simulate.summary.summarize`)."""
    drift = summary["odometry_drift"]
    yield (f"{summary['robot']}, scenario {summary['scenario']}, "
           f"{format_number(summary['duration_s'])} s, seed {summary['seed']}")
    yield f"distance          {format_number(summary['distance_m'])} m"
    yield f"final pose        {_pose(summary['final_pose'])}"
    yield f"odometry says     {_pose(summary['odometry_final_pose'])}"
    yield (f"odometry drift    {format_number(drift['final_position_m'])} m, "
           f"{format_number(drift['final_yaw_rad'])} rad at the end "
           f"(max {format_number(drift['max_position_m'])} m)")
    closest = summary["min_obstacle_distance_m"]
    near = f" ({summary['closest_obstacle']})" if summary.get("closest_obstacle") else ""
    yield f"closest obstacle  {format_number(closest) if closest is not None else '-'} m{near}"
    contacts = summary["collisions"]
    yield f"collisions        {len(contacts)}" + "".join(
        f"; {c['obstacle']} at {format_number(c['time_s'])} s" for c in contacts[:3]) + (
        ", ..." if len(contacts) > 3 else "")
    messages = ", ".join(f"{topic} {count}" for topic, count in summary["messages"].items())
    yield f"messages          {messages}"
