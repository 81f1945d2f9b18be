"""The live window: the run played back in a matplotlib window, at real time or faster.

Needs a display. :func:`display_problem` says in one line why there is none (so the command
can ask for ``--headless``) before any work is done. The window plays a :class:`LiveTrack`,
gathered a piece of the run at a time as the picture's :class:`~.plot.Track` is (a
:class:`LiveWriter` among the outputs): the paths and arm angles thinned to at most
:data:`~.plot.MAX_POINTS` points, the scans to at most :data:`MAX_SCANS`, so what it keeps
does not grow with the simulated duration.
"""

from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.files.plot import Track, draw_world, robot_outlines, scan_points
from servicebot_cli.simulate.simulator import SimResult

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

FloatArray = npt.NDArray[np.float64]
MAX_SCANS = 2_000
"""Scans kept at most: the first of each of this many equal stretches of the run."""


def display_problem(environ: dict[str, str] | None = None, platform: str = sys.platform) -> str:
    """Why no window can open here, or "" when one can."""
    env = os.environ if environ is None else environ
    if platform.startswith(("win", "darwin")):
        return ""
    if not env.get("DISPLAY") and not env.get("WAYLAND_DISPLAY"):
        return "no display to open the live window (DISPLAY is not set)"
    return ""


class LiveTrack:
    """What the live window plays, gathered a piece of the run at a time, thinned.

    Args:
        first: The run's first piece (or the whole run).
    """

    def __init__(self, first: SimResult) -> None:
        from servicebot_cli.simulate.sensors.sample import sample_count

        scenario = first.scenario
        self.track = Track(first, sample_count(scenario.controller.publish_rate_hz,
                                               scenario.duration_s))
        self.name, self.duration_s = scenario.name, scenario.duration_s
        self.scan_spacing_s = scenario.duration_s / MAX_SCANS
        self.scan_stretch = -1  # the stretch of the run the last kept scan began
        self.scan_times_s: list[float] = []
        self.scans: list[FloatArray] = []  # the kept scans' returns in the world, (M, 2) each

    @classmethod
    def of_run(cls, result: SimResult) -> LiveTrack:
        """The track of a run simulated in one piece."""
        track = cls(result)
        track.add(result)
        return track

    def add(self, piece: SimResult) -> None:
        """Keep what the window needs from the next piece of the run."""
        self.track.add(piece)
        if not piece.scans:
            return
        scans = piece.scans[0]  # the LIDAR's: the ray sensor with the most rays
        for i, time_s in enumerate(scans.times_s.tolist()):
            stretch = min(math.floor(time_s / self.scan_spacing_s), MAX_SCANS - 1)
            if stretch > self.scan_stretch:
                self.scan_stretch = stretch
                self.scan_times_s.append(time_s)
                self.scans.append(scan_points(scans, i))

    def stored_points(self) -> int:
        """Points kept: path, arm and odometry rows, and scan returns."""
        track = self.track
        return (sum(len(rows) for rows in track.truth) + sum(len(rows) for rows in track.arm)
                + sum(len(rows) for rows in track.odometry) + sum(len(s) for s in self.scans))


class LiveWriter:
    """The live window among a run's outputs: its track gathered as the run goes."""

    def __init__(self, first: SimResult) -> None:
        self.track = LiveTrack(first)

    def add(self, piece: SimResult) -> None:
        """Keep what the window needs from the next piece."""
        self.track.add(piece)

    def finish(self, summary: object) -> None:
        """Nothing is written: :func:`show` plays :attr:`track` once the run is done."""


