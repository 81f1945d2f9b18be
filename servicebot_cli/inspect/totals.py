"""Whole-robot numbers: degrees of freedom, mass, centre of mass, size, arm reach, drive.

Mass counts every link's ``<inertial>`` (Pinocchio's fixed-base model would leave out the root
link and everything fixed to it). The centre of mass and the bounding box are taken at one
configuration, zero unless the user gives joint values.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from servicebot_cli.description.elements import Joint, Vec3
from servicebot_cli.description.robot import RobotDescription
from servicebot_cli.inspect.geometry import FloatArray, MeshLibrary, bounding_box, posed_visuals
from servicebot_cli.inspect.joints import DOF
from servicebot_cli.inspect.numbers import clean, vec3
from servicebot_cli.inspect.tree import KinematicTree, descendants
from servicebot_cli.kinematics.drive_geometry import DriveGeometry
from servicebot_cli.kinematics.frames import looks_like_tool

CENTRE_UNKNOWN = ("centre of mass not shown: the links' masses and <inertial> origins are too "
                  "large to add up to a finite number")
"""The note for a robot with mass but no finite centre of mass."""
REACH_UNKNOWN = ("arm reach not shown: its joints' origins are too large to add up to a finite "
                 "length (check reports them as SB019)")
"""The note for an arm whose reach overflows."""
_PARALLEL = 0.999  # |cos| between a segment and a joint axis that counts as "along the axis"


@dataclass(frozen=True)
class Dof:
    """Degrees of freedom: the drive wheels, the rest of the running gear, everything else.

    Attributes:
        total: Every movable joint's degrees of freedom (a follower's counts none).
        wheels: The drive wheels'.
        arm: The rest: an arm, a lift, a head.
        chassis: Passive casters (MiR's four swivels and wheels), suspension and steering
            joints that carry wheels (Leo Rover's rockers): neither drive nor arm.
    """

    total: int
    wheels: int
    arm: int
    chassis: int = 0


@dataclass(frozen=True)
class Box:
    """An axis-aligned box in the root link frame [m]."""

    min_m: Vec3
    max_m: Vec3


@dataclass(frozen=True)
class ArmReach:
    """The farthest the arm may reach from its shoulder: its links end to end.

    A bound: exact where the segments can line up (the bundled arm, an iiwa), above the
    real reach where a segment is offset along a joint's axis (a UR10's 1.75 m against the
    1.3 m it reaches). A prismatic joint adds its travel (a rail, a gripper's fingers).

    Attributes:
        shoulder: The first arm joint whose next segment does not lie along its own axis
            (a base yaw joint turns its column in place, so the column adds no reach).
        tip: The frame at the end of the longest chain below the first arm joint.
        reach_m: Sum of segment lengths from the shoulder to the tip, and of the travel of
            its prismatic joints [m].
        travel_m: The prismatic joints' part of ``reach_m`` [m].
    """

    shoulder: str
    tip: str
    reach_m: float
    travel_m: float = 0.0


@dataclass(frozen=True)
class DriveInfo:
    """The differential drive, from the foundation's drive geometry.

    Attributes:
        wheelbase_m: Distance between the front-most and rear-most wheel axles [m].
        top_speed_m_s: Straight-line speed at the wheel velocity limit [m/s].
        top_turn_rate_rad_s: Turn rate in place at the wheel velocity limit [rad/s].
    """

    left: tuple[str, ...]
    right: tuple[str, ...]
    wheel_radius_m: float
    track_m: float
    wheelbase_m: float
    max_wheel_speed_rad_s: float
    top_speed_m_s: float
    top_turn_rate_rad_s: float


@dataclass(frozen=True)
class Totals:
    """Whole-robot numbers at one configuration.

    Attributes:
        frame: The root link, the frame of the centre of mass and the bounding box.
        configuration_rad_or_m: The joint values used (others are zero) [rad or m].
        mass_kg: Sum of every link's mass [kg].
        centre_of_mass_m: In the root link frame [m]; None without mass.
        bounding_box_m: Around the visual geometry, root link frame [m].
        notes: What was left out and why (unreadable meshes, no drive found).
    """

    frame: str | None
    configuration_rad_or_m: dict[str, float]
    dof: Dof
    mass_kg: float
    centre_of_mass_m: Vec3 | None
    bounding_box_m: Box | None
    arm: ArmReach | None
    drive: DriveInfo | None
    notes: tuple[str, ...]


def mass_and_centre(robot: RobotDescription,
                    transforms: Mapping[str, FloatArray]) -> tuple[float, Vec3 | None]:
    """Total mass [kg] and centre of mass in the root frame [m]: sum of m_i c_i / sum m_i.

    The centre is None without mass, and when it is not a finite number: ``<inertial>``
    origins or masses so large that the sums overflow (see :data:`CENTRE_UNKNOWN`).
    """
    total, moment = 0.0, np.zeros(3)
    with np.errstate(all="ignore"):  # an overflow gives inf or nan, refused below
        for link in robot.links:
            inertial = link.inertial
            if inertial is None or inertial.mass_kg is None \
                    or not math.isfinite(inertial.mass_kg):
                continue
            transform = transforms.get(link.name)
            if transform is None:
                continue
            total += inertial.mass_kg
            moment += inertial.mass_kg * (transform[:3, :3] @ inertial.origin.xyz
                                          + transform[:3, 3])
        centre = moment / total if 0 < total < math.inf else None
    if centre is None or not np.all(np.isfinite(centre)):
        return total, None
    return total, vec3(centre)


def links_of_unknown_mass(robot: RobotDescription) -> list[str]:
    """Links whose mass is written but is no finite number (``nan``, ``inf``, text).

    :func:`mass_and_centre` leaves them out.
    """
    return [link.name for link in robot.links if link.inertial is not None
            and link.inertial.mass_kg is not None and not math.isfinite(link.inertial.mass_kg)]


def links_of_negative_mass(robot: RobotDescription) -> list[str]:
    """``arm (-0.5 kg)`` for each link whose mass is negative.

    :func:`mass_and_centre` counts it as written.
    """
    return [f"{link.name} ({link.inertial.mass_kg:g} kg)" for link in robot.links
            if link.inertial is not None and link.inertial.mass_kg is not None
            and link.inertial.mass_kg < 0]


def arm_reach(tree: KinematicTree, arm_joints: list[Joint],
              transforms: Mapping[str, FloatArray], tool: str | None = None) -> ArmReach | None:
    """The reach of the arm joints' longest chain, from the arm joint that starts it.

    Of the arm joints no other arm joint moves, the first whose chain to its tip holds the
    most arm joints: on a robot with one arm, its first joint; on Pepper, not the head's two
    joints that come first in the file. The tip is ``tool`` (the frame fk and ik move
    without ``--frame``) where the chain leads to it, else its deepest link. None without an
    arm, or where the reach is no finite length (:data:`REACH_UNKNOWN`).
    """
    edges = tree.edges  # built anew at each use: once here
    parent_joint = {j.child or "": j for j in edges}
    order = {joint.child: i for i, joint in enumerate(edges)}
    names = {joint.name for joint in arm_joints}
    starts = [j for j in arm_joints if not _arm_above(j.parent, parent_joint, names)]
    chains = [chain for joint in starts
              if (chain := _chain(tree, joint, parent_joint, tool, order))]
    if not chains:
        return None
    path = max(chains, key=lambda chain: sum(j.name in names for j in chain))  # the first one
    tip = path[-1].child or ""
    points = [transforms[j.child or ""][:3, 3] for j in path]
    start = 0
    with np.errstate(all="ignore"):  # an origin of 1e308: inf or nan, refused below
        while start < len(path) - 1 and _adds_no_reach(path[start], points, start, transforms):
            start += 1
        travel = sum(map(_travel_m, path[start:]))
        reach = sum(float(np.linalg.norm(points[i + 1] - points[i]))
                    for i in range(start, len(points) - 1)) + travel
    if not math.isfinite(reach):
        return None
    return ArmReach(path[start].name, tip, clean(reach), clean(travel))


def _travel_m(joint: Joint) -> float:
    """The farthest a prismatic joint moves its child from where it is at zero [m].

    0 for other joints, and for a prismatic one without limits (nothing bounds it).
    """
    limits = joint.limits
    if joint.type != "prismatic" or limits is None:
        return 0.0
    return max(abs(limits.lower or 0.0), abs(limits.upper or 0.0))


def _arm_above(link: str | None, parent_joint: Mapping[str, Joint], names: set[str]) -> bool:
    """Whether an arm joint (of ``names``) moves ``link``, through the joints above it."""
    seen = set()
    while link is not None and link in parent_joint and link not in seen:  # safe on loops
        seen.add(link)
        joint = parent_joint[link]
        if joint.name in names:
            return True
        link = joint.parent
    return False


def _chain(tree: KinematicTree, first: Joint, parent_joint: Mapping[str, Joint],
           tool: str | None, order: Mapping[str | None, int]) -> list[Joint] | None:
    """The joints from ``first`` down to ``tool``, else to its deepest link; None without one.

    ``tool`` where it is below ``first``. A camera's optical frame three fixed frames down
    is deeper than the gripper frame the tool is (Trossen's wxai: the reach was the
    camera's, 1 cm short of the gripper's).
    """
    if first.child is None:
        return None
    below = descendants(tree, first.child)
    # of the deepest links, the one fk and ik would take: a tool's name, else the last in
    # the file (the WAM's second finger, not its first): ``order``, each child's place
    tip = tool if tool is not None and tool in {name for name, _ in below} else max(
        below, key=lambda item: (item[1], looks_like_tool(item[0]),
                                 order.get(item[0], -1)))[0] if below else first.child
    path = [parent_joint[tip]] if tip != first.child else [first]
    while path[-1] is not first:
        path.append(parent_joint[path[-1].parent or ""])
    path.reverse()
    return path


def _adds_no_reach(joint: Joint, points: list[FloatArray], i: int,
                   transforms: Mapping[str, FloatArray]) -> bool:
    if _travel_m(joint) > 0:  # a lift adds its travel, wherever its child's frame is
        return False
    segment = points[i + 1] - points[i]
    length = float(np.linalg.norm(segment))
    if length < 1e-12:
        return True
    if not joint.movable:
        return False
    axis = transforms[joint.child or ""][:3, :3] @ np.array(joint.axis, dtype=float)
    norm = float(np.linalg.norm(axis))
    return norm > 0 and abs(float(axis @ segment)) / (norm * length) >= _PARALLEL


def unequal_wheels(drive: DriveGeometry) -> str | None:
    """A note when the drive wheels' radii differ by more than 1 %, or None."""
    radii = [w.radius_m for w in drive.wheels]
    if max(radii) <= min(radii) * 1.01:
        return None
    listed = ", ".join(f"{w.joint} {clean(w.radius_m):g} m" for w in drive.wheels)
    return (f"the drive wheels' radii differ ({listed}): the numbers here use their mean, "
            f"{clean(drive.wheel_radius_m):g} m, and such a base curves when both sides "
            "turn at one speed")


def drive_info(drive: DriveGeometry) -> DriveInfo:
    """The drive's numbers, with the wheelbase and top speeds the wheel limits allow."""
    xs = [w.position_m[0] for w in drive.wheels]
    return DriveInfo(
        left=drive.left, right=drive.right, wheel_radius_m=clean(drive.wheel_radius_m),
        track_m=clean(drive.track_m), wheelbase_m=clean(max(xs) - min(xs)),
        max_wheel_speed_rad_s=drive.max_wheel_speed_rad_s,
        top_speed_m_s=clean(drive.max_linear_m_s),
        top_turn_rate_rad_s=clean(drive.max_angular_rad_s),
    )


def dof_of(robot: RobotDescription, wheel_joints: set[str],
           chassis_joints: frozenset[str] = frozenset()) -> Dof:
    """Degrees of freedom, split into drive wheels, the rest of the running gear, the rest.

    A joint that follows another (``<mimic>``: a gripper's second finger) adds none: it moves
    only with its leader.
    """
    from servicebot_cli.kinematics.chain_mimic import Groups
    from servicebot_cli.kinematics.mimics import Mimics

    names = [j.name for j in robot.joints if j.movable]
    root = Groups.of(Mimics.among(robot.joints, names), len(names)).root  # a loop keeps one
    following = {name for k, name in enumerate(names) if root[k] != k}
    movable = [j for j in robot.joints if j.movable and j.name not in following]
    wheels = sum(DOF[j.type] for j in movable if j.name in wheel_joints)
    chassis = sum(DOF[j.type] for j in movable
                  if j.name in chassis_joints and j.name not in wheel_joints)
    total = sum(DOF[j.type] for j in movable)
    return Dof(total, wheels, total - wheels - chassis, chassis)


def box_of(robot: RobotDescription, transforms: Mapping[str, FloatArray],
           meshes: MeshLibrary) -> Box | None:
    """The bounding box of the visual geometry at ``transforms``."""
    box = bounding_box(posed_visuals(robot, transforms), meshes)
    return None if box is None else Box(vec3(box[0]), vec3(box[1]))
