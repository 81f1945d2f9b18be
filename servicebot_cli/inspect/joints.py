"""The joints and fixed-frames tables, with limits in the units users type."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from servicebot_cli.description.elements import Joint, Vec3
from servicebot_cli.description.robot import FixedFrame
from servicebot_cli.inspect.numbers import rpy_of, vec3

DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}
"""Degrees of freedom per URDF joint type (a URDF ``planar`` joint moves in x, y and yaw)."""


@dataclass(frozen=True)
class Units:
    """Units of a joint's position, velocity and effort."""

    position: str
    velocity: str
    effort: str


ANGULAR = Units("rad", "rad/s", "N m")
LINEAR = Units("m", "m/s", "N")


@dataclass(frozen=True)
class Limits:
    """A joint's ``<limit>``; values in :attr:`units`, None where the URDF gives none."""

    lower: float | None
    upper: float | None
    velocity: float | None
    effort: float | None
    units: Units


@dataclass(frozen=True)
class MimicInfo:
    """This joint follows ``joint``: value = multiplier * other + offset."""

    joint: str | None
    multiplier: float
    offset: float


@dataclass(frozen=True)
class JointInfo:
    """One joint.

    Attributes:
        xyz_m, rpy_rad: The joint frame in the parent link.
        axis: Unit axis in the joint frame.
        dof: Degrees of freedom (0 for fixed).
    """

    name: str
    type: str
    parent: str | None
    child: str | None
    xyz_m: Vec3
    rpy_rad: Vec3
    axis: Vec3 | None
    limits: Limits | None
    mimic: MimicInfo | None
    dof: int


@dataclass(frozen=True)
class FrameInfo:
    """A link attached by a fixed joint.

    Attributes:
        xyz_m, rpy_rad: The frame in its parent link.
        root_xyz_m, root_rpy_rad: The frame in the root link at the zero configuration.
    """

    name: str
    parent: str
    joint: str
    xyz_m: Vec3
    rpy_rad: Vec3
    root_xyz_m: Vec3 | None
    root_rpy_rad: Vec3 | None


def joint_units(joint_type: str) -> Units | None:
    """The units of a joint type's values; None for types that take no single value."""
    if joint_type in ("revolute", "continuous"):
        return ANGULAR
    if joint_type == "prismatic":
        return LINEAR
    return None


def joint_info(joint: Joint) -> JointInfo:
    """The summary of ``joint``."""
    units = joint_units(joint.type)
    limits = None
    if joint.limits is not None and units is not None:
        lim = joint.limits
        limits = Limits(lim.lower, lim.upper, lim.velocity, lim.effort, units)
    mimic = None
    if joint.mimic is not None:
        mimic = MimicInfo(joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset)
    return JointInfo(
        name=joint.name, type=joint.type, parent=joint.parent, child=joint.child,
        xyz_m=joint.origin.xyz, rpy_rad=joint.origin.rpy,
        axis=joint.axis if joint.type not in ("fixed", "floating") else None,
        limits=limits, mimic=mimic, dof=DOF.get(joint.type, 0),
    )


def frame_info(frame: FixedFrame, transforms: Mapping[str, np.ndarray]) -> FrameInfo:
    """The summary of a fixed frame; ``transforms`` maps link names to transform_link_to_root."""
    transform = transforms.get(frame.name)
    root_xyz = root_rpy = None
    if transform is not None:
        root_xyz = vec3(transform[:3, 3])
        root_rpy = rpy_of(transform[:3, :3])
    return FrameInfo(frame.name, frame.parent, frame.joint, frame.origin.xyz, frame.origin.rpy,
                     root_xyz, root_rpy)
