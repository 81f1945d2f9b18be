"""The arm touching the robot's own body (or the floor), with ``kinematics.collisions``.

The check ``ik`` uses (adjacent and always-touching pairs left out) names the first pair that
touches; each stretch of ticks where that pair touches is one event, at the tick it began.
It runs at every distinct arm configuration where it could find something: where the bounding
sphere of a moving part meets that of a part of a link not joined to its own, or the floor.
Those configurations are looked for first over stretches of :data:`STRETCH_TICKS` ticks: where
the box swept by a part's centre over a stretch keeps its sphere clear, no tick of the stretch
can. The check itself is built at the first configuration that needs it. Pure: the robot and
the arm's positions in, events out.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import RobotShape

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.collisions import CollisionCheck

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]
STRETCH_TICKS = 64
"""Ticks whose swept bounds are compared at once before any tick of them is."""
_SLACK_M = 1e-9
"""Added to every bound, so rounding never clears a configuration the exact test flags."""


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
        disabled: Link pairs never checked (an SRDF's ``<disable_collisions>``).
        resolver: Finds ``package://`` collision meshes (None: the file's workspace).
    """

    def __init__(self, robot: RobotDescription, shape: RobotShape, base_height_m: float,
                 dt_s: float, disabled: Collection[tuple[str, str]] = (),
                 resolver: PackageResolver | None = None) -> None:
        self.robot, self.shape, self.base_height_m, self.dt_s = robot, shape, base_height_m, dt_s
        self.disabled, self.resolver = tuple(disabled), resolver
        self.built: tuple[CollisionCheck, FloatArray, list[int]] | None = None
        self.touching: set[tuple[str, str]] = set()
        self.previous = -2  # the last tick checked
        self.last_q: FloatArray | None = None  # the arm at the last tick seen

    def _check(self) -> tuple[CollisionCheck, FloatArray, list[int]]:
        """The collision check, a configuration to fill and the arm's columns in it."""
        if self.built is None:
            import pinocchio as pin

            from servicebot_cli.description.packages import PackageResolver
            from servicebot_cli.kinematics.collisions import build_check

            robot, model = self.robot, self.robot.model
            resolver = self.resolver or PackageResolver(context=robot.path.parent)
            # meshes the shape could not read are left out (its notes say so), as the
            # shape leaves them out; simulate has no --allow-collisions to offer
            check = build_check(robot, model, resolver, disabled=self.disabled,
                                omit_meshes=self.shape.unread_meshes, skippable=False)
            columns = [model.joints[model.getJointId(name)].idx_q for name in self.shape.joints]
            self.built = (check, np.array(pin.neutral(model)), columns)
        return self.built

    def advance(self, first_tick: int, arm_q: FloatArray,
                parts_to_base: FloatArray | None = None) -> list[SelfContact]:
        """Events among the arm positions (n+1, J) at the boundaries from ``first_tick``.

        ``parts_to_base`` is ``shape.transforms_to_base(arm_q)`` when the caller has it.
        """
        if not len(arm_q):
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
        if not len(changes):
            return []
        check, q, columns = self._check()
        if not check.pairs:
            return []
        events: list[SelfContact] = []
        for k in (changes + first_tick).tolist():
            if k != self.previous + 1:
                self.touching = set()  # the ticks in between could not touch
            q[columns] = arm_q[k - first_tick]
            contact = check.contact(q)
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
                 q: FloatArray, placed: FloatArray | None = None) -> BoolArray:
    """Per configuration: may a moving part touch another link's part, or the floor?

    A moving part (bounding sphere) is compared with a part fixed on the base through that
    part's box (which holds a cylinder or sphere too), with another moving part sphere to
    sphere. Stretches of configurations whose swept bounds keep clear are not compared one
    by one.
    """
    placed = shape.transforms_to_base(q) if placed is None else placed
    centres = placed[..., :3, 3]  # (n, parts, 3)
    pairs = _pairs(robot, shape)
    stretches = -(-len(q) // STRETCH_TICKS)
    padded = np.concatenate((centres, np.repeat(centres[-1:], stretches * STRETCH_TICKS
                                                - len(q), axis=0)))
    swept = padded.reshape(stretches, STRETCH_TICKS, *centres.shape[1:])
    maybe = _may_touch(shape, base_height_m, pairs, placed[0], swept.min(axis=1),
                       swept.max(axis=1))
    out = np.zeros(len(q), dtype=bool)
    rows = (np.flatnonzero(maybe)[:, None] * STRETCH_TICKS
            + np.arange(STRETCH_TICKS)).ravel()
    rows = rows[rows < len(q)]
    if len(rows):
        out[rows] = _touch(shape, base_height_m, pairs, placed[0], centres[rows])
    return out


def _pairs(robot: RobotDescription, shape: RobotShape) -> list[tuple[int, list[int]]]:
    """Each moving part, with the parts of links neither its own nor joined to its own."""
    joined = {frozenset((j.parent, j.child)) for j in robot.joints}
    out = []
    for i in np.flatnonzero(~shape.fixed()).tolist():
        link = shape.parts[i].link
        out.append((i, [j for j, other in enumerate(shape.parts) if other.link != link
                        and frozenset((link, other.link)) not in joined]))
    return out


def _touch(shape: RobotShape, base_height_m: float, pairs: list[tuple[int, list[int]]],
           fixed_placed: FloatArray, centres: FloatArray) -> BoolArray:
    """The exact bounding test per configuration; ``centres`` (n, parts, 3)."""
    fixed = shape.fixed()
    radius = np.array([p.radius_m for p in shape.parts])
    out = np.zeros(len(centres), dtype=bool)
    for i, others in pairs:
        out |= centres[:, i, 2] - radius[i] < -base_height_m  # reaches the floor
        for j in others:
            if fixed[j]:
                local = (centres[:, i] - fixed_placed[j, :3, 3]) @ fixed_placed[j, :3, :3]
                gap = np.linalg.norm(np.maximum(np.abs(local) - shape.parts[j].half_m, 0.0),
                                     axis=1)
                out |= gap < radius[i]
            else:
                gap = np.linalg.norm(centres[:, i] - centres[:, j], axis=1)
                out |= gap < radius[i] + radius[j]
    return out


def _may_touch(shape: RobotShape, base_height_m: float, pairs: list[tuple[int, list[int]]],
               fixed_placed: FloatArray, low: FloatArray, high: FloatArray) -> BoolArray:
    """Per stretch: could :func:`_touch` hold at one of its configurations?

    ``low`` and ``high`` (stretches, parts, 3) bound each part's centre over a stretch. A
    fixed part is taken as the axis-aligned box around its box; the distance between two
    boxes is at most that between any points of them.
    """
    fixed = shape.fixed()
    radius = np.array([p.radius_m for p in shape.parts])
    out = np.zeros(len(low), dtype=bool)
    for i, others in pairs:
        out |= low[:, i, 2] - radius[i] < -base_height_m + _SLACK_M
        for j in others:
            if fixed[j]:
                rotation, centre = fixed_placed[j, :3, :3], fixed_placed[j, :3, 3]
                extent = np.abs(rotation) @ shape.parts[j].half_m
                other_low, other_high, reach = centre - extent, centre + extent, radius[i]
            else:
                other_low, other_high = low[:, j], high[:, j]
                reach = radius[i] + radius[j]
            apart = np.maximum(np.maximum(other_low - high[:, i], low[:, i] - other_high), 0.0)
            out |= np.linalg.norm(apart, axis=1) < reach + _SLACK_M
    return out
