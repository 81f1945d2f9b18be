"""The parts of a URDF as plain values: links, joints, materials, transmissions.

Reading is tolerant, because ``check`` must describe broken files rather than stop at the
first defect: a missing attribute becomes ``None``, an unparsable number becomes NaN, and
URDF's defaults apply where the format has them (axis 1 0 0, zero origin, mimic
multiplier 1). Each value keeps its XML element, for source positions. Pure: no I/O.
"""

from __future__ import annotations

import functools
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

Vec3 = tuple[float, float, float]
ZERO3: Vec3 = (0.0, 0.0, 0.0)

MOVABLE_TYPES = ("revolute", "continuous", "prismatic", "planar", "floating")
JOINT_TYPES = ("fixed", *MOVABLE_TYPES)
ONE_AXIS_TYPES = ("revolute", "continuous", "prismatic")
"""Joints that move along one axis: one value each, and the dynamics Pinocchio reads."""


def parse_float(text: str | None) -> float | None:
    """A float, ``None`` when absent, NaN when present but not a number to urdfdom.

    Python's ``float`` also reads ``1_000``, digits of other scripts (``０.１``) and blanks
    after the number, all of which urdfdom refuses (check's SB013): NaN here, so that no
    rule computes with a value the file does not give urdfdom.
    """
    if text is None:
        return None
    if "_" in text or not text.isascii() or text[-1:].isspace():
        return math.nan
    try:
        return float(text)
    except ValueError:
        return math.nan


def escaped_blanks(text: str) -> str:
    """``text`` with its tabs and line breaks written as ``\\t``, ``\\r`` and ``\\n``."""
    return text.replace("\t", "\\t").replace("\r", "\\r").replace("\n", "\\n")


@functools.lru_cache(maxsize=4096)  # "0 0 0" and "1 1 1" fill most files
def parse_vec3(text: str | None, default: Vec3 | None = ZERO3) -> Vec3 | None:
    """Three floats from ``"x y z"``; NaNs when malformed, ``default`` when absent."""
    if text is None:
        return default
    parts = text.split()
    if len(parts) != 3:
        return (math.nan, math.nan, math.nan)
    x, y, z = (parse_float(p) for p in parts)
    return (x, y, z)  # type: ignore[return-value]


FARTHEST_M = 1e6
"""Origins and sizes beyond this [m] are no robot's: a typo or a wrong unit."""


@dataclass(frozen=True)
class Pose:
    """An ``<origin>``: translation [m] and roll-pitch-yaw [rad] (fixed axes X, Y, Z)."""

    xyz: Vec3 = ZERO3
    rpy: Vec3 = ZERO3

    @property
    def offset_m(self) -> float:
        """The largest of ``|x|``, ``|y|``, ``|z|``."""
        return max(abs(self.xyz[0]), abs(self.xyz[1]), abs(self.xyz[2]))

    @classmethod
    def of(cls, element: ET.Element | None) -> Pose:
        """The pose in ``element``'s ``<origin>`` child, identity when there is none."""
        origin = element.find("origin") if element is not None else None
        if origin is None:
            return _IDENTITY
        return _pose(origin.get("xyz"), origin.get("rpy"))


_IDENTITY = Pose()


@functools.lru_cache(maxsize=4096)
def _pose(xyz: str | None, rpy: str | None) -> Pose:
    """The pose of an ``<origin xyz rpy>`` (frozen: one object serves every equal origin)."""
    return Pose(parse_vec3(xyz) or ZERO3, parse_vec3(rpy) or ZERO3)


@dataclass(frozen=True)
class Geometry:
    """A ``<geometry>``: one primitive or a mesh; lengths in [m].

    Attributes:
        kind: ``box``, ``cylinder``, ``sphere``, ``mesh``, or ``""`` when missing or unknown.
        size: Box edge lengths.
        radius: Cylinder or sphere radius.
        length: Cylinder length along its z axis.
        filename: Mesh reference as written (``package://``, ``file://`` or a path).
        scale: Mesh scale per axis.
    """

    kind: str
    size: Vec3 | None = None
    radius: float | None = None
    length: float | None = None
    filename: str | None = None
    scale: Vec3 = (1.0, 1.0, 1.0)

    @classmethod
    def of(cls, element: ET.Element | None) -> Geometry:
        """The geometry in ``element``'s ``<geometry>`` child."""
        geometry = element.find("geometry") if element is not None else None
        shape = next(iter(geometry), None) if geometry is not None else None
        if shape is None or not isinstance(shape.tag, str):
            return cls("")
        if shape.tag == "box":
            return cls("box", size=parse_vec3(shape.get("size"), None))
        if shape.tag == "cylinder":
            return cls("cylinder", radius=parse_float(shape.get("radius")),
                       length=parse_float(shape.get("length")))
        if shape.tag == "sphere":
            return cls("sphere", radius=parse_float(shape.get("radius")))
        if shape.tag == "mesh":
            return cls("mesh", filename=shape.get("filename"),
                       scale=parse_vec3(shape.get("scale"), (1.0, 1.0, 1.0)) or (1.0, 1.0, 1.0))
        return cls("")


