"""Names rules: links, joints and materials named once, materials defined (SB101-SB113)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


SRDF_ELEMENTS = ("group", "group_state", "disable_collisions", "virtual_joint", "end_effector",
                 "passive_joint")
"""What a MoveIt SRDF's <robot> holds, and a URDF's does not."""


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Duplicate, empty and undefined names."""
    if not robot.links:
        semantic = sorted({child.tag for child in robot.root if child.tag in SRDF_ELEMENTS})
        if semantic:  # MoveIt's baxter.srdf.xacro, named by the user
            yield Issue("SB109", "the robot has no <link>: with its "
                        f"{', '.join(f'<{tag}>' for tag in semantic)} it is a MoveIt semantic "
                        "description (SRDF), not a URDF", robot.root,
                        fix="check the URDF it describes; MoveIt reads this file beside it")
        else:
            yield Issue("SB109", "the robot has no <link>", robot.root,
                        fix='add at least one <link name="base_link"/>')
    for kind, code, items in (("link", "SB101", robot.links), ("joint", "SB102", robot.joints)):
        first: dict[str, ET.Element | None] = {}
        for item in items:
            if not item.name:
                yield Issue("SB110", f"a <{kind}> without a name", item.element,
                            fix=f'add name="..." to the <{kind}>')
            elif not item.name.strip():  # urdfdom, Pinocchio and MuJoCo take it as a name
                yield Issue("SB110", f"a <{kind}> named '{item.name}', only blanks: urdfdom "
                            "takes it, but no command line, launch file or TF lookup can name "
                            "it", item.element, fix=f'give the <{kind}> a name to type',
                            severity=Severity.WARNING)
                first[item.name] = item.element
            elif item.name in first:
                yield Issue(code, f"{kind} '{item.name}' is defined twice (first at "
                            f"{robot.source_of(first[item.name])})", item.element,
                            fix=_twice_fix(robot, first[item.name], item.element, kind))
            else:
                first[item.name] = item.element
    yield from _materials(robot)


def _twice_fix(robot: RobotDescription, first: ET.Element | None, again: ET.Element | None,
               kind: str) -> str:
    """Rename one of the two; or, where one macro line wrote both, call it once."""
    a, b = robot.source_of(first), robot.source_of(again)
    if (a.file, a.line) == (b.file, b.line) and a.via is not None and b.via is not None \
            and a.via != b.via:
        return (f"the same macro is called twice ({a.via.location()} and {b.via.location()}): "
                "remove one call, or give each call its own name prefix")
    return f"rename one of the two {kind}s"


def _has_colour(material: ET.Element) -> bool:
    return material.find("color") is not None or material.find("texture") is not None


def _materials(robot: RobotDescription) -> Iterator[Issue]:
    defined: dict[str, ET.Element] = {}
    for material in robot.root.findall("material"):
        name = material.get("name", "")
        if name in defined:
            yield Issue("SB111", f"material '{name}' is defined twice (first at "
                        f"{robot.source_of(defined[name])})", material)
        elif _has_colour(material):
            defined[name] = material
        else:
            yield Issue("SB112", f"material '{name}' has no <color> or <texture>", material,
                        fix='add <color rgba="r g b a"/> with values in [0, 1]')
    for material in robot.root.findall("material"):
        yield from _rgba(material)
    for link in robot.links:  # in the file's order, as urdfdom reads them
        for visual in link.visuals:
            used = visual.element.find("material") if visual.element is not None else None
            if used is None:
                continue
            yield from _rgba(used)
            used_name = used.get("name")
            if used_name and used_name in defined and _has_colour(used) \
                    and _look(used) != _look(defined[used_name]):
                yield Issue("SB114", f"material '{used_name}' of link '{link.name}' has "
                            f"{_shown(used)}, but '{used_name}' is already "
                            f"{_shown(defined[used_name])} (at "
                            f"{robot.source_of(defined[used_name])}): urdfdom gives the link "
                            "that first definition, and RViz and Gazebo draw it so", used,
                            fix=f"give this colour a name of its own, not '{used_name}'")
            if not used_name or used_name in defined:
                continue
            if _has_colour(used):  # urdfdom keeps it: later links may use it by name
                defined[used_name] = used
                continue
            known = ", ".join(sorted(defined)) or "none"
            yield Issue("SB112", f"material '{used_name}' of link '{link.name}' has no colour "
                        "and is not defined at the top level or in an earlier link's visual "
                        f"(defined: {known})", used,
                        fix=f'define <material name="{used_name}"><color rgba="..."/>'
                        "</material>")


def _look(material: ET.Element) -> tuple[tuple[float, ...] | str | None, str | None]:
    """A material's colour (rgba numbers, or the text where they are none) and texture."""
    color, texture = material.find("color"), material.find("texture")
    text = color.get("rgba", "") if color is not None else None
    try:
        rgba: tuple[float, ...] | str | None = None if text is None else tuple(
            round(float(v), 6) for v in text.split())
    except ValueError:
        rgba = text
    return rgba, texture.get("filename") if texture is not None else None


def _shown(material: ET.Element) -> str:
    color = material.find("color")
    if color is not None:
        return f"rgba '{color.get('rgba', '')}'"
    return f"texture '{_look(material)[1]}'"


def _rgba(material: ET.Element) -> Iterator[Issue]:
    color = material.find("color")
    if color is None:
        return
    try:
        values = [float(v) for v in (color.get("rgba") or "").split()]
    except ValueError:
        return  # SB013 reports it
    if not all(math.isfinite(v) for v in values):
        return  # SB014 reports it
    if len(values) == 4 and not all(0.0 <= v <= 1.0 for v in values):
        # a 0-255 colour divided by 255; 1.0000000001, a rounding past 1, clamped to 1
        scaled = " ".join(("1" if v <= 1.01 else f"{min(v / 255.0, 1.0):.3g}") if v > 1
                          else f"{max(v, 0.0):g}" for v in values)
        yield Issue("SB113", f"rgba '{color.get('rgba')}' of material "
                    f"'{material.get('name', '')}' is outside [0, 1]: urdfdom drops the "
                    "material", color,
                    fix=f'rgba="{scaled}"')
