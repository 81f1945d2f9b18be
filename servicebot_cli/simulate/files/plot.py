"""A picture of a run: the world from above with both paths and a LIDAR scan, and the arm.

Drawn on a bare matplotlib Figure (no pyplot state), so it works without a display and the
same run gives the same PNG, SVG or PDF bytes. The live window reuses :func:`draw_world`.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.files import OutputError, atomic_output
from servicebot_cli.simulate.simulator import SimResult
from servicebot_cli.simulate.summary import odometry_in_world

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

_OBSTACLE = {"facecolor": "#b0b0b0", "edgecolor": "#505050", "linewidth": 0.8}


def draw_world(ax: Axes, result: SimResult) -> None:
    """Obstacles (low ones, below the LIDAR, hatched), with equal axes in metres."""
    from matplotlib.patches import Circle, Polygon

    lidar_z = None
    if result.scans is not None and len(result.scans.origin_m):
        lidar_z = float(result.scans.origin_m[0, 2])
    for solid in result.solids:
        low, high = solid.z_range_m
        style = dict(_OBSTACLE)
        if lidar_z is not None and not low <= lidar_z <= high:
            style.update(facecolor="#e8e8e8", hatch="///")
        if solid.kind == "cylinder":
            ax.add_patch(Circle(tuple(solid.center_m[:2]), solid.half_m[0], **style))
        else:
            ax.add_patch(Polygon(solid.floor_corners(), closed=True, **style))
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(True, linewidth=0.3, alpha=0.6)


def robot_outlines(result: SimResult, tick: int) -> list[np.ndarray]:
    """Every collision part seen from above at a tick, each closed, shape (K, 2)."""
    from servicebot_cli.simulate.shape import outlines
    from servicebot_cli.simulate.world.contacts import posed_parts

    truth, body = result.truth, result.body
    posed = posed_parts(body.shape, truth.x_m[tick:tick + 1], truth.y_m[tick:tick + 1],
                        truth.yaw_rad[tick:tick + 1], body.base_height_m,
                        result.arm_positions_rad[tick:tick + 1])
    return outlines(body.shape.parts, posed[0])


def scan_points(result: SimResult, index: int) -> np.ndarray:
    """Finite returns of scan ``index`` in the world frame, shape (M, 2)."""
    scans = result.scans
    assert scans is not None
    ranges = scans.ranges_m[index]
    ok = np.isfinite(ranges)
    bearing = scans.yaw_rad[index] + scans.angles_rad[ok]
    origin = scans.origin_m[index]
    return np.column_stack((origin[0] + ranges[ok] * np.cos(bearing),
                            origin[1] + ranges[ok] * np.sin(bearing)))


def _draw_map(ax: Axes, result: SimResult) -> None:
    draw_world(ax, result)
    truth = result.truth
    ox, oy, _ = odometry_in_world(result)
    ax.plot(truth.x_m, truth.y_m, color="#1f77b4", linewidth=1.6, label="ground truth")
    ax.plot(ox, oy, color="#ff7f0e", linewidth=1.2, linestyle="--", label="wheel odometry")
    if result.scans is not None and len(result.scans.times_s):
        k = len(result.scans.times_s) - 1
        points = scan_points(result, k)
        ax.scatter(points[:, 0], points[:, 1], s=4, color="#d62728", zorder=3,
                   label=f"LIDAR scan at {result.scans.times_s[k]:.1f} s")
    for tick, colour, label in ((0, "#2ca02c", "start"), (-1, "#1f77b4", "end")):
        for i, outline in enumerate(robot_outlines(result, tick % len(truth.x_m))):
            ax.plot(outline[:, 0], outline[:, 1], color=colour, linewidth=0.8,
                    label=label if i == 0 else None)
    for contact in result.contacts:
        ax.plot(contact.x_m, contact.y_m, marker="x", color="black", markersize=9, mew=2)
    if result.contacts:
        ax.plot([], [], marker="x", color="black", linestyle="", label="collision")
    ax.legend(loc="upper right", fontsize=7, framealpha=0.85)
    ax.set_title(f"{result.scenario.name}: {result.scenario.duration_s:g} s, seed {result.seed}")


def _draw_arm(ax: Axes, result: SimResult) -> None:
    times = np.arange(len(result.arm_positions_rad)) * result.truth.dt_s
    for j, name in enumerate(result.body.arm_joints):
        ax.plot(times, result.arm_positions_rad[:, j], linewidth=1.2, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("joint angle [rad]")
    ax.set_title("arm joints")
    ax.grid(True, linewidth=0.3, alpha=0.6)
    ax.legend(loc="best", fontsize=7)


def _draw_drift(ax: Axes, result: SimResult) -> None:
    from servicebot_cli.simulate.world.motion import pose_at

    ox, oy, _ = odometry_in_world(result)
    tx, ty, _ = pose_at(result.truth, result.odometry.times_s)
    ax.plot(result.odometry.times_s, np.hypot(ox - tx, oy - ty), color="#ff7f0e")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("odometry error [m]")
    ax.set_title("odometry drift from ground truth")
    ax.grid(True, linewidth=0.3, alpha=0.6)


def figure(result: SimResult) -> Figure:
    """The run's figure: map on the left, arm angles and odometry drift on the right."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(13, 7), dpi=100, layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.25, 1))
    _draw_map(fig.add_subplot(grid[:, 0]), result)
    _draw_arm(fig.add_subplot(grid[0, 1]), result)
    _draw_drift(fig.add_subplot(grid[1, 1]), result)
    return fig


PLOT_FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}
"""File extension to the format matplotlib writes."""

# Metadata that would change the bytes between two runs of the same seed (dates, versions).
_NO_METADATA = {"png": {"Software": None}, "svg": {"Date": None, "Creator": None},
                "pdf": {"CreationDate": None, "Creator": None, "Producer": None}}


def write_plot(path: str | Path, result: SimResult) -> None:
    """Save the figure as PNG, SVG or PDF (by the extension), atomically.

    Raises:
        OutputError: The extension is none of :data:`PLOT_FORMATS`, or the file cannot be
            written.
    """
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fmt = PLOT_FORMATS.get(Path(path).suffix.lower())
    if fmt is None:
        raise OutputError(f"{path}: a plot is written as {', '.join(PLOT_FORMATS)}; "
                          "name the file with one of these extensions")
    fig = figure(result)
    FigureCanvasAgg(fig)
    # A fixed salt makes SVG element ids, and so the bytes, the same for the same run.
    with matplotlib.rc_context({"svg.hashsalt": "servicebot"}), \
            atomic_output(path, "wb") as handle:
        fig.savefig(handle, format=fmt, metadata=_NO_METADATA[fmt])
