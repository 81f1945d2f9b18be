"""Joint rules: types, limits, dynamics, axes, mimic chains, safety controllers (SB201-SB217)."""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.simulators import simulated_by
from servicebot_cli.common.errors import DescriptionError, NameNotFound
from servicebot_cli.description.elements import JOINT_TYPES, ONE_AXIS_TYPES, parse_float

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.robot import RobotDescription

_ADVICE = {
    "ball": "URDF has no ball joint: chain three revolute joints through two massless links",
    "spherical": "URDF has no spherical joint: chain three revolute joints through two "
    "massless links",
    "universal": "URDF has no universal joint: chain two revolute joints through a massless link",
    "hinge": "a hinge is 'revolute' (or 'continuous' without limits)",
    "slider": "a slider is 'prismatic'",
    "free": "a free joint is 'floating'",
    "gearbox": "URDF has no gearbox joint: use a revolute joint with <mimic>",
}
_TWO_PI = 2.0 * math.pi
_HALF_TURN_DEG = 180.0  # SB212: limits of +-180 degrees or more may stand for no limit


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Every joint issue of ``robot``."""
    simulator = simulated_by(robot)
    placed = _placed_by_gazebo(robot)
    for joint in robot.joints:
        written = joint.element is not None and joint.element.get("type") is not None
        if (joint.type or written) and joint.type not in JOINT_TYPES:  # type="" too
            advice = _ADVICE.get(joint.type.lower(), f"use one of: {', '.join(JOINT_TYPES)}")
            yield Issue("SB201", f"joint '{joint.name}' has type '{joint.type}', which URDF "
                        f"does not have; {advice}", joint.element)
            continue
        yield from _limits(joint, simulator, joint.name in placed)
        yield from _dynamics(joint)
        yield from _axis(joint)
        yield from _safety(joint)
    yield from _mimics(robot)
    yield from _wheel_speeds(robot)


def _dynamics(joint: Joint) -> Iterator[Issue]:
    """SB216: a negative damping (a warning) or friction (Pinocchio refuses it).

    Only where a joint moves along one axis: Pinocchio reads no other joint's dynamics, nor
    does anything else a fixed joint's.
    """
    if joint.type not in ONE_AXIS_TYPES:
        return
    element = joint.element.find("dynamics") if joint.element is not None else None
    if element is None:
        return
    for key in ("friction", "damping"):
        value = parse_float(element.get(key))
        if value is None or not value < 0:
            continue  # SB013/SB014 report what is not a number
        consequence = ("Pinocchio refuses it" if key == "friction"
                       else "a simulator feeds the joint energy instead of taking it")
        yield Issue("SB216", f"joint '{joint.name}' has <dynamics {key}=\"{value:g}\">: "
                    f"{consequence}", element, fix=f'{key}="{-value:g}", or 0 for none',
                    severity=Severity.WARNING if key == "damping" else None)


def _range_unwritten(joint: Joint) -> bool:
    """Whether the joint's ``<limit>`` writes neither lower nor upper."""
    element = joint.element.find("limit") if joint.element is not None else None
    return element is not None and not {"lower", "upper"} & element.attrib.keys()


def _zero_limit(joint: Joint, label: str, simulator: str | None, placed: bool) -> Issue:
    """SB206: an effort or velocity limit of 0, weighed by who reads it.

    MoveIt and position or trajectory control do not read effort: ROS-Industrial's arms
    write ``effort="0"`` and move. A simulator's motors and effort-limited controllers
    cannot drive such a joint (a passive joint moves by springs and contact only). A velocity
    limit of 0 holds the joint still for every planner and controller that enforces limits.
    Gazebo Classic's ros2_control system sets a position-commanded joint's position
    (``placed``), whatever its effort limit.
    """
    unit = "m/s" if joint.type == "prismatic" else "rad/s"
    if label == "velocity":
        return Issue("SB206", f"joint '{joint.name}' has velocity limit 0: planners and "
                     "controllers that enforce velocity limits cannot move it", joint.element,
                     fix=f"write the joint's top speed in {unit}")
    force = "N" if joint.type == "prismatic" else "N m"
    fix = (f"write the actuator's effort limit in {force} (a passive joint: the largest "
           "effort it may take)")
    if placed:
        return Issue("SB206", f"joint '{joint.name}' has effort limit 0: gazebo_ros2_control "
                     "sets its position directly, so it moves in Gazebo Classic, but gz_ros2_"
                     "control and effort-limited controllers could not drive it",
                     joint.element, fix=fix, severity=Severity.INFO)
    if simulator is None:
        return Issue("SB206", f"joint '{joint.name}' has effort limit 0: kinematics, MoveIt "
                     "and position control do not read effort, but a simulator or an "
                     "effort-limited controller could not drive the joint", joint.element,
                     fix=fix, severity=Severity.INFO)
    return Issue("SB206", f"joint '{joint.name}' has effort limit 0: {simulator}'s motors and "
                 "effort-limited controllers cannot drive it (a passive joint moves only by "
                 "springs and contact)", joint.element, fix=fix)


