"""What ``simulate`` prints: the summary on stdout (text or JSON), the speed line on stderr."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import click

from servicebot_cli.common.jsonable import dumps
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.simulate.session import SimulateReport
    from servicebot_cli.simulate.summary import Pose, Summary


def _pose(pose: Pose | None) -> str:
    if pose is None:
        return "-"
    return (f"x {format_number(pose['x_m'])} m, y {format_number(pose['y_m'])} m, "
            f"yaw {format_number(pose['yaw_rad'])} rad")


def summary_lines(summary: Summary) -> Iterator[str]:
    """Lines of text for ``summary`` (see :func:`servicebot_cli.simulate.summary.summarize`)."""
    drift = summary["odometry_drift"]
    yield (f"{summary['robot']}, scenario {summary['scenario']}, "
           f"{format_number(summary['duration_s'])} s, seed {summary['seed']}")
    yield f"distance          {format_number(summary['distance_m'])} m"
    yield f"final pose        {_pose(summary['final_pose'])}"
    said = _pose(summary["odometry_final_pose"])
    yield f"odometry says     {said}" if summary["odometry_published_on"] else \
        f"wheel odometry    {said} (no controller publishes it)"
    yield (f"odometry drift    {format_number(drift['final_position_m'])} m, "
           f"{format_number(drift['final_yaw_rad'])} rad at the end "
           f"(max {format_number(drift['max_position_m'])} m)")
    closest = summary["min_obstacle_distance_m"]
    near = (f" ({summary['closest_obstacle']}, {summary['closest_link']})"
            if summary["closest_obstacle"] else "")
    yield f"closest obstacle  {format_number(closest)} m{near}"
    contacts = summary["collisions"]
    yield f"collisions        {len(contacts)}" + "".join(
        f"; {c['link']} on {c['obstacle']} at {format_number(c['time_s'])} s"
        for c in contacts[:3]) + (", ..." if len(contacts) > 3 else "")
    own = summary["self_collisions"]
    yield f"self collisions   {len(own)}" + "".join(
        f"; {c['first']} on {c['second']} at {format_number(c['time_s'])} s"
        for c in own[:3]) + (", ..." if len(own) > 3 else "")
    messages = ", ".join(f"{topic} {count}" for topic, count in summary["messages"].items())
    yield f"messages          {messages}"


def speed_line(report: SimulateReport) -> str:
    """``simulated 180 s in 0.42 s (real-time factor 429)``."""
    return (f"simulated {report.summary['duration_s']:g} s in {report.wall_s:.2f} s "
            f"(real-time factor {report.real_time_factor:.0f})")


def show_simulation(report: SimulateReport, fmt: str) -> None:
    """The summary on stdout as text or JSON, then the speed line on stderr."""
    if fmt == "json":
        click.echo(dumps(report.summary), nl=False)
    else:
        for line in summary_lines(report.summary):
            click.echo(line)
    click.echo(speed_line(report), err=True)


def unmet_line(report: SimulateReport) -> str:
    """One line naming each expectation the run did not meet, with the value it had."""
    parts = [f"{expectation.text} (" + (expectation.why_no_value(report.summary) if value is None
                                        else f"is {format_number(value)}") + ")"
             for expectation, value in report.unmet]
    return f"{len(parts)} of the run's expectations not met: " + "; ".join(parts)
