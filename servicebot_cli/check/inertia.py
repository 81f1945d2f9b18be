"""Inertia rules: masses, physically possible inertias, agreement with geometry (SB301-SB309)."""

from __future__ import annotations

import math
from collections.abc import Generator, Iterator
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.check import inertia_bound, solids, values
from servicebot_cli.check.env import CheckEnv, MeshError, MeshNotFound
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.geometry import LARGEST_M, SMALLEST_M
from servicebot_cli.check.simulators import simulated_by
from servicebot_cli.kinematics.transforms import rpy_matrix

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from servicebot_cli.check.meshes import MeshInfo
    from servicebot_cli.description.elements import Link, Shape
    from servicebot_cli.description.robot import RobotDescription


def _mass(link: Link) -> float:
    mass = link.inertial.mass_kg if link.inertial else None
    return mass if mass is not None and math.isfinite(mass) and mass > 0 else 0.0


def check(robot: RobotDescription, env: CheckEnv) -> Iterator[Issue]:
    """Every inertia issue of ``robot``."""
    moved = {joint.child for joint in robot.joints if joint.movable}
    alone = moved - _given_inertia_by_fixed_children(robot)
    mujoco = _mujoco_reading(robot)
    for link in robot.links:
        inertial = link.inertial
        if inertial is None:
            continue
        if inertial.mass_kg is not None and inertial.mass_kg < 0:
            yield Issue("SB302", f"link '{link.name}' has mass {inertial.mass_kg:g} kg",
                        inertial.element)
            continue
        moments = inertial.inertia_kg_m2
        huge = _beyond_any_robot(inertial.mass_kg, moments)
        if huge is not None:
            yield Issue("SB311", f"link '{link.name}' has {huge}, beyond the "
                        f"{values.LARGEST_INERTIA:g} of any robot: the dynamics computed "
                        "with it overflow or lose the other links", inertial.element,
                        fix="write the link's mass in kg and its inertia in kg m^2")
            continue
        if (moments is None or not values.bounded(moments, values.LARGEST_INERTIA)
                or not values.plain_numbers(inertial.element)):
            continue  # SB012/SB013/SB014 report it
        if inertial.mass_kg == 0.0 and any(moments):
            yield _inertia_without_mass(link.name, inertial.element, link.name == robot.root_link)
            continue
        physical = yield from _possible(link, moments, link.name in moved,
                                        link.name in alone, mujoco)
        if physical and _mass(link) > 0 and values.bounded((_mass(link),), values.LARGEST_INERTIA):
            yield from _against_geometry(robot, link, env)
    yield from _moving_masses(robot)
    root = robot.root_link
    if root is not None and _mass(robot.link(root)) > 0:
        link = robot.link(root)
        yield Issue("SB309", f"root link '{root}' carries {_mass(link):g} kg; KDL-based tools "
                    "(robot_state_publisher) ignore a root link's inertia", link.element,
                    fix="add a massless root link (base_footprint) with a fixed joint to it, "
                    "if KDL users matter")


def _beyond_any_robot(mass_kg: float | None,
                      moments: tuple[float, ...] | None) -> str | None:
    """``mass 1e+308 kg`` or ``ixx 1e+13 kg m^2``: a finite value no robot's link has."""
    if mass_kg is not None and math.isfinite(mass_kg) and mass_kg > values.LARGEST_INERTIA:
        return f"mass {mass_kg:g} kg"
    for name, value in zip(("ixx", "ixy", "ixz", "iyy", "iyz", "izz"), moments or (),
                           strict=False):
        if math.isfinite(value) and abs(value) > values.LARGEST_INERTIA:
            return f"{name} {value:g} kg m^2"
    return None


def _inertia_without_mass(name: str, element: ET.Element | None, root: bool) -> Issue:
    """SB310; a warning for the root link, which pybullet's mass 0 makes a fixed base."""
    if root:  # cartpole.urdf, kuka_iiwa/model.urdf: every consumer loads them as written
        return Issue("SB310", f"root link '{name}' has mass 0 and a non-zero inertia: "
                     "pybullet reads mass 0 as a base fixed to the world, and a fixed base's "
                     "inertia moves nothing; a base that moves needs its mass", element,
                     fix="give the link its real mass if the robot is not fixed to the world",
                     severity=Severity.WARNING)
    return Issue("SB310", f"link '{name}' has mass 0 and a non-zero inertia", element,
                 fix="give the link its real mass, or zero the inertia (or remove the "
                 "<inertial>) for a massless frame")