def _wheel_speeds(robot: RobotDescription) -> Iterator[Issue]:
    """SB215: a drive wheel (continuous, carrying a cylinder) without a velocity limit."""
    unlimited = [j for j in robot.joints if j.type == "continuous"
                 and not (j.limits and j.limits.velocity and math.isfinite(j.limits.velocity))]
    if not unlimited:
        return
    from servicebot_cli.kinematics.drive_geometry import drive_geometry
    from servicebot_cli.kinematics.mesh_wheels import no_points

    try:
        wheels = {w.joint for w in drive_geometry(robot, no_points).wheels}
    except (DescriptionError, ValueError, KeyError):
        return  # not a differential drive
    for joint in unlimited:
        if joint.name in wheels:
            yield Issue("SB215", f"wheel joint '{joint.name}' has no velocity limit: "
                        "`servicebot drive` refuses the robot, since nothing bounds the "
                        "speed it may command", joint.element,
                        fix='add <limit effort="..." velocity="..."/> with the motor\'s top '
                        "speed in rad/s")


_CLASSIC_SYSTEM = "gazebo_ros2_control/GazeboSystem"


def _placed_by_gazebo(robot: RobotDescription) -> set[str]:
    """The joints Gazebo Classic's ros2_control system commands by position alone.

    GazeboSystem::write sets such a joint's position (SetPosition), which its effort limit
    does not bound.
    """
    return {joint.name for block in robot.ros2_control if block.plugin == _CLASSIC_SYSTEM
            for joint in block.joints
            if joint.command_interfaces
            and {i.name for i in joint.command_interfaces} == {"position"}}


def _limits(joint: Joint, simulator: str | None, placed: bool = False) -> Iterator[Issue]:
    limits = joint.limits
    if limits is None:
        if joint.type in ("revolute", "prismatic"):
            yield Issue("SB202", f"{joint.type} joint '{joint.name}' has no <limit>",
                        joint.element, fix='add <limit lower="..." upper="..." effort="..." '
                        'velocity="..."/>' + (", or make the joint continuous"
                                              if joint.type == "revolute" else ""))
        return
    if not joint.movable:
        return
    for label, value in (("effort", limits.effort), ("velocity", limits.velocity)):
        if value is not None and value < 0:
            yield Issue("SB205", f"joint '{joint.name}' has {label} limit {value:g}", joint.element,
                        fix=f"{label}=\"{-value:g}\"")
        elif value == 0:
            yield _zero_limit(joint, label, simulator, placed)
    if joint.type == "continuous":
        element = joint.element.find("limit") if joint.element is not None else None
        if element is not None and ("lower" in element.attrib or "upper" in element.attrib):
            yield Issue("SB214", f"continuous joint '{joint.name}' has lower/upper limits, "
                        "which are ignored", element)
        return
    if joint.type not in ("revolute", "prismatic"):
        return
    lower, upper = limits.lower or 0.0, limits.upper or 0.0
    if lower > upper:
        yield Issue("SB203", f"joint '{joint.name}' has lower {lower:g} > upper {upper:g}: "
                    "pybullet reads that as no limit, and MuJoCo too without a word; a bounds "
                    "check (MoveIt's) as a range no position satisfies", joint.element,
                    fix=f'lower="{upper:g}" upper="{lower:g}", or type="continuous" for no limit')
    elif lower == upper and _range_unwritten(joint):
        # <limit effort velocity/> alone: urdfdom's lower and upper default to 0
        turning = ', or type="continuous" if it turns without end (a wheel)' \
            if joint.type == "revolute" else ""
        yield Issue("SB204", f"{joint.type} joint '{joint.name}' has a <limit> without lower "
                    "and upper, which default to 0: it cannot move", joint.element,
                    fix=f'give its range with lower="..." upper="..."{turning}')
    elif lower == upper:
        yield Issue("SB204", f"joint '{joint.name}' has lower = upper = {lower:g}: it cannot "
                    "move", joint.element, fix="make it fixed, or give it its real range")
    if joint.type == "revolute" and _degrees(lower, upper):
        # a symmetric range of half a turn or more each way is also how some descriptions
        # (ocs2's Kinova and PR2 roll joints, +-300) write a joint that turns without limit
        endless = ', or type="continuous" if it turns without limit' if (
            -lower == upper >= _HALF_TURN_DEG) else ""
        yield Issue("SB212", f"joint '{joint.name}' limits [{lower:g}, {upper:g}] look like "
                    "degrees; URDF angles are radians", joint.element,
                    fix=f'lower="{math.radians(lower):.6g}" upper="{math.radians(upper):.6g}"'
                    + endless)


