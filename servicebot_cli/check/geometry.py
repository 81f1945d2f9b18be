"""Geometry rules: shapes known and positive, mesh files found, loadable and of plausible size.

SB401-SB407. Mesh references resolve as in ``expand`` (relative to the file that wrote
them, ``file://``, ``package://`` through the package search); each file is read once.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check import mesh_elsewhere, values
from servicebot_cli.check.env import CheckEnv, MeshError, MeshNotFound, RemoteMesh, case_twin
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.packages import FileTally
from servicebot_cli.check.syntax import urdf_version

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Link, Shape
    from servicebot_cli.description.robot import RobotDescription

SHAPES = ("box", "cylinder", "sphere", "mesh")
LARGEST_M = 20.0
"""A mesh wider than this [m] is reported as implausibly large (SB404)."""
SMALLEST_M = 0.001
"""A mesh narrower than this [m] is reported as implausibly small (SB404)."""


def check(robot: RobotDescription, env: CheckEnv) -> Iterator[Issue]:
    """Every geometry issue of ``robot``; missing packages once per package (SB408)."""
    tally = FileTally()
    for link in robot.links:
        for kind, shapes in (("visual", link.visuals), ("collision", link.collisions)):
            for shape in shapes:
                yield from _shape(robot, link, kind, shape, env, tally)
    yield from tally.issues()


def _capsule(robot: RobotDescription, where: str, capsule: ET.Element) -> Issue:
    """SB407: urdfdom reads a capsule only in a ``<robot version="1.1">`` or later."""
    version = urdf_version(robot.root)
    if version is not None and version >= (1, 1):
        return Issue("SB407", f"the {where} is a capsule: urdfdom (ROS 2) and Pinocchio read "
                     f"it in this URDF {version[0]}.{version[1]} file, older URDF readers drop "
                     "the shape", capsule,
                     fix="a cylinder and two spheres, for tools without URDF 1.1")
    return Issue("SB407", f"the {where} is a capsule, which urdfdom reads only from URDF 1.1 "
                 "on: here it drops the whole element, and Pinocchio and Gazebo lose it",
                 capsule, severity=Severity.ERROR,
                 fix='<robot version="1.1">, or a cylinder and two spheres')


def _shape(robot: RobotDescription, link: Link, kind: str, shape: Shape,
           env: CheckEnv, tally: FileTally) -> Iterator[Issue]:
    element = shape.element.find("geometry") if shape.element is not None else None
    if element is None:
        return  # SB012 reports a missing <geometry>
    found = [c for c in element if isinstance(c.tag, str)]
    where = f"{kind} of link '{link.name}'"
    if not found or found[0].tag not in (*SHAPES, "capsule"):
        what = f"<{found[0].tag}>" if found else "nothing"
        yield Issue("SB406", f"the geometry of the {where} holds {what}; use box, cylinder, "
                    "sphere or mesh", element)
        return
    if found[0].tag == "capsule":
        yield _capsule(robot, where, found[0])
        return
    yield from _sizes(found[0], where, visual=kind == "visual")
    if found[0].tag == "mesh" and shape.geometry.filename and env.resolve_meshes:
        yield from _mesh(robot, shape, found[0], where, env, tally)


def _sizes(element: ET.Element, where: str, visual: bool = False) -> Iterator[Issue]:
    """SB405: zero or negative sizes, a zero scale.

    A visual of zero size (upkie_description's ``<box size="0 0 0"/>`` marking a virtual
    link, a frame) draws nothing, and every consumer reads it (MuJoCo drops URDF visuals,
    Pinocchio keeps an empty box): a warning. A collision of zero size MuJoCo refuses.
    """
    for key in ("size", "radius", "length", "scale"):
        values = []
        for text in (element.get(key) or "").split():
            try:
                values.append(float(text))
            except ValueError:
                return  # SB013 reports it
        bad = [v for v in values if math.isfinite(v) and (v == 0 if key == "scale" else v <= 0)]
        if bad and visual and key != "scale" and not any(bad):
            yield Issue("SB405", f"<{element.tag} {key}=\"{element.get(key)}\"> of the {where}: "
                        "a visual of zero size draws nothing (a collision this size MuJoCo "
                        "refuses)", element, severity=Severity.WARNING)
        elif bad:
            yield Issue("SB405", f"<{element.tag} {key}=\"{element.get(key)}\"> of the {where}: "
                        "sizes must be positive" + (" (scale 0 flattens it)" if key == "scale"
                                                    else ""), element)


def _missing_fix(robot: RobotDescription, shape: Shape, exc: MeshNotFound,
                 env: CheckEnv) -> str:
    """What to write for a mesh file that is not where its reference leads."""
    filename = shape.geometry.filename or ""
    if "$(" in filename:  # xacro's, in a file xacro does not expand
        return ("name the file .urdf.xacro, so that xacro expands it, or write the path as "
                "package://PKG/...")
    twin = case_twin(exc.resolved.path) if exc.resolved.path is not None else None
    if twin:
        return f"write '{twin}' as the file is named, or rename the file"
    elsewhere = None if exc.resolved.package is not None else mesh_elsewhere.package_uri(
        filename, env.directory_of(robot, shape), env.resolver.explicit)
    if elsewhere:
        return (f"write {elsewhere}: a package of this workspace holds it, and ROS finds it on "
                "every machine")
    if mesh_elsewhere.is_windows_path(filename):
        return "write it as package://PKG/... from the package that holds it"
    return "fix the path: the package or directory holds no such file"


def _mesh(robot: RobotDescription, shape: Shape, element: ET.Element, where: str,
          env: CheckEnv, tally: FileTally) -> Iterator[Issue]:
    try:
        path = env.mesh_path(robot, shape)
        info = env.meshes.get(path) if env.load_meshes else None
    except RemoteMesh:
        tally.remote.append((shape.geometry.filename or "", element))
        return
    except MeshNotFound as exc:
        if exc.resolved.path is None and exc.resolved.package is None:  # foo://
            yield Issue("SB401", f"{where}: {exc}", element,
                        fix="write the mesh as package://PKG/..., file:// or a path relative "
                        "to the file")
            return
        if exc.resolved.path is None:
            tally.add_missing(exc.resolved, element, where, shape.geometry.filename or "")
            return
        filename = shape.geometry.filename or ""
        windows = mesh_elsewhere.is_windows_path(filename)
        said = (f"{where}: mesh '{filename}' is a Windows path, which names no file elsewhere"
                if windows else f"{where}: {exc}")
        missing = Issue("SB401", said, element, fix=_missing_fix(robot, shape, exc, env))
        if not tally.guessed_wrong(exc.resolved, element, missing):
            tally.add_found(exc.resolved, element)
            yield missing
        return
    except MeshError as exc:
        lfs = "git lfs pull" in str(exc)
        yield Issue("SB402", f"{where}: mesh '{shape.geometry.filename}' cannot be loaded: {exc}",
                    element, fix="run 'git lfs pull' in the repository that holds it" if lfs
                    else None)
        return
    tally.add_found(env.resolve(robot, shape), element)
    if info is None:  # only where it leads was asked for
        return
    if info.triangles == 0:
        yield Issue("SB403", f"{where}: mesh '{shape.geometry.filename}' has no triangles",
                    element)
        return
    scale = shape.geometry.scale
    if not values.plain_numbers(element) or not values.finite(scale) or not all(scale):
        return  # SB013, SB014 and SB405 report such a scale
    extent_m = max(abs(hi - lo) * abs(s) for lo, hi, s in zip(info.lower, info.upper, scale,
                                                                  strict=True))
    name = shape.geometry.filename
    if extent_m == 0:  # as a <box size="0 0 0">: a visual draws nothing, MuJoCo refuses a
        visual = where.startswith("visual")  # collision of no size
        unit = " (or its <unit meter> is 0)" if (name or "").lower().endswith(".dae") else ""
        yield Issue("SB405", f"{where}: mesh '{name}' has no size: every vertex is at one "
                    f"point{unit}" + (
                        "; a visual of zero size draws nothing" if visual else ""), element,
                    severity=Severity.WARNING if visual else None)
    elif extent_m > LARGEST_M and not _scenery(robot):
        yield Issue("SB404", f"{where}: mesh '{name}' is {extent_m:.4g} m across; is it in "
                    "millimetres?", element, fix=_scale_fix(scale, 0.001))
    elif 0 < extent_m < SMALLEST_M and any(s != 1.0 for s in scale):
        yield Issue("SB404", f"{where}: mesh '{name}' is {extent_m:.3g} m across; is a "
                    "millimetre scale applied to a mesh already in metres?", element,
                    fix=_scale_fix(scale, 1000.0))
    elif 0 < extent_m < SMALLEST_M:  # no scale: a part that small (unitree's fingertip marks)
        yield Issue("SB404", f"{where}: mesh '{name}' is {extent_m:.3g} m across, unscaled; "
                    "is its file in metres?", element,
                    fix="export the mesh in metres, if the part is not that small")


def _scenery(robot: RobotDescription) -> bool:
    """A single link without mass: a ground plane or a scene, of any size.

    pybullet's plane.urdf and samurai.urdf and solo's plane load as static bodies.
    """
    if len(robot.links) != 1:
        return False
    inertial = robot.links[0].inertial
    return inertial is None or not inertial.mass_kg


def _scale_fix(scale: tuple[float, float, float], factor: float) -> str:
    return 'scale="' + " ".join(f"{s * factor:g}" for s in scale) + '"'
