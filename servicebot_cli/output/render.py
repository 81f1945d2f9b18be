"""``servicebot inspect --render FILE``: a posed robot drawn into a file, written atomically."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import numpy as np

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.files import atomic_output
from servicebot_cli.inspect.picture import PosedRobot
from servicebot_cli.output.picture import Scene, draw
from servicebot_cli.output.solids import solids
from servicebot_cli.output.table import format_number

FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}
SUFFIXES = tuple(FORMATS)
"""What ``--render`` writes; the option refuses any other name before any work."""


class RenderError(ServicebotError):
    """The picture cannot be made: an unknown file type, or nothing to draw."""


def picture_format(path: str) -> str:
    """``png``, ``svg`` or ``pdf`` from the file name.

    Raises:
        RenderError: Any other suffix.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise RenderError(f"{path}: cannot draw a '{suffix or 'suffixless'}' file; "
                          f"name it .png, .svg or .pdf")
    return FORMATS[suffix]


def title(robot: str, values: Mapping[str, float]) -> str:
    """``service_robot at arm_link1_to_link2=0.8 rad`` or ``... at the zero configuration``."""
    if not values:
        return f"{robot} at the zero configuration"
    return f"{robot} at " + ", ".join(f"{k}={format_number(v)}" for k, v in values.items()) \
        + " (others 0; rad, m)"


def write_picture(posed: PosedRobot, path: str, view: str) -> list[str]:
    """Draw ``posed`` into ``path`` as seen from ``view``; returns what was left out, and why.

    Raises:
        RenderError: Bad file type, or no visual geometry at all.
        OutputError: The file cannot be written.
    """
    fmt = picture_format(path)
    scene = _scene(posed)
    with atomic_output(path, "wb") as handle:
        draw(scene, handle, fmt=fmt, view=view)
    return [*posed.undrawn, *posed.meshes.problems]


def _scene(posed: PosedRobot) -> Scene:
    """Polygons of every shape, the floor under the robot as it stands at zero."""
    shapes = solids(list(posed.visuals), posed.meshes, posed.materials)
    if not shapes:
        problems = posed.meshes.problems
        raise RenderError(f"{posed.display}: no visual geometry to draw"
                          + (f" ({problems[0]})" if problems else ""))
    # the floor is where the robot stands at zero, so an arm reaching down goes through it
    standing = solids(list(posed.standing), posed.meshes, posed.materials)
    floor_z = min(float(np.min(poly[:, 2])) for s in standing for poly in s.polygons)
    return Scene(shapes, posed.frames, posed.labels, title(posed.name, posed.values), floor_z)
