"""Which values the computing rules may use: finite, in range, already accepted by SB0.

The parse-level rules (SB012-SB014, SB405) report a bad number once; the rules that compute
with numbers (inertia against geometry, mesh sizes) then skip what those rules rejected,
instead of computing on NaN, infinity or 1e300 and failing or printing numpy warnings.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable

from servicebot_cli.description.elements import Geometry, Pose, Shape

# a decimal number as C's readers take it: ASCII digits (Python's float() also reads "٣");
# and the words nan and inf, which some read and some do not
NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
NON_FINITE = re.compile(r"[+-]?(?:nan|inf|infinity)", re.IGNORECASE)
_TEXT_ATTRIBUTES = frozenset({"name", "filename", "type", "link", "joint", "reference"})
LARGEST_LENGTH_M = 1e6
"""Lengths and offsets beyond this [m] are not computed with (no robot is 1000 km wide)."""
LARGEST_SCALE = 1e6
"""Mesh scale factors beyond this are not computed with."""
LARGEST_INERTIA = 1e12
"""Masses [kg] and inertia components [kg m^2] beyond this are not computed with."""


def is_number(text: str) -> bool:
    """Whether ``text`` is one decimal number (ASCII digits; nan and inf count)."""
    return NUMBER.fullmatch(text) is not None or NON_FINITE.fullmatch(text) is not None


def finite(values: Iterable[float | None]) -> bool:
    """True when every value is present and a finite float."""
    return all(v is not None and math.isfinite(v) for v in values)


def bounded(values: Iterable[float | None], largest: float) -> bool:
    """True when every value is present, finite and at most ``largest`` in magnitude."""
    return all(v is not None and math.isfinite(v) and abs(v) <= largest for v in values)


def usable_pose(pose: Pose) -> bool:
    """An ``<origin>`` with finite, bounded translation and rotation (``rpy="0 0"`` is not)."""
    return bounded(pose.xyz, LARGEST_LENGTH_M) and bounded(pose.rpy, 1e3)


def usable_geometry(geometry: Geometry) -> bool:
    """A primitive with positive, bounded sizes, or a mesh with a non-zero, bounded scale."""
    if geometry.kind == "box":
        return geometry.size is not None and _positive(geometry.size)
    if geometry.kind == "cylinder":
        return _positive((geometry.radius, geometry.length))
    if geometry.kind == "sphere":
        return _positive((geometry.radius,))
    if geometry.kind == "mesh":
        return bool(geometry.filename) and bounded(geometry.scale, LARGEST_SCALE) and all(
            abs(s) >= 1.0 / LARGEST_SCALE for s in geometry.scale)
    return False


def usable_shape(shape: Shape) -> bool:
    """A visual or collision whose origin and geometry can be computed with."""
    return (usable_pose(shape.origin) and usable_geometry(shape.geometry)
            and plain_numbers(shape.element))


def plain_numbers(element: ET.Element | None) -> bool:
    """True when the numbers under ``element`` are ASCII, as urdfdom requires (SB013).

    Python's ``float`` reads full-width and Arabic-Indic digits, urdfdom refuses them and drops
    the element: the rules must not compute with a value urdfdom never sees.
    """
    if element is None:
        return True
    return all(value.isascii() for node in element.iter()
               for key, value in node.attrib.items() if key not in _TEXT_ATTRIBUTES)


def _positive(values: Iterable[float | None]) -> bool:
    numbers = list(values)
    return bounded(numbers, LARGEST_LENGTH_M) and all(
        v is not None and v >= 1.0 / LARGEST_LENGTH_M for v in numbers)
