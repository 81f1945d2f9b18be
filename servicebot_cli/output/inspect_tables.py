"""The tables of ``servicebot inspect``: links, joints, frames and totals.

Each function takes one section of an Inspection and returns Tables; text and Markdown
renderers share them, so both always show the same rows.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from servicebot_cli.output import describe as d
from servicebot_cli.output.blocks import Table
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.inspect.joints import FrameInfo, JointInfo
    from servicebot_cli.inspect.links import LinkInfo, ShapeInfo
    from servicebot_cli.inspect.totals import Totals


def links_tables(links: tuple[LinkInfo, ...]) -> list[Table]:
    """Mass and inertia; products of inertia where any; geometry."""
    inertia = Table(f"Links ({len(links)}): mass and inertia",
                    ("link", "mass [kg]", "centre of mass [m]", "ixx [kg m^2]", "iyy", "izz"))
    products = Table("Products of inertia", ("link", "ixy [kg m^2]", "ixz", "iyz"))
    for link in links:
        i = link.inertia_kg_m2
        inertia.rows.append((link.name, link.mass_kg, d.vec(link.com_m),
                             i.ixx if i else None, i.iyy if i else None, i.izz if i else None))
        if i is not None and i.has_products:
            products.rows.append((link.name, i.ixy, i.ixz, i.iyz))
    massless = [lk.name for lk in links if lk.mass_kg is None]
    if massless:
        inertia = Table(inertia.title, inertia.headers, inertia.rows,
                        (f"no <inertial> (frames): {', '.join(massless)}",))
    tables = [inertia] + ([products] if products.rows else [])
    return tables + [_geometry_table(links)]


def _geometry_table(links: tuple[LinkInfo, ...]) -> Table:
    table = Table("Link geometry (both = the same shape for visual and collision)",
                  ("link", "shape", "geometry [m]", "xyz [m]", "rpy [rad]"))
    for link in links:
        same = [_bare(v) for v in link.visuals] == [_bare(c) for c in link.collisions]
        groups = [("both", link.visuals)] if same else [("visual", link.visuals),
                                                        ("collision", link.collisions)]
        for role, shapes in groups:
            for shape in shapes:
                table.rows.append(_shape_row(link.name, role, shape))
    return table


def _bare(shape: ShapeInfo) -> ShapeInfo:
    """The shape without its material, which only visuals have."""
    return replace(shape, material=None)


def _shape_row(link: str, role: str, shape: ShapeInfo) -> tuple[object, ...]:
    return (link, role, d.shape(shape), d.vec(shape.xyz_m), d.vec(shape.rpy_rad))


def joints_tables(joints: tuple[JointInfo, ...]) -> list[Table]:
    """Movable joints: where they are and how they move; then their limits."""
    where = Table(f"Joints ({len(joints)} movable)",
                  ("joint", "type", "parent", "child", "axis", "origin xyz [m]"))
    limits = Table("Joint limits", ("joint", "lower", "upper", "velocity", "effort", "units"))
    rotated = []
    for j in joints:
        where.rows.append((j.name, j.type, j.parent, j.child, d.axis(j.axis), d.vec(j.xyz_m)))
        if any(j.rpy_rad):
            rotated.append(f"{j.name} rpy {d.vec(j.rpy_rad)} rad")
        lim = j.limits
        if lim is not None:
            units = f"{lim.units.position}, {lim.units.velocity}, {lim.units.effort}"
            limits.rows.append((j.name, lim.lower, lim.upper, lim.velocity, lim.effort, units))
        if j.mimic is not None:
            rotated.append(f"{j.name} mimics {j.mimic.joint}: x {format_number(j.mimic.multiplier)}"
                           f" + {format_number(j.mimic.offset)}")
    where = Table(where.title, where.headers, where.rows, tuple(rotated))
    return [where, limits]


def frames_tables(frames: tuple[FrameInfo, ...]) -> list[Table]:
    """Links fixed to their parent, and where they are in the root link."""
    table = Table(f"Fixed frames ({len(frames)})",
                  ("frame", "parent", "xyz [m]", "rpy [rad]", "in root at zero: xyz [m]"))
    for f in frames:
        table.rows.append((f.name, f.parent, d.vec(f.xyz_m), d.vec(f.rpy_rad), d.vec(f.root_xyz_m)))
    return [table]


def totals_tables(totals: Totals) -> list[Table]:
    """One quantity per row."""
    config = ", ".join(f"{k}={format_number(v)}" for k, v in totals.configuration_rad_or_m.items())
    at = f"at {config}" if config else "at the zero configuration"
    dof = totals.dof
    rows: list[tuple[object, ...]] = [
        ("degrees of freedom", f"{dof.total}: {dof.wheels} wheel{'s' * (dof.wheels != 1)} "
         f"+ {dof.arm} arm"
         + (f" + {dof.chassis} casters and suspension" if dof.chassis else "")),
        ("total mass", d.quantity(totals.mass_kg, "kg")),
        ("centre of mass", "-" if totals.centre_of_mass_m is None
         else f"{d.point(totals.centre_of_mass_m)} m in {totals.frame}"),
        ("bounding box (visual)", _box(totals)),
    ]
    if totals.arm is not None:
        slides = (f", its slides out by {d.quantity(totals.arm.travel_m, 'm')}"
                  if totals.arm.travel_m else "")
        rows.append(("arm reach", f"{d.quantity(totals.arm.reach_m, 'm')}, "
                     f"{totals.arm.shoulder} to {totals.arm.tip}, at most (its links end "
                     f"to end{slides})"))
    drive = totals.drive
    if drive is not None:
        rows += [("wheel radius", d.quantity(drive.wheel_radius_m, "m")),
                 ("track (wheel separation)", d.quantity(drive.track_m, "m")),
                 ("wheelbase", d.quantity(drive.wheelbase_m, "m")),
                 ("wheel velocity limit", d.quantity(drive.max_wheel_speed_rad_s, "rad/s")),
                 ("top speed", d.quantity(drive.top_speed_m_s, "m/s")),
                 ("top turn rate in place", d.quantity(drive.top_turn_rate_rad_s, "rad/s"))]
    return [Table(f"Totals ({at})", ("quantity", "value"), rows, totals.notes)]


def _box(totals: Totals) -> str:
    box = totals.bounding_box_m
    if box is None:
        return "-"
    return ", ".join(f"{axis} {d.span(lo, hi)}"
                     for axis, lo, hi in zip("xyz", box.min_m, box.max_m, strict=True)) + " m"