def _given_inertia_by_fixed_children(robot: RobotDescription) -> set[str]:
    """Links a fixed joint (through fixed joints) joins to a child with inertia.

    Gazebo (sdformat) and MuJoCo lump such a child into the link: the body they simulate
    has the child's inertia, whatever the link's own.
    """
    children: dict[str, list[str]] = {}
    for joint in robot.joints:
        if joint.type == "fixed" and joint.parent and joint.child:
            children.setdefault(joint.parent, []).append(joint.child)
    links = robot.links_by_name

    def has_inertia(name: str) -> bool:
        inertial = links[name].inertial if name in links else None
        moments = inertial.inertia_kg_m2 if inertial is not None else None
        return bool(moments) and any(m != 0 for m in moments or ())

    given: set[str] = set()
    for top in children:
        stack, seen = list(children[top]), {top}
        while stack:
            name = stack.pop()
            if name in seen:
                continue
            seen.add(name)
            if has_inertia(name):
                given.add(top)
                break
            stack.extend(children.get(name, ()))
    return given


_MJ_MINVAL = 1e-15
"""MuJoCo's mjMINVAL: an inertia eigenvalue below it is refused [kg m^2]."""


@dataclass(frozen=True)
class _MujocoReading:
    """How MuJoCo reads this file's inertias.

    Attributes:
        meant: The file is meant for MuJoCo: a ``<mujoco>`` block (MuJoCo's own URDF
            extension) or a MuJoCo ros2_control plugin.
        bound: Its ``<compiler boundinertia>``: smaller principal moments are raised to it.
        balance: Its ``<compiler balanceinertia="true">``: A + B >= C is made to hold.
    """

    meant: bool = False
    bound: float = 0.0
    balance: bool = False

    def refuses(self, moments: np.ndarray) -> str | None:
        """MuJoCo's words refusing principal ``moments`` (ascending), or None: it takes them."""
        raised = np.maximum(moments, self.bound)
        scale = float(np.abs(raised).max())
        if raised[0] < max(_MJ_MINVAL, 1e-14 * scale):  # its eigenvalues, past rounding
            return "inertia must have positive eigenvalues"
        if raised[0] + raised[1] < raised[2] and not self.balance:
            return "inertia must satisfy A + B >= C"
        return None


def _mujoco_reading(robot: RobotDescription) -> _MujocoReading:
    """What the file tells MuJoCo of inertias (:class:`_MujocoReading`)."""
    bound, balance = 0.0, False
    for compiler in robot.root.iterfind("mujoco/compiler"):
        try:
            bound = max(bound, float(compiler.get("boundinertia") or 0.0))
        except ValueError:
            pass
        balance = balance or (compiler.get("balanceinertia") or "").strip() == "true"
    meant = robot.root.find("mujoco") is not None or simulated_by(robot) == "MuJoCo"
    return _MujocoReading(meant, bound if math.isfinite(bound) else 0.0, balance)


