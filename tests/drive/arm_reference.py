"""An independent reference for the arm's collisions: Pinocchio and coal used directly.

Built from the real robot's URDF with Pinocchio's own loaders, not servicebot's: which links
intersect (coal, pair by pair, leaving out links joined by a URDF joint and links on one
body), and the lowest point of each moving box (its corners). The wheels stand on the floor.
"""

from __future__ import annotations

import itertools
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

from tests.conftest import REAL_URDF

ARM = ("arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4")


class ArmReference:
    """The real robot's collision geometry, checked pair by pair with coal."""

    def __init__(self) -> None:
        self.model = pin.buildModelFromUrdf(str(REAL_URDF))
        self.data = self.model.createData()
        self.geometry = pin.buildGeomFromUrdf(self.model, str(REAL_URDF), pin.COLLISION)
        self.geometry_data = pin.GeometryData(self.geometry)
        self.links = [self.model.frames[o.parentFrame].name
                      for o in self.geometry.geometryObjects]
        joined = {frozenset((j.find("parent").get("link"), j.find("child").get("link")))
                  for j in ET.parse(REAL_URDF).getroot().findall("joint")}
        objects = self.geometry.geometryObjects
        self.pairs = [(a, b) for a, b in itertools.combinations(range(len(objects)), 2)
                      if objects[a].parentJoint != objects[b].parentJoint
                      and frozenset((self.links[a], self.links[b])) not in joined]
        self.columns = [self.model.joints[self.model.getJointId(n)].idx_q for n in ARM]
        self.speeds_rad_s = [float(self.model.velocityLimit[
            self.model.joints[self.model.getJointId(n)].idx_v]) for n in ARM]
        self.floor_z_m = self._lowest_m(pin.neutral(self.model), moving=False)

    def _placed(self, arm_rad: tuple[float, ...]) -> np.ndarray:
        q = pin.neutral(self.model)
        q[self.columns] = arm_rad
        pin.updateGeometryPlacements(self.model, self.data, self.geometry, self.geometry_data, q)
        return q

    def intersecting(self, arm_rad: tuple[float, ...]) -> set[frozenset[str]]:
        """The link pairs that intersect with the arm at ``arm_rad``."""
        self._placed(arm_rad)
        found = set()
        objects, placed = self.geometry.geometryObjects, self.geometry_data.oMg
        for a, b in self.pairs:
            result = pin.coal.CollisionResult()
            pin.coal.collide(objects[a].geometry, _transform(placed[a]),
                             objects[b].geometry, _transform(placed[b]),
                             pin.coal.CollisionRequest(), result)
            if result.isCollision():
                found.add(frozenset((self.links[a], self.links[b])))
        return found

    def _lowest_m(self, q: np.ndarray, *, moving: bool) -> float:
        """The lowest box corner of the arm (``moving``) or of everything else, z [m]."""
        pin.updateGeometryPlacements(self.model, self.data, self.geometry, self.geometry_data, q)
        lowest = np.inf
        for obj, pose in zip(self.geometry.geometryObjects, self.geometry_data.oMg, strict=True):
            if (obj.parentJoint in self.arm_joint_ids) != moving:
                continue
            half = obj.geometry.halfSide if hasattr(obj.geometry, "halfSide") else np.full(
                3, obj.geometry.radius)
            for signs in itertools.product((-1, 1), repeat=3):
                lowest = min(lowest, float((pose.act(np.array(signs) * half))[2]))
        return lowest

    @property
    def arm_joint_ids(self) -> set[int]:
        return {self.model.getJointId(n) for n in ARM}

    def below_floor_m(self, arm_rad: tuple[float, ...]) -> float:
        """How far the arm's lowest corner is below the floor at ``arm_rad`` [m] (< 0: above)."""
        return self.floor_z_m - self._lowest_m(self._placed(arm_rad), moving=True)

    def clear(self, arm_rad: tuple[float, ...]) -> bool:
        """No pair intersects, and the arm is above the floor, at ``arm_rad``."""
        return not self.intersecting(arm_rad) and self.below_floor_m(arm_rad) < 0.0

    def firmware_path(self, start: tuple[float, ...], target: tuple[float, ...],
                      dt_s: float = 0.001) -> list[tuple[float, ...]]:
        """The arm every ``dt_s`` as the emulator moves it: each joint at its limit."""
        here, path = list(start), []
        while here != list(target):
            for i, (s, t, v) in enumerate(zip(here, target, self.speeds_rad_s, strict=True)):
                step = v * dt_s
                here[i] = t if abs(t - s) <= step else s + np.copysign(step, t - s)
            path.append(tuple(here))
        return path


def _transform(pose: pin.SE3) -> pin.coal.Transform3s:
    return pin.coal.Transform3s(pose.rotation, pose.translation)
