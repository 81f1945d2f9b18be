"""A picture of a run: the world from above with both paths and the last scans, and the arm.

Drawn on a bare matplotlib Figure (no pyplot state), so it works without a display and the
same run gives the same PNG, SVG or PDF bytes. What it draws is gathered as the run goes
(:class:`Track`), long series thinned to :data:`MAX_POINTS`. The live window reuses
:func:`draw_world`, :func:`robot_outlines` and :func:`scan_points`.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.files import OutputError, atomic_output
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.sensors.lidar import Scans
from servicebot_cli.simulate.simulator import SimResult
from servicebot_cli.simulate.summary import odometry_drift, odometry_in_world
from servicebot_cli.simulate.world.solids import Solid

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

FloatArray = npt.NDArray[np.float64]
_OBSTACLE = {"facecolor": "#b0b0b0", "edgecolor": "#505050", "linewidth": 0.8}


MAX_POINTS = 20_000
"""Points per line at most; a longer run's lines keep every k-th point (and the last)."""


class Track:
    """What the figure draws, gathered a piece of the run at a time, long series thinned.

    Paths, arm angles and the drift keep evenly spaced points (the stride depends only on the
    run's length), so the picture is the same however the run was split into pieces.
    """

    def __init__(self, run: SimResult, odometry_count: int) -> None:
        self.body, self.scenario, self.seed, self.solids = (run.body, run.scenario, run.seed,
                                                            run.solids)
        self.dt_s, self.ticks = run.truth.dt_s, run.run_ticks
        self.tick_stride = math.ceil((self.ticks + 1) / MAX_POINTS)
        self.odometry_stride = max(1, math.ceil(odometry_count / MAX_POINTS))
        self.odometry_count = odometry_count
        self.seen = 0  # odometry samples so far
        self.ticks_kept: list[npt.NDArray[np.int64]] = []
        self.truth: list[FloatArray] = []  # x, y, yaw per kept boundary
        self.arm: list[FloatArray] = []
        self.odometry: list[FloatArray] = []  # time, x, y (world) and drift per kept sample
        self.contacts: list[tuple[float, float]] = []
        self.lidar_z: float | None = None
        self.scan: FloatArray | None = None  # the first ray sensor's last scan, world (M, 2)
        self.scan_time_s = 0.0
        self.scan_topic = ""  # that ray sensor's topic: a TurtleBot 4 without one, an IR's
        self.other_scans: dict[int, FloatArray] = {}  # the other ray sensors' last scans
        self.start: tuple[float, float, float, FloatArray] | None = None
        self.end: tuple[float, float, float, FloatArray] | None = None

    def add(self, piece: SimResult) -> None:
        """Keep what the figure needs from the next piece of the run."""
        truth, first = piece.truth, piece.first_tick
        ticks = np.arange(first, first + len(truth.x_m))
        keep = ((ticks % self.tick_stride == 0) | (ticks == self.ticks)) & (
            (ticks > first) | piece.first)
        self.ticks_kept.append(ticks[keep])
        self.truth.append(np.column_stack((truth.x_m, truth.y_m, truth.yaw_rad))[keep])
        self.arm.append(piece.arm_positions_rad[keep])
        odom = piece.odometry
        if len(odom.times_s):
            index = self.seen + np.arange(len(odom.times_s))
            kept = (index % self.odometry_stride == 0) | (index == self.odometry_count - 1)
            ox, oy, _ = odometry_in_world(piece)
            drift, _ = odometry_drift(piece)
            self.odometry.append(np.column_stack((odom.times_s, ox, oy, drift))[kept])
            self.seen += len(odom.times_s)
        self.contacts += [(c.x_m, c.y_m) for c in piece.contacts]
        self._add_scans(piece.scans)
        if piece.first:
            self.start = (truth.x_m[0], truth.y_m[0], truth.yaw_rad[0],
                          piece.arm_positions_rad[0])
        self.end = (truth.x_m[-1], truth.y_m[-1], truth.yaw_rad[-1], piece.arm_positions_rad[-1])

    def _add_scans(self, scans: tuple[Scans, ...]) -> None:
        """Keep each ray sensor's last scan: the LIDAR's (the first) and the others'."""
        for index, sensor in enumerate(scans):
            if not len(sensor.times_s):
                continue
            points = scan_points(sensor, len(sensor.times_s) - 1)
            if index:
                self.other_scans[index] = points
                continue
            self.lidar_z = float(sensor.origin_m[0, 2]) if self.lidar_z is None else self.lidar_z
            self.scan, self.scan_time_s = points, float(sensor.times_s[-1])
            self.scan_topic = sensor.spec.topic or ""

    def series(self) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """Kept boundaries' times [s], (x, y, yaw) of the truth, arm angles; odometry rows."""
        ticks = np.concatenate(self.ticks_kept)
        width = len(self.body.arm_joints)
        return (np.asarray(ticks * self.dt_s, dtype=np.float64), np.vstack(self.truth),
                np.vstack(self.arm) if self.arm else np.zeros((0, width)),
                np.vstack(self.odometry) if self.odometry else np.zeros((0, 4)))


def draw_world(ax: Axes, solids: Sequence[Solid], lidar_z: float | None) -> None:
    """Obstacles (those the LIDAR at ``lidar_z`` does not see, hatched), equal axes in metres."""
    from matplotlib.patches import Circle, Polygon

    for solid in solids:
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


def robot_outlines(body: SimRobot, pose: tuple[float, float, float],
                   arm_q: FloatArray) -> list[FloatArray]:
    """Every collision part seen from above at a base pose and arm, each closed, (K, 2)."""
    from servicebot_cli.simulate.shape import outlines
    from servicebot_cli.simulate.world.contacts import posed_parts

    x, y, yaw = pose
    posed = posed_parts(body.shape, np.array([x]), np.array([y]), np.array([yaw]),
                        body.base_height_m, arm_q[None])
    return outlines(body.shape.parts, posed[0])


