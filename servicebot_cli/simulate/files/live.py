"""The live window: the run played back in a matplotlib window, at real time or faster.

Needs a display. :func:`display_problem` says in one line why there is none (so the command
can ask for ``--headless``) before any work is done. The window plays a run simulated in one
piece (:func:`~servicebot_cli.simulate.simulator.run`): every tick is kept for it.
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.files.plot import draw_world, robot_outlines, scan_points
from servicebot_cli.simulate.simulator import SimResult
from servicebot_cli.simulate.summary import odometry_in_world

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

FloatArray = npt.NDArray[np.float64]


def display_problem(environ: dict[str, str] | None = None, platform: str = sys.platform) -> str:
    """Why no window can open here, or "" when one can."""
    env = os.environ if environ is None else environ
    if platform.startswith(("win", "darwin")):
        return ""
    if not env.get("DISPLAY") and not env.get("WAYLAND_DISPLAY"):
        return "no display to open the live window (DISPLAY is not set)"
    return ""


def show(result: SimResult, *, speed: float = 1.0, frame_rate_hz: float = 20.0) -> None:
    """Play ``result`` back in a window; returns when the window is closed."""
    import matplotlib

    from servicebot_cli.common.errors import ServicebotError

    try:
        matplotlib.use("TkAgg" if "MPLBACKEND" not in os.environ else os.environ["MPLBACKEND"])
        import matplotlib.pyplot as plt
        from matplotlib.animation import FuncAnimation
    except (ImportError, ValueError) as exc:
        raise ServicebotError(f"cannot open the live window ({exc}); install python3-tk, or "
                              "use --headless with --plot FILE.png") from None
    fig, ax = plt.subplots(figsize=(8, 8))
    scans = result.scans
    draw_world(ax, result.solids,
               float(scans.origin_m[0, 2]) if scans is not None and len(scans.times_s) else None)
    truth = result.truth
    ox, oy, _ = odometry_in_world(result)
    margin = 0.5
    ax.set_xlim(min(truth.x_m.min(), ox.min()) - margin, max(truth.x_m.max(), ox.max()) + margin)
    ax.set_ylim(min(truth.y_m.min(), oy.min()) - margin, max(truth.y_m.max(), oy.max()) + margin)
    artists = _artists(ax)
    frames = np.arange(0.0, result.scenario.duration_s, speed / frame_rate_hz)

    def update(t: float) -> list[Artist]:
        _update(artists, result, t, ox, oy)
        return [artists.truth, artists.odom, artists.body, artists.scan, artists.clock]

    animation = FuncAnimation(fig, update, frames=frames, interval=1000 / frame_rate_hz,
                              blit=False, repeat=False)
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


def _update(artists: _Artists, result: SimResult, t: float, ox: FloatArray,
            oy: FloatArray) -> None:
    truth = result.truth
    k = min(int(t / truth.dt_s), len(truth.x_m) - 1)
    artists.truth.set_data(truth.x_m[:k + 1], truth.y_m[:k + 1])
    j = int(np.searchsorted(result.odometry.times_s, t))
    artists.odom.set_data(ox[:j], oy[:j])
    # the parts' outlines as one line, separated by NaN breaks
    parts = robot_outlines(result.body, (truth.x_m[k], truth.y_m[k], truth.yaw_rad[k]),
                           result.arm_positions_rad[k])
    outline = np.vstack([np.vstack((p, [[np.nan, np.nan]])) for p in parts])
    artists.body.set_data(outline[:, 0], outline[:, 1])
    if result.scans is not None and len(result.scans.times_s):
        s = max(int(np.searchsorted(result.scans.times_s, t, side="right")) - 1, 0)
        points = scan_points(result.scans, s)
        artists.scan.set_data(points[:, 0], points[:, 1])
    artists.clock.set_text(f"{result.scenario.name}  t = {t:6.1f} s")
