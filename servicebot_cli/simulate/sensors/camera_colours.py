"""The colours a camera draws things in: the robot's URDF materials, the scenario's colours.

A link takes the colour of its first ``<visual>`` whose ``<material>`` has one, resolved as
urdfdom resolves it: the material's own ``<color rgba>``, else that of the top-level
``<material>`` of the same name (alpha is not drawn). A link without one, and anything the
scenario gives no ``color``, keeps :class:`~.camera_image.Palette`'s. The floor's colour
makes the lighter square of its checker; the other is 80 % of it, so motion still shows.
Pure.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from servicebot_cli.description.elements import parse_float
from servicebot_cli.simulate.scenario.camera import CameraImages
from servicebot_cli.simulate.sensors.camera_image import Palette, Rgb, rgb_of

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from servicebot_cli.description.robot import RobotDescription

FLOOR_SHADE = 0.8
"""The darker floor square's share of the floor's colour."""


def link_colours(robot: RobotDescription) -> dict[str, Rgb]:
    """Each link's URDF material colour, for the links that have one."""
    named = robot.materials
    colours: dict[str, Rgb] = {}
    for link in robot.links:
        for visual in link.visuals:
            element = visual.element.find("material") if visual.element is not None else None
            inline = _rgba(element.find("color")) if element is not None else None
            rgba = inline or (named.get(visual.material) if visual.material else None)
            if rgba is not None:
                colours[link.name] = rgb_of(rgba[:3])
                break
    return colours


def palette(images: CameraImages) -> Palette:
    """The default palette with the scenario's floor colour, if it gives one."""
    if images.floor_color is None:
        return Palette()
    light = rgb_of(images.floor_color)
    dark = rgb_of([FLOOR_SHADE * c for c in images.floor_color])
    return Palette(floor=(light, dark))


def mesh_colours(images: CameraImages, count: int, default: Palette) -> tuple[Rgb, ...]:
    """The colour of each of ``count`` meshes: the scenario's, else the palette's."""
    given: Sequence[tuple[float, float, float] | None] = images.mesh_colors or (None,) * count
    return tuple(rgb_of(c) if c is not None else default.mesh for c in given)


def _rgba(color: ET.Element | None) -> tuple[float, ...] | None:
    """``<color rgba="r g b a">`` as four numbers, None when absent or malformed."""
    text = color.get("rgba") if color is not None else None
    numbers = [parse_float(p) for p in (text or "").split()]
    if len(numbers) != 4 or any(n is None for n in numbers):
        return None
    return tuple(n for n in numbers if n is not None)