def _possible(link: Link, values: tuple[float, ...], moving: bool, alone: bool = False,
              mujoco: _MujocoReading = _MujocoReading()) -> Generator[Issue, None, bool]:
    """SB306-SB308; returns True when the inertia is a real body's.

    A zero principal moment is an idealisation (a thin rod: 0, I, I) that Gazebo and
    Pinocchio take and MuJoCo refuses on any link: a warning naming MuJoCo, an error in a
    file meant for MuJoCo (``mujoco``, :func:`_mujoco_reading`); two of them (0, 0, I) are
    no body at all, which MuJoCo refuses (fetch's gripper fingers): an error on a link a
    joint moves. A point mass (mass, no inertia) is an error on a link a joint moves
    ``alone`` (no fixed child with inertia lumped into it): MuJoCo refuses it. A link
    fixed to others (anymal's dummy ``base``) is lumped with
    them by Gazebo (sdformat) and Pinocchio, so only the sum has to be a body: a warning there.
    """
    moments = solids.principal_moments(values)
    scale = float(np.abs(moments).max())
    shown = ", ".join(f"{m:.6g}" for m in moments)
    element = link.inertial.element if link.inertial else None
    if scale <= 1e-15:  # all zero, up to rounding in the file
        if _mass(link) > 0 and alone:  # laikago's hip motors: MuJoCo refuses the robot
            yield Issue("SB307", f"link '{link.name}' has mass {_mass(link):g} kg and zero "
                        "inertia (a point mass), and a joint moves it: MuJoCo refuses a "
                        "moving body without inertia ('mass and inertia of moving bodies must "
                        "be larger than mjMINVAL')", element, severity=Severity.ERROR,
                        fix="give the link the inertia of its shape")
        elif _mass(link) > 0:
            yield Issue("SB307", f"link '{link.name}' has mass {_mass(link):g} kg and zero "
                        "inertia (a point mass)", element)
        return False
    if moments[0] < -1e-9 * scale:
        yield Issue("SB306", f"link '{link.name}' inertia is not positive definite: principal "
                    f"moments {shown} kg m^2", element)
        return False
    degenerate = moments[0] <= 1e-9 * scale
    if moments[0] + moments[1] < moments[2] * (1 - 1e-6) and (moving or not degenerate):
        yield Issue("SB308", f"link '{link.name}' principal moments {shown} kg m^2 break the "
                    f"triangle inequality: {moments[0]:.6g} + {moments[1]:.6g} < "
                    f"{moments[2]:.6g}", element)
        return False
    if moments[0] + moments[1] < moments[2] * (1 - 1e-12) and (moving or not degenerate):
        # within rounding of the file's numbers, but MuJoCo tests A + B >= C exactly
        yield Issue("SB308", f"link '{link.name}' principal moments {shown} kg m^2 miss the "
                    f"triangle inequality by {moments[2] - moments[0] - moments[1]:.2g}: "
                    "rounding for Gazebo and Pinocchio, but MuJoCo refuses the robot ('inertia "
                    "must satisfy A + B >= C')", element, severity=Severity.WARNING,
                    fix=f"round {moments[2]:.6g} down, or set <compiler balanceinertia=\"true\"/>"
                    " in the file's <mujoco> block")
        return False
    if degenerate:
        if _mass(link) > 0:
            said = f"link '{link.name}' inertia has a zero principal moment ({shown} kg m^2)"
            refusal = mujoco.refuses(moments)
            if refusal is None:  # past MuJoCo's rounding, or raised by the file's compiler
                yield Issue("SB307", said, element, fix="give it a small moment about that axis")
            else:
                raised = (f"MuJoCo raises it to its boundinertia {mujoco.bound:g} and then "
                          "refuses" if mujoco.bound else "MuJoCo refuses")
                yield Issue("SB307", f"{said}: Gazebo and Pinocchio take it, {raised} the "
                            f"robot ('{refusal}')", element,
                            severity=Severity.ERROR if mujoco.meant else Severity.WARNING,
                            fix="give it a small moment about that axis (1e-6 kg m^2), or set "
                            "<compiler boundinertia=\"1e-6\" balanceinertia=\"true\"/> in the "
                            "file's <mujoco> block")
        return False
    return True


_PLACEHOLDER_M3 = 1e-6
"""Collision geometry this small (1 cm^3) may stand in for a body it does not describe..."""
_DENSEST_KG_M3 = 1e5
_METAL_KG_M3 = 3e4
"""Denser than osmium (22,590 kg/m^3): no part of a robot is."""
"""...when the link's mass in it would be denser than any material (osmium: 22,590 kg/m^3):
then the visual geometry, where its volume is known, stands for the body."""


def _expected(robot: RobotDescription, link: Link, env: CheckEnv,
              shapes: tuple[Shape, ...]) -> solids.Solid | None:
    """The link's ``shapes`` (its collisions, or visuals) as one solid; None: not known."""
    parts = []
    for shape in shapes:
        if not values.usable_shape(shape):
            return None  # SB012-SB014 and SB405 report it
        geometry = shape.geometry
        found = solids.primitive(geometry)
        if found is not None:
            volume, moment, label = found
            parts.append(solids.placed(volume, np.zeros(3), moment, (1, 1, 1), shape.origin, label))
            continue
        if geometry.kind != "mesh" or not env.load_meshes:
            return None
        try:
            info = env.mesh(robot, shape, with_mass=True)
        except (MeshNotFound, MeshError):
            return None
        if info.mass is None or not info.mass.volume > 0 or _unit_in_doubt(info, geometry.scale):
            return None
        parts.append(solids.placed(info.mass.volume, np.array(info.mass.centroid),
                                   info.mass.second_moment, geometry.scale, shape.origin,
                                   f"closed mesh '{geometry.filename}'"))
    kind = "visual" if shapes is link.visuals and shapes else "collision"
    return solids.combined(parts, kind) if parts else None