def _degrees(lower: float, upper: float) -> bool:
    """Whole numbers from 30 to 720: degrees. Radian placeholders (10, 100, 1e9) are not."""
    values = [abs(v) for v in (lower, upper) if math.isfinite(v) and abs(v) > _TWO_PI + 1e-3]
    return bool(values) and all(v == round(v) for v in values) and 30 <= max(values) <= 720


def _axis(joint: Joint) -> Iterator[Issue]:
    if not joint.movable or joint.type == "floating":
        return
    x, y, z = joint.axis
    if not all(math.isfinite(c) for c in (x, y, z)):
        return  # SB013/SB014 report it
    norm = math.hypot(x, y, z)  # no overflow: an axis of 1e160 has length 1e160
    squared = x * x + y * y + z * z  # as Eigen's normalize() computes it
    if squared == math.inf or (squared == 0.0 and norm > 0.0):
        what = "long" if squared else "short"
        yield Issue("SB208", f"joint '{joint.name}' axis has length {norm:.8g}, too {what} to "
                    f"normalise: Pinocchio squares it to {'infinity' if squared else 'zero'} "
                    "and turns the joint by no rotation matrix", joint.element,
                    severity=Severity.ERROR, fix='write the unit axis: xyz="' + " ".join(
                        f"{c / norm:.6g}" for c in (x, y, z)) + '"')
    elif norm == 0.0:
        yield Issue("SB207", f"{joint.type} joint '{joint.name}' has axis 0 0 0", joint.element,
                    fix='write the axis, e.g. <axis xyz="0 0 1"/>')
    elif abs(norm - 1.0) > _AXIS_ROUNDING:
        unit = " ".join(f"{c / norm:.6g}" for c in (x, y, z))
        yield Issue("SB208", f"joint '{joint.name}' axis has length {norm:.8g}, not 1",
                    joint.element, fix=f'<axis xyz="{unit}"/>')


_AXIS_ROUNDING = 1e-4
"""How far from 1 an axis's length may be from the rounding of its written digits.

A CAD export's ``0.041054 0 -0.99916`` (length 1.0000031) and a hand-written 45 degrees,
``0.7071 0 0.7071`` (0.99999), are unit axes written with five or four digits: a tool that
does not normalise them moves the joint a hundred-thousandth too far or short.
"""


def _safety(joint: Joint) -> Iterator[Issue]:
    element = joint.element.find("safety_controller") if joint.element is not None else None
    if element is None or joint.limits is None or joint.type not in ("revolute", "prismatic"):
        return
    soft_lower = parse_float(element.get("soft_lower_limit"))
    soft_upper = parse_float(element.get("soft_upper_limit"))
    lower, upper = joint.limits.lower or 0.0, joint.limits.upper or 0.0
    problems = []
    if soft_lower is not None and soft_lower < lower:
        problems.append(f"soft_lower_limit {soft_lower:g} < lower {lower:g}")
    if soft_upper is not None and soft_upper > upper:
        problems.append(f"soft_upper_limit {soft_upper:g} > upper {upper:g}")
    if soft_lower is not None and soft_upper is not None and soft_lower > soft_upper:
        problems.append(f"soft_lower_limit {soft_lower:g} > soft_upper_limit {soft_upper:g}")
    if problems:
        yield Issue("SB213", f"joint '{joint.name}': " + "; ".join(problems), element,
                    fix=f"keep the soft limits inside [{lower:g}, {upper:g}]")


_UNFOLLOWABLE = ("fixed", "floating", "planar")
"""Joints a <mimic> cannot follow: MuJoCo ignores it on them, Pinocchio refuses it."""


