"""The running gear besides the drive wheels: casters, suspensions and steering joints.

A passive caster is a wheel joint that turns freely below a swivel turning freely about the
vertical (:func:`swivels_above`), or a ball on the centre line; above them and above the
drive wheels, joints that carry the wheels of one side only are running gear too
(:func:`chassis_joints`). None of them is an arm. Pure.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.description.elements import ONE_AXIS_TYPES, Joint
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.wheel_joints import (
    BALL_CASTER,
    NO_ROUND_SHAPE,
    PARALLEL,
    as_wheel,
    turns_freely,
    unit_axis,
)

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription



def chassis_joints(robot: RobotDescription, wheels: Sequence[str] = ()) -> tuple[str, ...]:
    """The movable joints of the running gear other than the drive ``wheels``, URDF order.

    Passive casters (:func:`swivels_above`; a ball on the centre line), and the one-axis
    joints above a drive wheel or a caster that carry wheels of one side only: a suspension
    (Leo Rover's rockers) or a steering joint. A joint that carries both sides' wheels (a
    virtual planar base above the whole robot) is not running gear, nor is anything above
    it. None of them is an arm.
    """
    world = link_transforms(robot)
    below = swivels_above(robot, world)
    gear = set(below.values()) | set(below) | {
        joint.name for joint in robot.joints
        if as_wheel(robot, joint, world) == BALL_CASTER}
    by_child = {joint.child: joint for joint in robot.joints}
    by_name = robot.joints_by_name
    children: dict[str, list[Joint]] = {}
    for each in robot.joints:
        if each.parent is not None:
            children.setdefault(each.parent, []).append(each)
    side = _wheel_sides(by_name, wheels, world)
    for name in (*wheels, *gear):
        joint = by_name.get(name)
        above = by_child.get(joint.parent) if joint is not None else None
        while above is not None and above.name not in gear:
            if len({side[w] for w in _wheels_below(above, side, children)}) > 1:
                break  # it carries both sides: the base itself moves
            if above.type in ONE_AXIS_TYPES:
                gear.add(above.name)
            above = by_child.get(above.parent)
    return tuple(j.name for j in robot.joints if j.name in gear and j.name not in wheels)


def _wheel_sides(by_name: dict[str, Joint], wheels: Sequence[str],
                 world: dict[str, np.ndarray]) -> dict[str, str]:
    """Each drive wheel's side (its joint's child on +y of the root: left)."""
    sides = {}
    for name in wheels:
        child = by_name[name].child if name in by_name else None
        if child is not None and child in world:
            sides[name] = "left" if world[child][1, 3] > 0 else "right"
    return sides


def _wheels_below(joint: Joint, side: dict[str, str],
                  children: dict[str, list[Joint]]) -> list[str]:
    """The drive wheels of ``side`` in the subtree ``joint`` carries (itself included).

    ``children``: each link's child joints.
    """
    found: list[str] = []
    stack, seen = [joint], set()
    while stack:
        current = stack.pop()
        if current.name in seen:
            continue
        seen.add(current.name)
        if current.name in side:
            found.append(current.name)
        stack += children.get(current.child or "", [])
    return found


def swivels_above(robot: RobotDescription, world: dict[str, np.ndarray]) -> dict[str, str]:
    """Passive casters: each caster wheel joint, and the swivel it turns on.

    A swivel turns freely about the vertical (the root link's z), on a link fixed to the
    root link; its child link is the parent of the caster wheel's joint, which turns freely
    and carries a round shape (MiR's ``fl_caster_rotation_joint`` over
    ``fl_caster_wheel_joint``). An arm's waist carries no wheel; a virtual yaw joint above
    the whole base stands on a moving link.
    """
    by_child = {joint.child: joint for joint in robot.joints}
    on_root = _fixed_to_root(robot)
    found: dict[str, str] = {}
    for joint in robot.joints:
        swivel = by_child.get(joint.parent) if joint.parent is not None else None
        if joint.child is None or not turns_freely(joint) or swivel is None \
                or not turns_freely(swivel) or swivel.parent not in on_root \
                or not _vertical(swivel, world):
            continue
        link = robot.find_link(joint.child)
        if link is None:
            continue
        if any(s.geometry.kind in ("cylinder", "sphere")
               for s in (*link.collisions, *link.visuals)) or _mesh_leaf(robot, link.name):
            found[joint.name] = swivel.name
    return found


def loose_wheels(robot: RobotDescription, world: dict[str, np.ndarray]) -> tuple[str, ...]:
    """Wheel joints of a robot no differential drive was made of: wheels, and no arm either.

    Each joint that turns a wheel (one side's only; the Pioneer's caster), and each that
    turns freely across the robot (about the root's y) carrying a link that ends the tree,
    with a mesh and no cylinder or sphere to take a radius from (scout_mini's wheels,
    without a Gazebo plugin to name them). URDF order.
    """
    found = []
    for joint in robot.joints:
        wheel = as_wheel(robot, joint, world)
        if wheel is not None and not isinstance(wheel, str):
            found.append(joint.name)
            continue
        if wheel != NO_ROUND_SHAPE or joint.child is None or not _mesh_leaf(robot, joint.child):
            continue
        axis = unit_axis(joint)
        if axis is not None and abs((world[joint.child][:3, :3] @ axis)[1]) >= PARALLEL:
            found.append(joint.name)
    return tuple(found)


def _mesh_leaf(robot: RobotDescription, link_name: str) -> bool:
    """Whether ``link_name`` has a mesh and carries nothing that moves (a wheel's link)."""
    link = robot.find_link(link_name)
    if link is None or not any(s.geometry.kind == "mesh"
                               for s in (*link.collisions, *link.visuals)):
        return False
    stack, seen = [link_name], set()
    while stack:  # only fixed joints below it
        current = stack.pop()
        seen.add(current)
        for joint in robot.joints:
            if joint.parent == current and joint.child not in seen:
                if joint.type != "fixed":
                    return False
                stack.append(joint.child or "")
    return True


def _fixed_to_root(robot: RobotDescription) -> set[str]:
    """The root link and the links fixed to it."""
    fixed: dict[str, list[str]] = {}
    for joint in robot.joints:
        if joint.type == "fixed" and joint.parent is not None and joint.child is not None:
            fixed.setdefault(joint.parent, []).append(joint.child)
    found, stack = set(), [robot.root_link] if robot.root_link else []
    while stack:
        link = stack.pop()
        if link not in found:
            found.add(link)
            stack += fixed.get(link, [])
    return found


def _vertical(joint: Joint, world: dict[str, np.ndarray]) -> bool:
    """Whether ``joint`` turns about the root link's z at the zero configuration."""
    axis = np.array(joint.axis, dtype=float)
    norm = float(np.linalg.norm(axis))
    if joint.child not in world or not math.isfinite(norm) or norm == 0:
        return False
    return abs(float((world[joint.child][:3, :3] @ (axis / norm))[2])) >= PARALLEL