def _unit_in_doubt(info: MeshInfo, scale: tuple[float, float, float]) -> bool:
    """Whether SB404 doubts the mesh's unit (100 m across: millimetres?).

    Its mass properties, in the wrong unit, would make SB301's fix a million times off (a
    100 mm cube exported from Fusion in millimetres, unscaled): SB404 says what to fix.
    """
    extent_m = max(abs(hi - lo) * abs(s) for lo, hi, s in zip(info.lower, info.upper, scale,
                                                                 strict=True))
    return extent_m > LARGEST_M or (0 < extent_m < SMALLEST_M and any(s != 1.0 for s in scale))


def _against_geometry(robot: RobotDescription, link: Link, env: CheckEnv) -> Iterator[Issue]:
    inertial = link.inertial
    if inertial is None or inertial.inertia_kg_m2 is None or not values.usable_pose(
            inertial.origin):
        return
    solid = _expected(robot, link, env, link.collisions)
    if solid is None or not solids.usable(solid):
        yield from _beyond_reach(robot, link, env)
        return
    mass = _mass(link)
    have = solids.principal_moments(inertial.inertia_kg_m2)
    found = _mismatch(have, solid, mass, env.inertia_factor)
    if found is None:
        if mass > _METAL_KG_M3 * solid.volume_m3 and not _placeholder(solid, mass):
            yield _both_in_grams(link, solid, mass)  # the inertia made from the same mass
        return
    if _placeholder(solid, mass) and link.visuals:  # baxter_simple's 1 mm collision spheres
        visual = _expected(robot, link, env, link.visuals)
        if visual is None or not solids.usable(visual):
            return  # nothing known of the body: its visual mesh is open
        if _placeholder(visual, mass):  # drawn as small: the body is, and the inertia wrong
            yield _issue(link, have, solid, mass, found)
            return
        found = _mismatch(have, visual, mass, env.inertia_factor)
        if found is None:
            return
        solid = replace(visual, label=f"{visual.label} (the visual geometry; the collision "
                        f"geometry, {solid.label}, is a placeholder)")
    if mass > _METAL_KG_M3 * solid.volume_m3 and _mismatch(
            have, solid, mass / 1000, env.inertia_factor) is None:  # the mass is in grams
        yield _in_grams(link, solid, mass)
        return
    yield _issue(link, have, solid, mass, found)


def _beyond_reach(robot: RobotDescription, link: Link, env: CheckEnv) -> Iterator[Issue]:
    """SB301 for an inertia beyond any the mass can have within the link's shapes.

    For a link whose solid is not known (an open mesh): :mod:`.inertia_bound`.
    """
    inertial = link.inertial
    assert inertial is not None and inertial.inertia_kg_m2 is not None
    reach = inertia_bound.farthest_m(robot, link, env, np.array(inertial.origin.xyz, float))
    mass = _mass(link)
    if reach is None or not reach > 0:
        return
    have = solids.principal_moments(inertial.inertia_kg_m2)
    most = mass * reach * reach
    if not (math.isfinite(most) and most > 0) or not have.max() > inertia_bound.BEYOND * most:
        return
    yield Issue("SB301", f"link '{link.name}' inertia (principal moments {_join(have)} kg m^2) "
                f"is more than {mass:g} kg can have within its shapes: none of them reaches "
                f"over {reach:.3g} m from its centre of mass, so no moment exceeds "
                f"{most:.3g} kg m^2, and it is {have.max() / most:.3g} times that",
                inertial.element, fix="compute the inertia from the link's real shape and mass")


