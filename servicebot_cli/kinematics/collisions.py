r"""Does a configuration put links of the robot into each other, or into the floor?

The URDF's ``<collision>`` geometry goes into a Pinocchio ``GeometryModel`` (coal does the
tests). Pairs that can never tell anything are left out, as MoveIt's setup assistant does:

- links fixed to one another (one Pinocchio body), and adjacent links (a URDF joint's parent
  and child), which touch where they are joined;
- pairs that touch at every one of :data:`SAMPLES` random configurations within the limits
  (a fixed seed: the same pairs every run), "always in collision";
- pairs an SRDF names in ``<disable_collisions>``.

Links also collide with the floor on a robot that stands on one (see
:mod:`~servicebot_cli.kinematics.collision_floor`); which pairs are left out is
:mod:`~servicebot_cli.kinematics.collision_pairs`'s to decide. Pure: a model, geometry and
configurations in; contacts out.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.collision_floor import FLOOR, add_floor, grounded
from servicebot_cli.kinematics.collision_meshes import coal_reason, collision_meshes, mesh_problem
from servicebot_cli.kinematics.collision_pairs import (
    SAMPLES,
    drop_always_touching,
    keep_moved_pairs,
)

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]


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
                moving: Collection[str] | None = None, samples: int = SAMPLES,
                omit_meshes: Collection[str] = (), skippable: bool = True
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
        omit_meshes: Collision meshes (as written) left out of the check (simulate's
            unreadable ones, already named in its notes).
        skippable: The command has ``--allow-collisions``, which the messages offer.

    Raises:
        CollisionSetupError: A collision mesh that cannot be read.
        PackageNotFound: A mesh in a package that is nowhere.
    """
    import pinocchio as pin

    geometry = _geometry(robot, model, resolver, omit_meshes, skippable)
    links = [model.frames[o.parentFrame].name for o in geometry.geometryObjects]
    at_rest = grounded(model, geometry) if floor else {}
    skip: set[frozenset[str]] = {frozenset((j.parent, j.child)) for j in robot.joints
                                 if j.parent and j.child}
    skip |= {frozenset(pair) for pair in disabled}
    objects = geometry.geometryObjects
    for a, b in itertools.combinations(range(geometry.ngeoms), 2):
        same_body = objects[a].parentJoint == objects[b].parentJoint
        if not same_body and frozenset((links[a], links[b])) not in skip:
            geometry.addCollisionPair(pin.CollisionPair(a, b))
    floor_z = add_floor(geometry, links, at_rest, skip)
    if moving is not None:
        keep_moved_pairs(model, geometry, moving)
    drop_always_touching(model, geometry, samples)
    return CollisionCheck(model, geometry, links, floor_z)


def _geometry(robot: RobotDescription, model: pin.Model, resolver: PackageResolver,
              omit: Collection[str] = (), skippable: bool = True) -> pin.GeometryModel:
    """The ``<collision>`` geometry, with ``package://`` meshes resolved by ``resolver``.

    Each mesh is read by the project's own bounded readers first: Assimp (in coal) crashes
    on, or allocates without bound for, some broken files.
    """
    import pinocchio as pin

    base_dir = robot.path.parent
    meshes = list(collision_meshes(robot, resolver, omit, skippable))
    problem = mesh_problem(robot, meshes, skippable)
    if problem is not None:
        raise CollisionSetupError(problem)

    def resolved(match: re.Match[str]) -> str:
        # absolute: Pinocchio looks for a relative mesh path on its package dirs, not here
        path = resolver.resolve_uri(match.group(2), base_dir).absolute()
        return f"filename={match.group(1)}{path}{match.group(1)}"

    xml = re.sub(r"filename\s*=\s*([\"'])(.*?)\1", resolved, _without_meshes(robot, omit))
    from servicebot_cli.common.native_stderr import captured_fd2

    try:
        with captured_fd2():  # urdfdom's words on what it skips (check reports those)
            return pin.buildGeomFromUrdfString(model, xml, pin.COLLISION)
    except (ValueError, RuntimeError) as exc:
        mesh, reason = coal_reason(str(exc), meshes)
        what = ("cannot read the collision geometry" if mesh is None else
                f"collision mesh '{mesh.filename}' of link '{mesh.link}' cannot be read")
        raise CollisionSetupError(f"{robot.display}: {what}: {reason}"
                                  + ("; --allow-collisions skips the check" if skippable
                                     else "")) from None


def _without_meshes(robot: RobotDescription, omit: Collection[str]) -> str:
    """The robot's XML without the ``<collision>`` elements of the meshes in ``omit``."""
    if not omit:
        return robot.xml_text
    import copy
    import xml.etree.ElementTree as ET

    root = copy.deepcopy(robot.root)
    for link in root.iter("link"):
        for shape in list(link.findall("collision")):
            mesh = shape.find("geometry/mesh")
            if mesh is not None and mesh.get("filename") in omit:
                link.remove(shape)
    return ET.tostring(root, encoding="unicode")