def show(run: SimResult | LiveTrack, *, speed: float = 1.0,
         frame_rate_hz: float = 20.0) -> None:
    """Play a run back in a window; returns when the window is closed.

    ``run`` is the track a :class:`LiveWriter` gathered, or a run simulated in one piece.
    """
    import matplotlib

    from servicebot_cli.common.errors import ServicebotError

    try:
        matplotlib.use("TkAgg" if "MPLBACKEND" not in os.environ else os.environ["MPLBACKEND"])
        import matplotlib.pyplot as plt
        from matplotlib.animation import FuncAnimation
    except (ImportError, ValueError) as exc:
        raise ServicebotError(f"cannot open the live window ({exc}); install python3-tk, or "
                              "use --headless with --plot FILE.png") from None
    live = run if isinstance(run, LiveTrack) else LiveTrack.of_run(run)
    fig, ax = plt.subplots(figsize=(8, 8))
    series = _Series.of(live)
    _frame_world(ax, live, series)
    artists = _artists(ax)
    step_s = speed / frame_rate_hz
    count = math.ceil(live.duration_s / step_s)

    def update(t: float) -> list[Artist]:
        _update(artists, live, series, t)
        return [artists.truth, artists.odom, artists.body, artists.scan, artists.clock]

    animation = FuncAnimation(fig, update, frames=(i * step_s for i in range(count)),
                              save_count=0, interval=1000 / frame_rate_hz, blit=False,
                              repeat=False, cache_frame_data=False)
    plt.show()
    del animation


@dataclass(frozen=True)
class _Artists:
    """What each frame of the animation redraws."""

    truth: Line2D
    odom: Line2D
    body: Line2D
    scan: Line2D
    clock: Text


def _artists(ax: Axes) -> _Artists:
    return _Artists(
        truth=ax.plot([], [], color="#1f77b4", label="ground truth")[0],
        odom=ax.plot([], [], color="#ff7f0e", linestyle="--", label="wheel odometry")[0],
        body=ax.plot([], [], color="#1f77b4")[0],
        scan=ax.plot([], [], ".", color="#d62728", markersize=3, label="LIDAR")[0],
        clock=ax.set_title(""),
    )


@dataclass(frozen=True)
class _Series:
    """The track's kept rows, joined once for the whole playback."""

    times_s: FloatArray  # kept tick boundaries
    truth: FloatArray  # x, y, yaw per kept boundary
    arm: FloatArray
    odometry: FloatArray  # time, x, y (world), drift per kept sample

    @classmethod
    def of(cls, live: LiveTrack) -> _Series:
        return cls(*live.track.series())


def _frame_world(ax: Axes, live: LiveTrack, series: _Series) -> None:
    """The obstacles, and axes that hold both paths with a margin."""
    draw_world(ax, live.track.solids, live.track.lidar_z)
    xs = np.concatenate((series.truth[:, 0], series.odometry[:, 1]))
    ys = np.concatenate((series.truth[:, 1], series.odometry[:, 2]))
    margin = 0.5
    ax.set_xlim(xs.min() - margin, xs.max() + margin)
    ax.set_ylim(ys.min() - margin, ys.max() + margin)


def _update(artists: _Artists, live: LiveTrack, series: _Series, t: float) -> None:
    """Draw the run at time ``t`` [s]: as far as the last kept boundary at or before it."""
    k = max(int(np.searchsorted(series.times_s, t + 1e-9, side="right")) - 1, 0)
    artists.truth.set_data(series.truth[:k + 1, 0], series.truth[:k + 1, 1])
    j = int(np.searchsorted(series.odometry[:, 0], t + 1e-9, side="right"))
    artists.odom.set_data(series.odometry[:j, 1], series.odometry[:j, 2])
    # the parts' outlines as one line, separated by NaN breaks
    pose = series.truth[k]
    parts = robot_outlines(live.track.body, (pose[0], pose[1], pose[2]), series.arm[k])
    outline = np.vstack([np.vstack((p, [[np.nan, np.nan]])) for p in parts])
    artists.body.set_data(outline[:, 0], outline[:, 1])
    s = int(np.searchsorted(live.scan_times_s, t + 1e-9, side="right")) - 1
    if s >= 0:
        artists.scan.set_data(live.scans[s][:, 0], live.scans[s][:, 1])
    artists.clock.set_text(f"{live.name}  t = {t:6.1f} s")