def _in_grams(link: Link, solid: solids.Solid, mass: float) -> Issue:
    """SB301 for a mass in grams: the inertia fits a thousandth of it (mp_400's wheels)."""
    inertial = link.inertial
    assert inertial is not None
    return Issue("SB301", f"link '{link.name}' mass {mass:g} kg makes its {solid.label} "
                 f"{mass / solid.volume_m3:.3g} kg/m^3, denser than any metal, and its inertia "
                 f"fits {mass / 1000:g} kg: is the mass in grams?", inertial.element,
                 fix=f'mass value="{mass / 1000:g}"')


def _both_in_grams(link: Link, solid: solids.Solid, mass: float) -> Issue:
    """SB301 for a mass in grams whose inertia was computed from it: both 1000 times over.

    articubot_one's wheel of 0.05 kg written 50, its inertia from the usual cylinder macro:
    the two agree, and only the density (25 times osmium's) tells the unit.
    """
    inertial = link.inertial
    assert inertial is not None
    return Issue("SB301", f"link '{link.name}' mass {mass:g} kg makes its {solid.label} "
                 f"{mass / solid.volume_m3:.3g} kg/m^3, denser than any metal, and its inertia "
                 f"fits that mass: are both in grams (the inertia computed from it)?",
                 inertial.element, fix=f'mass value="{mass / 1000:g}", and the inertia a '
                 "thousandth of what it is")


def _issue(link: Link, have: np.ndarray, solid: solids.Solid, mass: float,
           found: tuple[np.ndarray, np.ndarray, np.ndarray, float]) -> Issue:
    """SB301: the inertia ``have`` against ``mass`` filling ``solid``, as ``found`` differ."""
    inertial = link.inertial
    assert inertial is not None  # (compared only with one)
    expected, want, ratios, worst = found
    rotation = rpy_matrix(*inertial.origin.rpy)
    local = rotation.T @ expected @ rotation  # the geometry's inertia in the inertial's axes
    direction = "too large" if ratios.max() >= 1.0 / ratios.min() else "too small"
    return Issue(
        "SB301",
        f"link '{link.name}' inertia (principal moments {_join(have)} kg m^2) does not match a "
        f"{mass:g} kg {solid.label} ({_join(want)} kg m^2): up to {worst:.3g} times {direction}",
        inertial.element,
        fix=f"use {_components(local)}",
    )


def _mismatch(have: np.ndarray, solid: solids.Solid, mass: float, factor: float
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, float] | None:
    """How the principal moments ``have`` differ from those of ``mass`` filling ``solid``.

    The solid's inertia, its principal moments, the ratios and the worst of them; None when
    they agree within ``factor``, or when no number can state it (a flat solid, a mass of
    1e-320 kg: SB30x reports such a mass).
    """
    expected = solids.inertia_of(solid, mass)
    if not np.all(np.isfinite(expected)):
        return None
    want = np.linalg.eigvalsh(expected)
    if not want.min() > 0:
        return None
    with np.errstate(all="ignore"):  # moments beyond a double's range
        ratios = have / want
        worst = float(max(ratios.max(), 1.0 / ratios.min()))
    if not math.isfinite(worst) or worst <= factor:
        return None
    return expected, want, ratios, worst


def _placeholder(solid: solids.Solid, mass: float) -> bool:
    """Whether ``solid`` is too small to be the body: under 1 cm^3, denser than any material."""
    return solid.volume_m3 <= _PLACEHOLDER_M3 and mass > _DENSEST_KG_M3 * solid.volume_m3


def _join(values: np.ndarray) -> str:
    return ", ".join(f"{v:.6g}" for v in values)


def _components(matrix: np.ndarray) -> str:
    diagonal = f"ixx={matrix[0, 0]:.6g} iyy={matrix[1, 1]:.6g} izz={matrix[2, 2]:.6g}"
    # a product of inertia a hundred-thousandth of the largest term is rounding (the sums',
    # or a right angle written 1.5708): its axes turn by less than that many radians; 0
    noise = 1e-5 * abs(matrix).max()
    off = {k: 0.0 if abs(v) <= noise else v
           for k, v in (("ixy", matrix[0, 1]), ("ixz", matrix[0, 2]), ("iyz", matrix[1, 2]))}
    if not any(off.values()):
        return diagonal + " (ixy=ixz=iyz=0)"
    return diagonal + " " + " ".join(f"{k}={v:.6g}" for k, v in off.items())