@dataclass(frozen=True)
class Shape:
    """A ``<visual>`` or ``<collision>`` of a link."""

    origin: Pose
    geometry: Geometry
    name: str | None = None
    material: str | None = None
    element: ET.Element | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Inertial:
    """A link's ``<inertial>``.

    Attributes:
        mass_kg: Mass [kg]; None if ``<mass>`` is missing.
        origin: Centre of mass and inertia axes relative to the link frame.
        inertia_kg_m2: ``(ixx, ixy, ixz, iyy, iyz, izz)`` [kg m^2]; None if missing.
    """

    mass_kg: float | None
    origin: Pose
    inertia_kg_m2: tuple[float, float, float, float, float, float] | None
    element: ET.Element | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Link:
    """A ``<link>``."""

    name: str
    inertial: Inertial | None
    visuals: tuple[Shape, ...]
    collisions: tuple[Shape, ...]
    element: ET.Element | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class JointLimits:
    """A joint's ``<limit>``, in the joint's own units.

    Position in [rad] (revolute) or [m] (prismatic), velocity in [rad/s] or [m/s],
    effort in [N m] or [N]. ``lower``/``upper`` are None for continuous joints.
    """

    lower: float | None
    upper: float | None
    velocity: float | None
    effort: float | None


@dataclass(frozen=True)
class Mimic:
    """``<mimic>``: this joint = multiplier * other + offset."""

    joint: str | None
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class Joint:
    """A ``<joint>``.

    Attributes:
        axis: Unit axis in the joint frame (URDF default 1 0 0).
        limits: The ``<limit>``; None when the element is absent.
    """

    name: str
    type: str
    parent: str | None
    child: str | None
    origin: Pose
    axis: Vec3
    limits: JointLimits | None
    mimic: Mimic | None = None
    element: ET.Element | None = field(default=None, compare=False, repr=False)

    @property
    def movable(self) -> bool:
        """True for every type but fixed (and unknown types)."""
        return self.type in MOVABLE_TYPES

    @property
    def angular(self) -> bool:
        """True when the joint's position is an angle [rad]."""
        return self.type in ("revolute", "continuous")


@dataclass(frozen=True)
class Transmission:
    """A ``<transmission>``: its joints and actuators by name."""

    name: str
    type: str | None
    joints: tuple[str, ...]
    actuators: tuple[str, ...]
    element: ET.Element | None = field(default=None, compare=False, repr=False)


def read_link(element: ET.Element) -> Link:
    """A Link from a ``<link>`` element."""
    inertial_el = element.find("inertial")
    inertial = None
    if inertial_el is not None:
        mass_el = inertial_el.find("mass")
        inertia_el = inertial_el.find("inertia")
        inertia = None
        if inertia_el is not None:
            keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
            values = [parse_float(inertia_el.get(k)) for k in keys]
            inertia = tuple(math.nan if v is None else v for v in values)
        inertial = Inertial(
            mass_kg=parse_float(mass_el.get("value")) if mass_el is not None else None,
            origin=Pose.of(inertial_el),
            inertia_kg_m2=inertia,  # type: ignore[arg-type]
            element=inertial_el,
        )
    return Link(
        name=element.get("name", ""),
        inertial=inertial,
        visuals=tuple(_shape(v) for v in element.findall("visual")),
        collisions=tuple(_shape(c) for c in element.findall("collision")),
        element=element,
    )


def _shape(element: ET.Element) -> Shape:
    material = element.find("material")
    return Shape(
        origin=Pose.of(element),
        geometry=Geometry.of(element),
        name=element.get("name"),
        material=material.get("name") if material is not None else None,
        element=element,
    )


def read_joint(element: ET.Element) -> Joint:
    """A Joint from a ``<joint>`` element."""
    parent = element.find("parent")
    child = element.find("child")
    axis = element.find("axis")
    limit = element.find("limit")
    mimic = element.find("mimic")
    joint_type = element.get("type", "")
    limits = None
    if limit is not None:
        continuous = joint_type == "continuous"
        limits = JointLimits(
            lower=None if continuous else (parse_float(limit.get("lower")) or 0.0),
            upper=None if continuous else (parse_float(limit.get("upper")) or 0.0),
            velocity=parse_float(limit.get("velocity")),
            effort=parse_float(limit.get("effort")),
        )
    return Joint(
        name=element.get("name", ""),
        type=joint_type,
        parent=parent.get("link") if parent is not None else None,
        child=child.get("link") if child is not None else None,
        origin=Pose.of(element),
        axis=parse_vec3(axis.get("xyz") if axis is not None else None, (1.0, 0.0, 0.0))
        or (1.0, 0.0, 0.0),
        limits=limits,
        mimic=None if mimic is None else Mimic(
            joint=mimic.get("joint"),
            multiplier=_or(parse_float(mimic.get("multiplier")), 1.0),
            offset=_or(parse_float(mimic.get("offset")), 0.0),
        ),
        element=element,
    )


def read_transmission(element: ET.Element) -> Transmission:
    """A Transmission from a ``<transmission>`` element (ROS 1 or ros2_control style)."""
    type_el = element.find("type")
    return Transmission(
        name=element.get("name", ""),
        type=type_el.text.strip() if type_el is not None and type_el.text else element.get("type"),
        joints=tuple(j.get("name", "") for j in element.findall("joint")),
        actuators=tuple(a.get("name", "") for a in element.findall("actuator")),
        element=element,
    )


def read_materials(root: ET.Element) -> dict[str, tuple[float, float, float, float] | None]:
    """Top-level named materials: name to RGBA in [0, 1], or None when there is no colour."""
    materials: dict[str, tuple[float, float, float, float] | None] = {}
    for material in root.findall("material"):
        color = material.find("color")
        rgba = None
        if color is not None:
            parts = [parse_float(p) for p in (color.get("rgba") or "").split()]
            numbers = [p for p in parts if p is not None]
            if len(parts) == len(numbers) == 4:
                rgba = (numbers[0], numbers[1], numbers[2], numbers[3])
        materials[material.get("name", "")] = rgba
    return materials


def _or(value: float | None, default: float) -> float:
    return default if value is None else value