def scan_points(scans: Scans, index: int) -> FloatArray:
    """Finite returns of scan ``index`` in the world frame, shape (M, 2)."""
    ranges = scans.ranges_m[index]
    ok = np.isfinite(ranges)
    bearing = scans.yaw_rad[index] + scans.angles_rad[ok]
    origin = scans.origin_m[index]
    return np.column_stack((origin[0] + ranges[ok] * np.cos(bearing),
                            origin[1] + ranges[ok] * np.sin(bearing)))


def _draw_map(ax: Axes, track: Track) -> None:
    draw_world(ax, track.solids, track.lidar_z)
    _, truth, _, odometry = track.series()
    ax.plot(truth[:, 0], truth[:, 1], color="#1f77b4", linewidth=1.6, label="ground truth")
    ax.plot(odometry[:, 1], odometry[:, 2], color="#ff7f0e", linewidth=1.2, linestyle="--",
            label="wheel odometry")
    if track.scan is not None:
        ax.scatter(track.scan[:, 0], track.scan[:, 1], s=4, color="#d62728", zorder=3,
                   label=f"scan on {track.scan_topic or 'its topic'} at {track.scan_time_s:.1f} s")
    if track.other_scans:
        others = np.vstack(list(track.other_scans.values()))
        ax.scatter(others[:, 0], others[:, 1], s=9, marker="^", color="#9467bd", zorder=3,
                   label="other ray sensors' last scans")
    for pose, colour, label in ((track.start, "#2ca02c", "start"),
                                (track.end, "#1f77b4", "end")):
        assert pose is not None
        for i, outline in enumerate(robot_outlines(track.body, pose[:3], pose[3])):
            ax.plot(outline[:, 0], outline[:, 1], color=colour, linewidth=0.8,
                    label=label if i == 0 else None)
    for x, y in track.contacts:
        ax.plot(x, y, marker="x", color="black", markersize=9, mew=2)
    if track.contacts:
        ax.plot([], [], marker="x", color="black", linestyle="", label="collision")
    ax.legend(loc="upper right", fontsize=7, framealpha=0.85)
    ax.set_title(f"{track.scenario.name}: {track.scenario.duration_s:g} s, seed {track.seed}")


def _draw_arm(ax: Axes, track: Track) -> None:
    times, _, arm, _ = track.series()
    names = track.body.arm_joints
    for j, name in enumerate(names):  # a legend of TIAGo's 44 joints would cover the figure
        ax.plot(times, arm[:, j], linewidth=1.2, label=name if j < _LEGEND_MOST else None)
    if len(names) > _LEGEND_MOST:
        ax.plot([], [], linestyle="", label=f"and {len(names) - _LEGEND_MOST} more")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("joint angle [rad]")
    ax.set_title("arm joints")
    ax.grid(True, linewidth=0.3, alpha=0.6)
    if not track.body.arm_joints:  # an empty legend is a matplotlib warning on stderr
        ax.text(0.5, 0.5, "no arm joints", ha="center", va="center", transform=ax.transAxes)
        return
    ax.legend(loc="best", fontsize=7)


_LEGEND_MOST = 8  # arm joints named in the legend


def _draw_drift(ax: Axes, track: Track) -> None:
    odometry = track.series()[3]
    ax.plot(odometry[:, 0], odometry[:, 3], color="#ff7f0e")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("odometry error [m]")
    ax.set_title("odometry drift from ground truth")
    ax.grid(True, linewidth=0.3, alpha=0.6)


def figure(track: Track) -> Figure:
    """The run's figure: map on the left, arm angles and odometry drift on the right."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(13, 7), dpi=100, layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.25, 1))
    _draw_map(fig.add_subplot(grid[:, 0]), track)
    _draw_arm(fig.add_subplot(grid[0, 1]), track)
    _draw_drift(fig.add_subplot(grid[1, 1]), track)
    return fig


PLOT_FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}
"""File extension to the format matplotlib writes."""

# Metadata that would change the bytes between two runs of the same seed (dates, versions).
_NO_METADATA = {"png": {"Software": None}, "svg": {"Date": None, "Creator": None},
                "pdf": {"CreationDate": None, "Creator": None, "Producer": None}}


class PlotWriter:
    """Gathers the figure's data as the run goes and saves the picture at the end."""

    def __init__(self, path: str | Path, first: SimResult) -> None:
        from servicebot_cli.simulate.sensors.sample import sample_count

        controller, duration = first.scenario.controller, first.scenario.duration_s
        self.path = path
        self.track = Track(first, sample_count(controller.publish_rate_hz, duration))

    def add(self, piece: SimResult) -> None:
        """Keep what the figure needs from the next piece."""
        self.track.add(piece)

    def finish(self, summary: object) -> None:
        """Draw and save the picture (it needs no summary)."""
        write_plot(self.path, self.track)


def write_plot(path: str | Path, track: Track) -> None:
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
    fig = figure(track)
    FigureCanvasAgg(fig)
    # A fixed salt makes SVG element ids, and so the bytes, the same for the same run.
    with matplotlib.rc_context({"svg.hashsalt": "servicebot"}), warnings.catch_warnings(), \
            atomic_output(path, "wb") as handle:
        # a layout that does not fit is still drawn: matplotlib's warning is for its users
        warnings.filterwarnings("ignore", message="constrained_layout not applied")
        fig.savefig(handle, format=fmt, metadata=_NO_METADATA[fmt])
