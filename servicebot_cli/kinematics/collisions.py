r"""Does a configuration put links of the robot into each other, or into the floor?

The URDF's ``<collision>`` geometry goes into a Pinocchio ``GeometryModel`` (coal does the
tests). Pairs that can never tell anything are left out, as MoveIt's setup assistant does:

- links fixed to one another (one Pinocchio body), and adjacent links (a URDF joint's parent
  and child), which touch where they are joined;
- pairs that touch at every one of :data:`SAMPLES` random configurations within the limits
  (a fixed seed: the same pairs every run), "always in collision";
- pairs an SRDF names in ``<disable_collisions>``.

The floor is the plane :math:`z = z_{floor}` of the root frame, with :math:`z_{floor}` the
lowest point, at the neutral configuration, of the links no bounded joint moves: the root
link and what is fixed to it, and wheels (continuous joints). On a mobile base that is where
the wheels touch the ground; on a fixed arm, the plane it is mounted on. A link collides with
the floor when any of it goes lower; links that reach it at the neutral configuration stand
on it. Meshes meet the floor through their convex hull, which has the same lowest point.
Pure: a model, geometry and configurations in; contacts out.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import ServicebotError

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]

FLOOR = "floor"
"""The name a contact gives the floor."""
SAMPLES = 200
"""Random configurations that decide which pairs always touch."""
_SAMPLE_SEED = 0
_ON_FLOOR_M = 1e-6  # a link this close to the floor at the neutral configuration stands on it
_FAR_BELOW_M = 1e3  # a plane this far below the robot measures its lowest point


class CollisionSetupError(ServicebotError):
    """The collision geometry cannot be read (a mesh that does not load)."""


@dataclass(frozen=True)
class Contact:
    """Two things that intersect: links, or a link and the floor.

    Attributes:
        first: A link.
        second: Another link, or :data:`FLOOR`.
    """

    first: str
    second: str

    def __str__(self) -> str:
        """``'arm_link3' and 'base_link'``, or ``'arm_link3' and the floor``."""
        other = "the floor" if self.second == FLOOR else f"'{self.second}'"
        return f"'{self.first}' and {other}"


class CollisionCheck:
    """The pairs worth checking on one model, and the check itself.

    Attributes:
        pairs: The link pairs checked (the floor as :data:`FLOOR`), in check order.
        floor_z_m: Height of the floor in the root frame [m]; None without a floor.
    """

    def __init__(self, model: pin.Model, geometry: pin.GeometryModel, links: Sequence[str],
                 floor_z_m: float | None) -> None:
        """Check ``geometry``'s collision pairs; ``links[k]`` is object k's link."""
        import pinocchio as pin

        self._pin = pin
        self._model, self._data = model, model.createData()
        self._geometry, self._geometry_data = geometry, pin.GeometryData(geometry)
        self._links = tuple(links)
        self.floor_z_m = floor_z_m
        self.pairs = tuple((self._links[p.first], self._links[p.second])
                           for p in geometry.collisionPairs)

    @property
    def geometry(self) -> pin.GeometryModel:
        """The objects checked: the collision geometry, mesh hulls and the floor (read only)."""
        return self._geometry

    def contact(self, q: FloatArray) -> Contact | None:
        """The first pair that intersects at ``q`` (full configuration); None: none does."""
        pin = self._pin
        if not self.pairs:
            return None
        model, data, geometry, geometry_data = (self._model, self._data, self._geometry,
                                                self._geometry_data)
        pin.updateGeometryPlacements(model, data, geometry, geometry_data, q)
        for k in range(len(self.pairs)):
            if pin.computeCollision(geometry, geometry_data, k):
                return Contact(*self.pairs[k])
        return None


def build_check(robot: RobotDescription, model: pin.Model, resolver: PackageResolver, *,
                disabled: Iterable[tuple[str, str]] = (), floor: bool = True,
                moving: Collection[str] | None = None, samples: int = SAMPLES
                ) -> CollisionCheck:
    """The collision check of ``robot`` on ``model`` (fixed or planar base).

    Args:
        robot: The description (its ``<collision>`` elements and joint tree).
        model: A Pinocchio model of it.
        resolver: Finds ``package://`` meshes.
        disabled: Link pairs never to check (an SRDF's ``<disable_collisions>``).
        floor: Also check every link against the floor.
        moving: Check only pairs these joints move relative to each other (IK's chain:
            the fingers of a closed gripper touch, but no arm joint changes that); None:
            every pair.
        samples: Random configurations that decide which pairs always touch.

    Raises:
        CollisionSetupError: A collision mesh that cannot be read.
        PackageNotFound: A mesh in a package that is nowhere.
    """
    import pinocchio as pin

    geometry = _geometry(robot, model, resolver)
    links = [model.frames[o.parentFrame].name for o in geometry.geometryObjects]
    grounded = _grounded(model, geometry) if floor else {}
    skip: set[frozenset[str]] = {frozenset((j.parent, j.child)) for j in robot.joints
                                 if j.parent and j.child}
    skip |= {frozenset(pair) for pair in disabled}
    objects = geometry.geometryObjects
    for a, b in itertools.combinations(range(geometry.ngeoms), 2):
        same_body = objects[a].parentJoint == objects[b].parentJoint
        if not same_body and frozenset((links[a], links[b])) not in skip:
            geometry.addCollisionPair(pin.CollisionPair(a, b))
    floor_z = min(grounded.values()) if grounded else None
    if floor_z is not None:
        standing = {links[k] for k, z in grounded.items() if z <= floor_z + _ON_FLOOR_M}
        _add_floor(geometry, links, floor_z, standing | {link for pair in skip
                                                         if FLOOR in pair for link in pair})
    if moving is not None:
        _keep_moved_pairs(model, geometry, moving)
    _drop_always_touching(model, geometry, samples)
    return CollisionCheck(model, geometry, links, floor_z)


def _keep_moved_pairs(model: pin.Model, geometry: pin.GeometryModel,
                      moving: Collection[str]) -> None:
    """Remove the pairs whose relative pose none of the ``moving`` joints changes."""
    chosen = {model.getJointId(name) for name in moving if model.existJointName(name)}
    objects = geometry.geometryObjects

    def movers(k: int) -> frozenset[int]:
        return frozenset(int(j) for j in model.supports[objects[k].parentJoint]) & chosen

    still = [(pair.first, pair.second) for pair in geometry.collisionPairs
             if movers(pair.first) == movers(pair.second)]
    _remove(geometry, still)


def _remove(geometry: pin.GeometryModel, pairs: Iterable[tuple[int, int]]) -> None:
    """Remove pairs given by object indices (copies: the model's own pairs move on removal)."""
    import pinocchio as pin

    for first, second in pairs:
        geometry.removeCollisionPair(pin.CollisionPair(first, second))


def _geometry(robot: RobotDescription, model: pin.Model,
              resolver: PackageResolver) -> pin.GeometryModel:
    """The ``<collision>`` geometry, with ``package://`` meshes resolved by ``resolver``."""
    import pinocchio as pin

    base_dir = robot.path.parent

    def resolved(match: re.Match[str]) -> str:
        # absolute: Pinocchio looks for a relative mesh path on its package dirs, not here
        path = resolver.resolve_uri(match.group(2), base_dir).absolute()
        return f"filename={match.group(1)}{path}{match.group(1)}"

    xml = re.sub(r"filename\s*=\s*([\"'])(.*?)\1", resolved, robot.xml_text)
    from servicebot_cli.common.native_stderr import captured_fd2

    try:
        with captured_fd2():  # urdfdom's words on what it skips (check reports those)
            return pin.buildGeomFromUrdfString(model, xml, pin.COLLISION)
    except (ValueError, RuntimeError) as exc:
        reason = " ".join(str(exc).split())
        raise CollisionSetupError(f"{robot.display}: cannot read the collision geometry: "
                                  f"{reason}; --allow-collisions skips the check") from None


def _placed(model: pin.Model, geometry: pin.GeometryModel,
            q: FloatArray) -> pin.GeometryData:
    import pinocchio as pin

    geometry_data = pin.GeometryData(geometry)
    pin.updateGeometryPlacements(model, model.createData(), geometry, geometry_data, q)
    return geometry_data


def _heights_m(model: pin.Model, geometry: pin.GeometryModel) -> list[float]:
    """The lowest point of each object at the neutral configuration, z in the root [m].

    Measured as the distance to a plane far below, which coal computes exactly for
    primitives and meshes alike.
    """
    import pinocchio as pin

    coal = pin.coal  # shipped with Pinocchio
    placed = _placed(model, geometry, pin.neutral(model))
    plane = coal.Halfspace(np.array([0.0, 0.0, 1.0]), -_FAR_BELOW_M)
    heights = []
    for k, obj in enumerate(geometry.geometryObjects):
        pose = placed.oMg[k]
        result = coal.DistanceResult()
        distance = coal.distance(obj.geometry, coal.Transform3s(pose.rotation, pose.translation),
                                 plane, coal.Transform3s(), coal.DistanceRequest(), result)
        heights.append(float(distance) - _FAR_BELOW_M)
    return heights


def _grounded(model: pin.Model, geometry: pin.GeometryModel) -> dict[int, float]:
    """Objects no bounded joint moves, and their lowest point at neutral (z in the root) [m]."""
    heights = _heights_m(model, geometry)
    return {k: z for k, (obj, z) in enumerate(zip(geometry.geometryObjects, heights, strict=True))
            if all(_unbounded(model, int(j)) for j in model.supports[obj.parentJoint][1:])}


def _unbounded(model: pin.Model, joint: int) -> bool:
    """A continuous joint (a wheel), or a mobile base's own root joint."""
    shape = model.joints[joint]
    return bool(model.names[joint] == "root_joint" or (shape.nq == 2 and shape.nv == 1))


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
        if hasattr(shape, "buildConvexHull"):  # a mesh: its hull has the same lowest point
            shape.buildConvexHull(True, "Qt")
            hull = pin.GeometryObject(f"{obj.name}_hull", obj.parentJoint, obj.parentFrame,
                                      obj.placement.copy(), shape.convex)
            k = geometry.addGeometryObject(hull)
            links.append(link)
        geometry.addCollisionPair(pin.CollisionPair(k, index))


def _floor_object(z_m: float) -> pin.GeometryObject:
    """The half-space below ``z_m``, fixed to the root."""
    import pinocchio as pin

    plane = pin.coal.Halfspace(np.array([0.0, 0.0, 1.0]), z_m)
    return pin.GeometryObject(FLOOR, 0, 0, pin.SE3.Identity(), plane)


def sample_configurations(model: pin.Model, count: int,
                          rng: np.random.Generator) -> list[FloatArray]:
    """``count`` random configurations: bounded joints within their limits, others any angle.

    A planar or free root joint stays at its neutral pose (moving it moves every link alike).
    """
    import pinocchio as pin

    out = []
    for _ in range(count):
        q: FloatArray = pin.neutral(model)
        for j in range(1, model.njoints):
            joint, name = model.joints[j], model.names[j]
            i = joint.idx_q
            if name == "root_joint":
                continue
            if joint.nq == 1:
                lo, hi = model.lowerPositionLimit[i], model.upperPositionLimit[i]
                q[i] = rng.uniform(lo, hi) if math.isfinite(lo) and math.isfinite(hi) else \
                    rng.uniform(-math.pi, math.pi)
            elif joint.nq == 2 and joint.nv == 1:  # continuous: cos, sin
                angle = rng.uniform(-math.pi, math.pi)
                q[i:i + 2] = math.cos(angle), math.sin(angle)
        out.append(q)
    return out


def _drop_always_touching(model: pin.Model, geometry: pin.GeometryModel, samples: int) -> None:
    """Remove the pairs that intersect at the neutral configuration and every sample."""
    import pinocchio as pin

    rng = np.random.default_rng(_SAMPLE_SEED)
    always = list(range(len(geometry.collisionPairs)))
    for q in [pin.neutral(model), *sample_configurations(model, samples, rng)]:
        if not always:
            return
        placed = _placed(model, geometry, q)
        always = [k for k in always if pin.computeCollision(geometry, placed, k)]
    pairs = geometry.collisionPairs
    _remove(geometry, [(pairs[k].first, pairs[k].second) for k in always])
