"""``servicebot inspect --render FILE``: the robot at a configuration, written atomically."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import IO, TYPE_CHECKING

import numpy as np

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.files import atomic_output
from servicebot_cli.inspect.geometry import mesh_library, posed_visuals
from servicebot_cli.inspect.poses import link_transforms
from servicebot_cli.output.picture import Scene, draw
from servicebot_cli.output.solids import solids
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}


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


def _labels(robot: RobotDescription, frames: Mapping[str, np.ndarray]) -> list[str]:
    """Frames worth naming: the root, sensor links, and bare leaf frames (the tool)."""
    parents = {j.parent for j in robot.joints}
    bare_leaves = [lk.name for lk in robot.links if lk.name not in parents and not lk.visuals]
    wanted = [robot.root_link or "", *(s.reference or "" for s in robot.sensors), *bare_leaves]
    labels: list[str] = []
    for name in wanted:
        if name in frames and name not in labels and not any(
                np.allclose(frames[name][:3, 3], frames[other][:3, 3]) for other in labels):
            labels.append(name)
    return labels


def title(robot: str, values: Mapping[str, float]) -> str:
    """``service_robot at arm_link1_to_link2=0.8 rad`` or ``... at the zero configuration``."""
    if not values:
        return f"{robot} at the zero configuration"
    return f"{robot} at " + ", ".join(f"{k}={format_number(v)}" for k, v in values.items()) \
        + " (others 0; rad, m)"


def render_robot(robot: RobotDescription, path: str, values: Mapping[str, float], *,
                 clamp: bool, resolver: PackageResolver, view: str) -> list[str]:
    """Draw ``robot`` at ``values`` into ``path``; returns problems met (unreadable meshes).

    Raises:
        RenderError: Bad file type, or no visual geometry at all.
        OutputError: The file cannot be written.
    """
    fmt = picture_format(path)
    with atomic_output(path, "wb") as handle:  # a bad target fails before any drawing
        problems = _draw_robot(robot, handle, fmt, values, clamp=clamp, resolver=resolver,
                               view=view)
    return problems


def _draw_robot(robot: RobotDescription, handle: IO[bytes], fmt: str,
                values: Mapping[str, float], *, clamp: bool, resolver: PackageResolver,
                view: str) -> list[str]:
    frames = link_transforms(robot, values, clamp=clamp)
    meshes = mesh_library(robot, resolver)
    shapes = solids(posed_visuals(robot, frames), meshes, robot.materials)
    if not shapes:
        raise RenderError(f"{robot.display}: no visual geometry to draw"
                          + (f" ({meshes.problems[0]})" if meshes.problems else ""))
    # the floor is where the robot stands at zero, so an arm reaching down goes through it
    standing = solids(posed_visuals(robot, link_transforms(robot)), meshes, robot.materials)
    floor_z = min(float(np.min(poly[:, 2])) for s in standing for poly in s.polygons)
    scene = Scene(shapes, frames, _labels(robot, frames), title(robot.name, values), floor_z)
    draw(scene, handle, fmt=fmt, view=view)
    return meshes.problems