def _moving_masses(robot: RobotDescription) -> Iterator[Issue]:
    """SB303-SB305: what a moving joint moves must have mass; fixed frames may be massless."""
    by_name = {link.name: link for link in robot.links}
    below: dict[str, list[str]] = {}
    fixed_below: dict[str, list[str]] = {}  # the links fixed to each: lumped with it
    kept = robot.kept_apart
    for joint in robot.joints:
        if joint.parent in by_name and joint.child in by_name:
            below.setdefault(joint.parent or "", []).append(joint.child or "")
            if joint.type == "fixed" and joint.name not in kept:
                fixed_below.setdefault(joint.parent or "", []).append(joint.child or "")
    carried = _subtree_masses(by_name, below)
    simulator = simulated_by(robot)
    for joint in robot.joints:  # sdformat does not lump these: each child is a body
        link = by_name.get(joint.child or "")
        if joint.type == "fixed" and joint.name in kept and link is not None and \
                _lumped_mass(link.name, by_name, fixed_below) == 0.0:
            yield Issue("SB304", f"link '{link.name}' hangs from fixed joint '{joint.name}', "
                        f"which <{kept[joint.name]}> keeps a body of its own, and has no "
                        "mass: Gazebo drops it, and every link below it", link.element,
                        fix="add an <inertial>, or let Gazebo lump the joint",
                        severity=Severity.ERROR)
    for joint in robot.joints:
        link = by_name.get(joint.child or "")
        if not joint.movable or link is None:
            continue
        if carried[link.name] == 0.0:
            target = (f"; {simulator} needs mass on every moving link" if simulator
                      else " (fine for kinematics only: no <gazebo> or simulator plugin here)")
            yield Issue("SB303", f"{joint.type} joint '{joint.name}' moves link '{link.name}', "
                        f"and nothing it carries has mass{target}", link.element,
                        fix="add an <inertial> with the link's real mass and inertia",
                        severity=Severity.ERROR if simulator else Severity.WARNING)
        elif _lumped_mass(link.name, by_name, fixed_below) > 0.0:
            continue  # links fixed to it lend it their mass: sdformat and Pinocchio merge them
        elif link.inertial is None:  # sdformat drops it, and what hangs below it
            dropped = ("" if not simulator else "; MuJoCo refuses a moving body without mass"
                       if simulator == "MuJoCo" else
                       f"; {simulator} drops it, and every link below it")
            yield Issue("SB304", f"link '{link.name}' is moved by joint '{joint.name}' but has "
                        f"no <inertial>{dropped}", link.element, fix="add an <inertial>",
                        severity=Severity.ERROR if simulator else None)
        elif _mass(link) == 0.0 and link.inertial.mass_kg == 0.0:
            yield Issue("SB305", f"link '{link.name}' is moved by joint '{joint.name}' and has "
                        "mass 0", link.inertial.element, fix="give the link its real mass")


def _lumped_mass(name: str, by_name: dict[str, Link], fixed_below: dict[str, list[str]]) -> float:
    """Mass of link ``name`` and of the links fixed to it (through fixed joints only)."""
    total, seen, stack = 0.0, set(), [name]
    while stack:  # iterative, and safe on loops
        current = stack.pop()
        if current in seen:
            continue
        seen.add(current)
        total += _mass(by_name[current])
        stack.extend(fixed_below.get(current, ()))
    return total


def _subtree_masses(by_name: dict[str, Link], below: dict[str, list[str]]) -> dict[str, float]:
    """Mass of each link plus everything below it, in one iterative post-order pass."""
    carried: dict[str, float] = {}
    for start in by_name:
        if start in carried:
            continue
        stack = [(start, False)]
        while stack:  # iterative, and safe on loops (a link on a loop is counted once)
            name, children_done = stack.pop()
            if children_done:
                carried[name] = _mass(by_name[name]) + sum(
                    carried.get(c, 0.0) for c in below.get(name, ()) if c != name)
                continue
            if name in carried:
                continue
            carried[name] = 0.0  # placeholder: marks the link as being visited
            stack.append((name, True))
            stack.extend((c, False) for c in below.get(name, ()) if c not in carried)
    return carried
