"""A picture of the robot: its visual geometry, shaded, with its frames, drawn without a display.

Matplotlib's Agg canvas draws it (no pyplot, no window, no DISPLAY needed), as one collection
of polygons so faces are sorted by depth together. Each face is lit from one direction with
two-sided Lambert shading; the axes are scaled equally, so a box looks like a box.
"""

from __future__ import annotations

import textwrap
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import IO, Any

import numpy as np

from servicebot_cli.inspect.geometry import FloatArray
from servicebot_cli.output.solids import Solid

VIEWS = {"iso": (20.0, -35.0), "front": (8.0, 0.0), "side": (8.0, -90.0), "top": (90.0, -90.0)}
"""Camera elevation and azimuth [deg] for each ``--view``."""
_LIGHT = np.array([0.4, -0.5, 0.8]) / np.linalg.norm([0.4, -0.5, 0.8])
_AXIS_COLOURS = ("#d62728", "#2ca02c", "#1f77b4")  # x red, y green, z blue, as in RViz


@dataclass(frozen=True)
class Scene:
    """What to draw.

    Attributes:
        solids: Shapes in the root frame.
        frames: Frame name to ``transform_frame_to_root`` (4x4).
        labels: Frames whose names are written next to them.
        title: The picture's title.
        floor_z_m: Height of the floor plane (the lowest point) [m].
    """

    solids: list[Solid]
    frames: Mapping[str, FloatArray]
    labels: Sequence[str]
    title: str
    floor_z_m: float


def _shaded(rgba: Sequence[float], polygon: FloatArray) -> tuple[float, ...]:
    normal = np.cross(polygon[1] - polygon[0], polygon[2] - polygon[0])
    norm = np.linalg.norm(normal)
    light = abs(float(normal @ _LIGHT)) / norm if norm > 0 else 1.0
    factor = 0.45 + 0.55 * light
    r, g, b = rgba[:3]
    if max(r, g, b) < 0.2:  # black parts (tyres) would lose all shading: lift them a little
        r, g, b = (0.15 + 0.85 * c for c in (r, g, b))
    return (float(r * factor), float(g * factor), float(b * factor), float(rgba[3]))


def _limits(scene: Scene) -> tuple[FloatArray, FloatArray]:
    points = [p for s in scene.solids for poly in s.polygons for p in poly]
    points += [t[:3, 3] for t in scene.frames.values()]
    cloud = np.array(points) if points else np.zeros((1, 3))
    low, high = cloud.min(axis=0), cloud.max(axis=0)
    margin = 0.08 * max(float(np.max(high - low)), 0.1)
    return low - margin, high + margin


def _draw_solids(ax: Any, scene: Scene) -> None:
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # type: ignore[import-untyped]

    polygons, faces, edges = [], [], []
    for solid in scene.solids:
        edge = (0.1, 0.1, 0.1, 0.5) if solid.kind == "box" else (0, 0, 0, 0)
        for polygon in solid.polygons:
            polygons.append(polygon)
            faces.append(_shaded(solid.rgba, polygon))
            edges.append(edge)
    if polygons:
        ax.add_collection3d(Poly3DCollection(polygons, facecolors=faces, edgecolors=edges,
                                             linewidths=0.4, zsort="average", zorder=1))


def _draw_frames(ax: Any, scene: Scene, length_m: float) -> None:
    for name, transform in scene.frames.items():
        origin = transform[:3, 3]
        for axis in range(3):
            tip = origin + transform[:3, axis] * length_m
            ax.plot(*zip(origin, tip, strict=True), color=_AXIS_COLOURS[axis], linewidth=1.4,
                    zorder=2)
        if name in scene.labels:
            ax.text(*(origin + np.array([0, 0, length_m * 0.6])), name, fontsize=7, zorder=3,
                    color="#222222")


def _draw_floor(ax: Any, low: FloatArray, high: FloatArray, z_m: float) -> None:
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    corners = np.array([[low[0], low[1], z_m], [high[0], low[1], z_m],
                        [high[0], high[1], z_m], [low[0], high[1], z_m]])
    ax.add_collection3d(Poly3DCollection([corners], facecolors=[(0.85, 0.85, 0.82, 0.5)],
                                         edgecolors=[(0.6, 0.6, 0.6, 0.6)], zorder=0))


def draw(scene: Scene, out: IO[bytes], *, fmt: str = "png", view: str = "iso",
         size_px: tuple[int, int] = (1200, 900)) -> None:
    """Draw ``scene`` into the binary stream ``out`` as ``fmt`` (png, svg or pdf)."""
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        # mplot3d's view limits overflow harmlessly on the way; nothing for a user to act on
        warnings.simplefilter("ignore", RuntimeWarning)
        _draw(scene, out, fmt, view, size_px)


def _draw(scene: Scene, out: IO[bytes], fmt: str, view: str, size_px: tuple[int, int]) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    dpi = 150
    figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    FigureCanvasAgg(figure)
    ax = figure.add_subplot(projection="3d")
    ax.computed_zorder = False  # floor, then the robot (faces depth-sorted), then frames
    low, high = _limits(scene)
    low[2] = min(low[2], scene.floor_z_m)
    # fixed limits before anything is added: mplot3d's autoscaling can overflow to NaN
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    ax.set_autoscale_on(False)
    ax.set_box_aspect(tuple(high - low))
    _draw_floor(ax, low, high, scene.floor_z_m)
    _draw_solids(ax, scene)
    _draw_frames(ax, scene, 0.07 * float(np.max(high - low)))
    ax.view_init(*VIEWS[view])
    for name, setter in (("x", ax.set_xlabel), ("y", ax.set_ylabel), ("z", ax.set_zlabel)):
        setter(f"{name} [m]", fontsize=8)
    ax.tick_params(labelsize=6)
    figure.suptitle("\n".join(textwrap.wrap(scene.title, 90)), fontsize=10)
    figure.text(0.01, 0.01, "frames: x red, y green, z blue", fontsize=7, color="#444444")
    figure.subplots_adjust(left=0, right=1, bottom=0.05, top=0.93)
    figure.savefig(out, format=fmt)
