"""What ``inspect --render`` draws: the robot's visuals and frames placed at a configuration.

Plain values: ``output/render`` turns a :class:`PosedRobot` into polygons and a picture.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.inspect.geometry import (
    FAR_M,
    FloatArray,
    MeshLibrary,
    PosedShape,
    mesh_library,
    posed_visuals,
    unusable,
)
from servicebot_cli.inspect.poses import link_transforms

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

Rgba = tuple[float, float, float, float]


@dataclass(frozen=True)
class PosedRobot:
    """A robot placed at a configuration, ready to draw.

    Attributes:
        name: The robot's name.
        display: How messages name its file.
        values: The joint values it is placed at [rad or m]; others are zero.
        frames: Link name to ``transform_link_to_root`` (4x4).
        visuals: Visual shapes at ``values``.
        standing: Visual shapes at the zero configuration (where the floor is).
        meshes: The mesh files, loaded once; its ``problems`` lists the unusable ones.
        materials: Top-level material name to RGBA.
        labels: Frames worth naming: the root, sensor links, bare leaf frames (the tool).
        undrawn: One line per visual shape left out, and why.
    """

    name: str
    display: str
    values: Mapping[str, float]
    frames: Mapping[str, FloatArray] = field(repr=False)
    visuals: tuple[PosedShape, ...] = field(repr=False)
    standing: tuple[PosedShape, ...] = field(repr=False)
    meshes: MeshLibrary = field(repr=False)
    materials: Mapping[str, Rgba | None] = field(repr=False)
    labels: tuple[str, ...] = ()
    undrawn: tuple[str, ...] = ()


def pose_robot(robot: RobotDescription, values: Mapping[str, float],
               resolver: PackageResolver) -> PosedRobot:
    """``robot`` at the checked ``values`` (from :func:`~.poses.checked_values`)."""
    frames = link_transforms(robot, values)
    visuals = posed_visuals(robot, frames)
    why = [unusable(shape) for shape in visuals]
    undrawn = tuple(f"link '{shape.link}': a {shape.shape.geometry.kind} not drawn: {reason}"
                    for shape, reason in zip(visuals, why, strict=True) if reason)
    drawn = [shape for shape, reason in zip(visuals, why, strict=True) if not reason]
    standing = [shape for shape in posed_visuals(robot, link_transforms(robot))
                if not unusable(shape)]
    near = {name: t for name, t in frames.items()
            if np.all(np.isfinite(t)) and np.abs(t[:3, 3]).max() <= FAR_M}
    undrawn += tuple(f"frame '{name}' not drawn: {np.abs(t[:3, 3]).max():.3g} m from the root, "
                     "beyond any robot" for name, t in frames.items()
                     if name not in near and np.all(np.isfinite(t)))
    return PosedRobot(
        name=robot.name, display=robot.display, values=dict(values),
        frames=near,
        visuals=tuple(drawn), standing=tuple(standing),
        meshes=mesh_library(robot, resolver), materials=robot.materials,
        labels=_labels(robot, near), undrawn=undrawn,
    )


def _labels(robot: RobotDescription, frames: Mapping[str, FloatArray]) -> tuple[str, ...]:
    """Frames worth naming: the root, sensor links, and bare leaf frames (the tool)."""
    parents = {j.parent for j in robot.joints}
    bare_leaves = [lk.name for lk in robot.links if lk.name not in parents and not lk.visuals]
    wanted = [robot.root_link or "", *(s.reference or "" for s in robot.sensors), *bare_leaves]
    labels: list[str] = []
    for name in wanted:
        if name in frames and name not in labels and not any(
                np.allclose(frames[name][:3, 3], frames[other][:3, 3]) for other in labels):
            labels.append(name)
    return tuple(labels)
