r"""The floor of a collision check: where it is, which links stand on it, and its pairs.

The floor is the plane :math:`z = z_{floor}` of the root frame, with :math:`z_{floor}` the
lowest point, at the neutral configuration, of the links no bounded joint moves: the root
link and what is fixed to it, and wheels (continuous joints): on a mobile base, where the
wheels touch the ground (a fixed arm gets no floor: it may hang from a table's edge or a
wall, :func:`~servicebot_cli.kinematics.ik_session.is_mobile`). A link collides with
the floor when any of it goes lower; links that reach it at the neutral configuration stand
on it. Meshes meet the floor through their convex hull, which has the same lowest point.
For :func:`~servicebot_cli.kinematics.collisions.build_check`. Pure.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.kinematics.collision_pairs import placed

if TYPE_CHECKING:
    import pinocchio as pin

FLOOR = "floor"
"""The name a contact gives the floor."""
_ON_FLOOR_M = 1e-6  # a link this close to the floor at the neutral configuration stands on it
_FAR_BELOW_M = 1e3  # a plane this far below the robot measures its lowest point


def _heights_m(model: pin.Model, geometry: pin.GeometryModel) -> list[float]:
    """The lowest point of each object at the neutral configuration, z in the root [m].

    Measured as the distance to a plane far below, which coal computes exactly for
    primitives and meshes alike.
    """
    import pinocchio as pin

    coal = pin.coal  # shipped with Pinocchio
    placed_data = placed(model, geometry, pin.neutral(model))
    plane = coal.Halfspace(np.array([0.0, 0.0, 1.0]), -_FAR_BELOW_M)
    heights = []
    for k, obj in enumerate(geometry.geometryObjects):
        pose = placed_data.oMg[k]
        result = coal.DistanceResult()
        distance = coal.distance(obj.geometry, coal.Transform3s(pose.rotation, pose.translation),
                                 plane, coal.Transform3s(), coal.DistanceRequest(), result)
        heights.append(float(distance) - _FAR_BELOW_M)
    return heights


def grounded(model: pin.Model, geometry: pin.GeometryModel) -> dict[int, float]:
    """Objects no bounded joint moves, and their lowest point at neutral (z in the root) [m]."""
    heights = _heights_m(model, geometry)
    return {k: z for k, (obj, z) in enumerate(zip(geometry.geometryObjects, heights, strict=True))
            if all(_unbounded(model, int(j)) for j in model.supports[obj.parentJoint][1:])}


def _unbounded(model: pin.Model, joint: int) -> bool:
    """A continuous joint (a wheel), or a mobile base's own root joint."""
    shape = model.joints[joint]
    return bool(model.names[joint] == "root_joint" or (shape.nq == 2 and shape.nv == 1))


def add_floor(geometry: pin.GeometryModel, links: list[str], at_rest: dict[int, float],
              skipped: Iterable[frozenset[str]]) -> float | None:
    """Add the floor below the objects ``at_rest`` (:func:`grounded` finds them), and pairs.

    Every link is paired with the floor but those standing on it and those a ``skipped``
    pair with :data:`FLOOR` names. ``links[k]`` is object k's link; the floor and mesh hulls
    are appended to it.

    Returns:
        The floor's height in the root frame [m]; None (no floor added) when nothing is
        grounded.
    """
    floor_z = min(at_rest.values()) if at_rest else None
    if floor_z is not None:
        standing = {links[k] for k, z in at_rest.items() if z <= floor_z + _ON_FLOOR_M}
        _add_floor(geometry, links, floor_z, standing | {link for pair in skipped
                                                         if FLOOR in pair for link in pair})
    return floor_z


def _add_floor(geometry: pin.GeometryModel, links: list[str], floor_z: float,
               exempt: set[str]) -> None:
    """Add the floor, and a pair with it for every link but ``exempt`` (they stand on it)."""
    import pinocchio as pin

    count = geometry.ngeoms
    index = geometry.addGeometryObject(_floor_object(floor_z - _ON_FLOOR_M))
    links.append(FLOOR)
    for k in range(count):
        link = links[k]
        if link in exempt:
            continue
        obj = geometry.geometryObjects[k]  # fresh: adding objects moves them in memory
        shape = obj.geometry
        if hasattr(shape, "buildConvexHull") and _solid(shape):  # a mesh: its hull has the
            shape.buildConvexHull(True, "Qt")  # same lowest point
            hull = pin.GeometryObject(f"{obj.name}_hull", obj.parentJoint, obj.parentFrame,
                                      obj.placement.copy(), shape.convex)
            k = geometry.addGeometryObject(hull)
            links.append(link)
        geometry.addCollisionPair(pin.CollisionPair(k, index))


def _solid(mesh: object) -> bool:
    """Whether ``mesh``'s vertices span a volume, so that qhull can build its hull.

    A flat plate or a lone triangle (valid meshes, which check passes) made qhull fail,
    or crash the process; such a mesh meets the floor as it is.
    """
    try:
        points = np.asarray(mesh.vertices(), dtype=np.float64)  # type: ignore[attr-defined]
    except (AttributeError, TypeError, ValueError):
        return False
    if points.ndim != 2 or len(points) < 4 or not np.all(np.isfinite(points)):
        return False
    spread = points - points.mean(axis=0)
    size = float(np.abs(spread).max())
    if size == 0.0:
        return False
    return bool(np.linalg.matrix_rank(spread / size, tol=1e-9) == 3)


def _floor_object(z_m: float) -> pin.GeometryObject:
    """The half-space below ``z_m``, fixed to the root."""
    import pinocchio as pin

    plane = pin.coal.Halfspace(np.array([0.0, 0.0, 1.0]), z_m)
    return pin.GeometryObject(FLOOR, 0, 0, pin.SE3.Identity(), plane)