def _mimics(robot: RobotDescription) -> Iterator[Issue]:
    names = [j.name for j in robot.joints]
    kinds = {j.name: j.type for j in robot.joints}
    follows: dict[str, str] = {}
    for joint in robot.joints:
        target = joint.mimic.joint if joint.mimic else None
        if target is None:
            continue  # no joint attribute: SB012
        if not target.strip():
            yield Issue("SB209", f"joint '{joint.name}' has <mimic joint=\"{target}\">, which "
                        "names no joint", joint.element,
                        fix="name the joint it follows, or remove the <mimic>")
        elif target == joint.name:
            yield Issue("SB210", f"joint '{joint.name}' mimics itself", joint.element)
        elif target not in names:
            others = [name for name in names if name != joint.name]  # not itself: SB210
            others = [name for name in others if kinds[name] not in _UNFOLLOWABLE] or others
            hint = str(NameNotFound.for_name(target, others)).split("; ", 1)[-1]
            yield Issue("SB209", f"joint '{joint.name}' mimics '{target}', which does not "
                        f"exist; {hint}", joint.element)
        elif kinds[target] in _UNFOLLOWABLE:  # a misspelled type is SB201's
            yield Issue("SB209", f"joint '{joint.name}' mimics '{target}', a {kinds[target]} "
                        "joint: Pinocchio, reading mimic joints, refuses it ('The parent joint "
                        "of the mimic joint is not in the kinematic tree'), MuJoCo ignores the "
                        f"<mimic> and yourdfpy holds '{joint.name}' still", joint.element,
                        fix="name the revolute, continuous or prismatic joint it follows")
        else:
            follows[joint.name] = target
    yield from _mimic_cycles(robot, follows)
    yield from _mimic_ranges(robot, follows)


_BOUNDED = ("revolute", "prismatic")


def _bounds(joint: Joint) -> tuple[float, float] | None:
    """A revolute or prismatic joint's finite [lower, upper], lower below upper; else None."""
    limits = joint.limits
    if joint.type not in _BOUNDED or limits is None or limits.lower is None \
            or limits.upper is None:
        return None
    lower, upper = limits.lower, limits.upper
    return (lower, upper) if math.isfinite(lower) and math.isfinite(upper) and lower < upper \
        else None


def _beyond(ends: list[float], own: tuple[float, float]) -> bool:
    """Whether ``ends`` leave ``own`` by over a twentieth of either range (the lesser)."""
    out = max(own[0] - ends[0], 0.0) + max(ends[1] - own[1], 0.0)
    return out > 0.05 * min(own[1] - own[0], max(ends[1] - ends[0], 1e-9))


def _mimic_ranges(robot: RobotDescription, follows: dict[str, str]) -> Iterator[Issue]:
    """SB217: a mimic joint the joint it follows takes outside its own limits.

    ``multiplier * followed + offset`` over the followed joint's range must stay in the
    joint's own: a simulator that enforces the limit holds the joint at it (the linkage does
    not follow), and servicebot's fk refuses such a value. Beyond a twentieth of that range,
    or of the joint's own, whichever is less (moveo's gripper: a multiplier of the wrong
    sign). MoveIt does not check a mimic joint's bounds: nothing says so there.
    """
    by_name = robot.joints_by_name
    for name, target in follows.items():
        joint, followed = by_name[name], by_name[target]
        own, range_ = _bounds(joint), _bounds(followed)
        mimic = joint.mimic
        if own is None or range_ is None or mimic is None or not (
                math.isfinite(mimic.multiplier) and math.isfinite(mimic.offset)):
            continue
        ends = sorted(mimic.multiplier * end + mimic.offset for end in range_)
        if not _beyond(ends, own):
            continue
        flipped = sorted(-mimic.multiplier * end + mimic.offset for end in range_)
        fix = (f'multiplier="{-mimic.multiplier:g}", if the two turn the other way round'
               if not _beyond(flipped, own)
               else f'make its limits cover [{ends[0]:g}, {ends[1]:g}], or fix the <mimic>')
        yield Issue("SB217", f"joint '{name}' = {mimic.multiplier:g} x '{target}' + "
                    f"{mimic.offset:g} (its <mimic>): as '{target}' moves over [{range_[0]:g}, "
                    f"{range_[1]:g}], it moves over [{ends[0]:g}, {ends[1]:g}], outside its "
                    f"limits [{own[0]:g}, {own[1]:g}]: the description contradicts itself (a "
                    "simulator enforcing the limit holds the joint there; servicebot fk refuses "
                    "such values)", joint.element, fix=fix)


def _mimic_cycles(robot: RobotDescription, follows: dict[str, str]) -> Iterator[Issue]:
    done: set[str] = set()
    for start in follows:
        path: list[str] = []
        node: str | None = start
        while node in follows and node not in done and node not in path:
            path.append(node)
            node = follows[node]
        if node in path:
            cycle = path[path.index(node):]
            yield Issue("SB211", "mimic cycle: " + " -> ".join([*cycle, cycle[0]]),
                        robot.joint(cycle[0]).element,
                        fix=f"remove the <mimic> of '{cycle[0]}'")
        done.update(path)
