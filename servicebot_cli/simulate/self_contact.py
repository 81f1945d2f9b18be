"""The arm touching the robot's own body (or the floor), with ``kinematics.collisions``.

The check ``ik`` uses (adjacent and always-touching pairs left out) names the first pair that
touches; each stretch of ticks where that pair touches is one event, at the tick it began.
It runs at every distinct arm configuration where it could find something: where the bounding
sphere of a moving part meets that of a part of a link not joined to its own, or the floor.
 Pure: the robot and the arm's positions in, events out.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import RobotShape

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class SelfContact:
    """From ``time_s`` on, link ``first`` touches ``second`` (another link or ``floor``)."""

    time_s: float
    first: str
    second: str


class SelfContactWatch:
    """Where the arm's motion puts links into each other or into the floor, a stretch at a time.

    Args:
        robot: The description.
        shape: The robot's parts; its joints are the arm positions' columns.
        base_height_m: Height of the base frame above the floor [m].
        dt_s: Control period [s].
    """

    def __init__(self, robot: RobotDescription, shape: RobotShape, base_height_m: float,
                 dt_s: float) -> None:
        import pinocchio as pin

        from servicebot_cli.description.packages import PackageResolver
        from servicebot_cli.kinematics.collisions import build_check

        self.robot, self.shape, self.base_height_m, self.dt_s = robot, shape, base_height_m, dt_s
        model = robot.model
        self.check = build_check(robot, model, PackageResolver(context=robot.path.parent))
        self.q = np.array(pin.neutral(model))
        self.columns = [model.joints[model.getJointId(name)].idx_q for name in shape.joints]
        self.touching: set[tuple[str, str]] = set()
        self.previous = -2  # the last tick checked
        self.last_q: FloatArray | None = None  # the arm at the last tick seen

    def advance(self, first_tick: int, arm_q: FloatArray,
                parts_to_base: FloatArray | None = None) -> list[SelfContact]:
        """Events among the arm positions (n+1, J) at the boundaries from ``first_tick``.

        ``parts_to_base`` is ``shape.transforms_to_base(arm_q)`` when the caller has it.
        """
        if not self.check.pairs or not len(arm_q):
            return []
        before = arm_q[:1] if self.last_q is None else self.last_q[None]
        start = 0 if self.last_q is None else 1  # the first boundary was the last one seen
        changed = np.any(np.diff(np.vstack((before, arm_q[start:])), axis=0), axis=1)
        changes = np.flatnonzero(changed) + start
        if self.last_q is None:
            changes = np.concatenate(([0], changes))
        self.last_q = arm_q[-1].copy()
        if len(changes):
            changes = changes[_could_touch(
                self.robot, self.shape, self.base_height_m, arm_q[changes],
                None if parts_to_base is None else parts_to_base[changes])]
        events: list[SelfContact] = []
        for k in (changes + first_tick).tolist():
            if k != self.previous + 1:
                self.touching = set()  # the ticks in between could not touch
            self.q[self.columns] = arm_q[k - first_tick]
            contact = self.check.contact(self.q)
            now = {(contact.first, contact.second)} if contact is not None else set()
            events += [SelfContact(float(k * self.dt_s), *pair)
                       for pair in sorted(now - self.touching)]
            self.touching, self.previous = now, k
        return events


def self_contacts(robot: RobotDescription, shape: RobotShape, base_height_m: float,
                  arm_q: FloatArray, dt_s: float) -> list[SelfContact]:
    """Self-contact events of a whole run's arm positions (n+1, J) at tick boundaries."""
    return SelfContactWatch(robot, shape, base_height_m, dt_s).advance(0, arm_q)


def _could_touch(robot: RobotDescription, shape: RobotShape, base_height_m: float,
                 q: FloatArray, placed: FloatArray | None = None) -> npt.NDArray[np.bool_]:
    """Per configuration: may a moving part touch another link's part, or the floor?

    A moving part (bounding sphere) is compared with a part fixed on the base through that
    part's box (which holds a cylinder or sphere too), with another moving part sphere to
    sphere.
    """
    joined = {frozenset((j.parent, j.child)) for j in robot.joints}
    fixed = shape.fixed()
    radius = np.array([p.radius_m for p in shape.parts])
    placed = shape.transforms_to_base(q) if placed is None else placed
    centres = placed[..., :3, 3]
    out = np.zeros(len(q), dtype=bool)
    for i in np.flatnonzero(~fixed):
        link = shape.parts[i].link
        out |= centres[:, i, 2] - radius[i] < -base_height_m  # reaches the floor
        for j, other in enumerate(shape.parts):
            if other.link == link or frozenset((link, other.link)) in joined:
                continue
            if fixed[j]:
                local = (centres[:, i] - placed[0, j, :3, 3]) @ placed[0, j, :3, :3]
                gap = np.linalg.norm(np.maximum(np.abs(local) - other.half_m, 0.0), axis=1)
                out |= gap < radius[i]
            else:
                gap = np.linalg.norm(centres[:, i] - centres[:, j], axis=1)
                out |= gap < radius[i] + radius[j]
    return out
