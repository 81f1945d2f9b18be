"""The links table: mass, centre of mass, inertia, visual and collision geometry."""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.description.elements import Link, Shape, Vec3


@dataclass(frozen=True)
class Inertia:
    """The six independent entries of an inertia tensor [kg m^2], about the centre of mass."""

    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float

    @property
    def has_products(self) -> bool:
        """True when any product of inertia is not zero."""
        return any(v != 0 for v in (self.ixy, self.ixz, self.iyz))


@dataclass(frozen=True)
class ShapeInfo:
    """A visual or collision shape.

    Attributes:
        kind: ``box``, ``cylinder``, ``sphere``, ``mesh``, or ``""`` when missing.
        size_m: Box edge lengths [m].
        radius_m: Cylinder or sphere radius [m].
        length_m: Cylinder length along its own z axis [m].
        mesh: Mesh file as written in the URDF.
        scale: Mesh scale per axis.
        xyz_m: Shape origin in the link frame [m].
        rpy_rad: Shape orientation in the link frame [rad].
        material: Material name, if any.
    """

    kind: str
    size_m: Vec3 | None
    radius_m: float | None
    length_m: float | None
    mesh: str | None
    scale: Vec3 | None
    xyz_m: Vec3
    rpy_rad: Vec3
    material: str | None

    @classmethod
    def of(cls, shape: Shape) -> ShapeInfo:
        """The summary of ``shape``."""
        g = shape.geometry
        return cls(
            kind=g.kind, size_m=g.size, radius_m=g.radius, length_m=g.length,
            mesh=g.filename, scale=g.scale if g.kind == "mesh" else None,
            xyz_m=shape.origin.xyz, rpy_rad=shape.origin.rpy, material=shape.material,
        )


@dataclass(frozen=True)
class LinkInfo:
    """One link.

    Attributes:
        mass_kg: Mass [kg]; None when the link has no ``<inertial>`` (a frame).
        com_m: Centre of mass in the link frame [m].
        com_rpy_rad: Orientation of the inertia axes in the link frame [rad].
        inertia_kg_m2: Inertia about the centre of mass, in the inertia axes.
    """

    name: str
    mass_kg: float | None
    com_m: Vec3 | None
    com_rpy_rad: Vec3 | None
    inertia_kg_m2: Inertia | None
    visuals: tuple[ShapeInfo, ...]
    collisions: tuple[ShapeInfo, ...]


def link_info(link: Link) -> LinkInfo:
    """The summary of ``link``."""
    inertial = link.inertial
    inertia = None
    if inertial is not None and inertial.inertia_kg_m2 is not None:
        inertia = Inertia(*inertial.inertia_kg_m2)
    return LinkInfo(
        name=link.name,
        mass_kg=inertial.mass_kg if inertial else None,
        com_m=inertial.origin.xyz if inertial else None,
        com_rpy_rad=inertial.origin.rpy if inertial else None,
        inertia_kg_m2=inertia,
        visuals=tuple(ShapeInfo.of(s) for s in link.visuals),
        collisions=tuple(ShapeInfo.of(s) for s in link.collisions),
    )


def links_info(links: tuple[Link, ...]) -> tuple[LinkInfo, ...]:
    """Every link, URDF order."""
    return tuple(link_info(link) for link in links)
