"""SB517: ``<ros2_control>`` markup that ros2_control's component parser refuses.

The parser (hardware_interface's ``component_parser.cpp``), shared by ros2_control_node and
Gazebo's ros2_control plugins, throws on an attribute it needs and does not find: a
component's ``name`` and ``type``, the ``name`` of a joint, sensor, gpio, interface or
``<param>``; the resource manager refuses two components of one name and loads only the types
``system``, ``actuator`` and ``sensor`` (the Gazebo plugins load every component as a system:
there, another type is a warning). Either way no controller runs. SB515 judges a joint's
``mimic`` attribute.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity

if TYPE_CHECKING:
    from servicebot_cli.description.extensions import Ros2Control

_TYPES = ("system", "actuator", "sensor")
_NAMED = ("joint", "sensor", "gpio")
_INTERFACES = ("command_interface", "state_interface")
_REFUSED = "ros2_control's parser refuses the robot, and no controller runs"


def check(blocks: Sequence[Ros2Control], simulator: str | None) -> Iterator[Issue]:
    """SB517 for each component's refused markup, and for a name two components share.

    ``simulator``: the Gazebo plugin that runs the components, if any.
    """
    first: dict[str, Ros2Control] = {}
    for block in blocks:
        element = block.element
        if element is None:
            continue
        yield from _component(element, simulator)
        name = element.get("name")
        if name is None:
            continue
        other = first.setdefault(name, block)
        if other is not block:
            yield Issue("SB517", f"two <ros2_control> components named '{name}': the resource "
                        "manager refuses the second ('Hardware name ... is duplicated'), and no "
                        "controller runs", element, fix="give each component its own name")


def _component(element: ET.Element, simulator: str | None) -> Iterator[Issue]:
    for attribute in ("name", "type"):
        if element.get(attribute) is None:
            yield Issue("SB517", f"<ros2_control> without a '{attribute}' attribute: {_REFUSED}",
                        element, fix=f"add {attribute}=\"...\"" if attribute == "name" else
                        'add type="system" (or "actuator", "sensor")')
    kind = element.get("type")
    if kind is not None and kind not in _TYPES:
        close = next((t for t in _TYPES if t.startswith(kind.strip().lower()[:3])), "system")
        warning = simulator is not None
        yield Issue("SB517", f"<ros2_control type=\"{kind}\">: ros2_control_node loads only "
                    f"{', '.join(_TYPES)} components and refuses the robot"
                    + (f"; {simulator} loads it as a system" if warning else ""), element,
                    fix=f'type="{close}"', severity=Severity.WARNING if warning else None)
    for part in element:
        if not isinstance(part.tag, str):
            continue
        if part.tag in _NAMED and part.get("name") is None:
            yield _unnamed(part, f"<{part.tag}>")
        for child in part:
            if child.tag in _INTERFACES and child.get("name") is None:
                yield _unnamed(child, f"<{child.tag}> of {_of(part)}")
            elif child.tag == "param" and child.get("name") is None:
                yield _unnamed(child, f"<param> of {_of(part)}")
            for param in child if child.tag in _INTERFACES else ():
                if param.tag == "param" and param.get("name") is None:
                    yield _unnamed(param, f"<param> of {_of(child)}")


def _of(element: ET.Element) -> str:
    name = element.get("name")
    return f"<{element.tag} name=\"{name}\">" if name is not None else f"<{element.tag}>"


def _unnamed(element: ET.Element, what: str) -> Issue:
    return Issue("SB517", f"{what} has no 'name' attribute: {_REFUSED}", element,
                 fix='add name="..."')
