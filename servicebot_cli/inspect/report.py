"""One inspection of a robot description: the sections asked for, computed once.

Only what a section needs is computed: the tree needs no model, the totals need the
Pinocchio model and perhaps meshes, the topics read the controller configuration.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.inspect import SCHEMA, SECTIONS
from servicebot_cli.inspect.controllers import Controller, find_controllers
from servicebot_cli.inspect.interfaces import InterfacesInfo, interfaces_info
from servicebot_cli.inspect.joints import FrameInfo, JointInfo, frame_info, joint_info
from servicebot_cli.inspect.links import LinkInfo, links_info
from servicebot_cli.inspect.plugins import PluginsInfo, plugins_info
from servicebot_cli.inspect.sensors import SensorInfo, sensors_info
from servicebot_cli.inspect.topics import TopicInfo, topics_info
from servicebot_cli.inspect.tree import KinematicTree, kinematic_tree

if TYPE_CHECKING:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.inspect.totals import Totals


@dataclass(frozen=True)
class TreeInfo:
    """The kinematic tree.

    Attributes:
        roots: Root links (one in a valid URDF).
        edges: Every joint between two links, in tree order (depth first).
        unreachable: Links no root reaches.
        tree: The tree itself, for drawing (not part of the JSON).
    """

    roots: tuple[str, ...]
    edges: tuple[JointInfo, ...]
    unreachable: tuple[str, ...]
    tree: KinematicTree = field(repr=False, compare=False)


@dataclass(frozen=True)
class TopicsInfo:
    """Topics with the controller configuration they were derived from.

    Attributes:
        controllers_file: The controller YAML read, None when there was none.
        controllers_found_by: ``--controllers``, ``gazebo_ros2_control`` or ``beside``.
        controllers: The controllers it lists (name and type).
        notes: Why some topics may be missing.
    """

    controllers_file: str | None
    controllers_found_by: str | None
    controllers: tuple[Controller, ...]
    topics: tuple[TopicInfo, ...]
    notes: tuple[str, ...]


@dataclass(frozen=True)
class Inspection:
    """The sections of one inspection; those not asked for are None."""

    robot: str
    file: str
    xacro_args: dict[str, str]
    tree: TreeInfo | None = None
    links: tuple[LinkInfo, ...] | None = None
    joints: tuple[JointInfo, ...] | None = None
    frames: tuple[FrameInfo, ...] | None = None
    sensors: tuple[SensorInfo, ...] | None = None
    plugins: PluginsInfo | None = None
    interfaces: InterfacesInfo | None = None
    topics: TopicsInfo | None = None
    totals: Totals | None = None

    def sections(self) -> list[str]:
        """The sections present, in display order."""
        return [name for name in SECTIONS if getattr(self, name) is not None]

    def to_json(self) -> dict[str, Any]:
        """The documented JSON form: schema, robot, source, then each section present."""
        from servicebot_cli.common.jsonable import to_jsonable

        document: dict[str, Any] = {"schema": SCHEMA, "robot": self.robot, "file": self.file,
                                    "xacro_args": self.xacro_args}
        for name in self.sections():
            document[name] = to_jsonable(getattr(self, name))
        return document


@dataclass(frozen=True)
class Request:
    """What to inspect.

    Attributes:
        sections: Section names, a subset of SECTIONS.
        configuration: Joint values for the totals [rad or m]; others are zero.
        clamp: Clamp out-of-limit values instead of refusing them.
        resolver: Finds ``package://`` meshes.
        controllers: A controller YAML given by the user, else None to look for one.
    """

    sections: Sequence[str] = SECTIONS
    configuration: Mapping[str, float] = field(default_factory=dict)
    clamp: bool = False
    resolver: PackageResolver | None = None
    controllers: Path | None = None


def inspect_robot(robot: RobotDescription, request: Request) -> Inspection:
    """Compute the requested sections of ``robot``."""
    wanted = set(request.sections)
    parts: dict[str, Any] = {}
    tree = kinematic_tree(tuple(link.name for link in robot.links), robot.joints)
    if "tree" in wanted:
        edges = tuple(joint_info(j) for j in tree.edges)
        parts["tree"] = TreeInfo(tree.roots, edges, tree.unreachable, tree)
    if "links" in wanted:
        parts["links"] = links_info(robot.links)
    if "joints" in wanted:
        parts["joints"] = tuple(joint_info(j) for j in robot.movable_joints)
    if "frames" in wanted:
        from servicebot_cli.inspect.poses import link_transforms

        transforms = link_transforms(robot)
        parts["frames"] = tuple(frame_info(f, transforms) for f in robot.fixed_frames)
    sensors = sensors_info(robot.sensors)
    plugins = plugins_info(robot.gazebo, robot.sensors, robot.ros2_control)
    for name, value in (("sensors", sensors), ("plugins", plugins)):
        if name in wanted:
            parts[name] = value
    if "interfaces" in wanted:
        parts["interfaces"] = interfaces_info(robot.ros2_control, robot.transmissions)
    if "topics" in wanted:
        parts["topics"] = _topics(robot, sensors, plugins, request.controllers)
    if "totals" in wanted:
        parts["totals"] = _totals(robot, tree, request)
    return Inspection(robot.name, robot.display, dict(robot.xacro_args), **parts)


def _topics(robot: RobotDescription, sensors: tuple[SensorInfo, ...], plugins: PluginsInfo,
            explicit: Path | None) -> TopicsInfo:
    controllers, notes = find_controllers(robot.path, robot.plugins, explicit)
    # sdformat applies a <gazebo> block to the link (or joint) it names, and drops it
    # otherwise: no sensor is made of a block that names none of the robot's parts
    made = tuple(s for s in sensors if s.link and s.link in robot.part_names)
    dropped = tuple(f"sensor '{s.name}' publishes nothing: its <gazebo> block names "
                    + (f"'{s.link}', no link or joint of the robot" if s.link else "no link")
                    + ", and Gazebo makes no sensor of it (check reports it)"
                    for s in sensors if s not in made)
    return TopicsInfo(
        controllers_file=controllers.file if controllers else None,
        controllers_found_by=controllers.found_by if controllers else None,
        controllers=controllers.controllers if controllers else (),
        topics=topics_info(made, plugins.ros2_control, controllers, plugins.gazebo),
        notes=(*notes, *dropped),
    )


def _tool_frame(robot: RobotDescription) -> str | None:
    """The frame fk and ik move without ``--frame``; None where they refuse the tree."""
    from servicebot_cli.kinematics.frames import default_tool_frame, require_tree

    try:
        require_tree(robot)
        return default_tool_frame(robot).name
    except DescriptionError:
        return None


def _totals(robot: RobotDescription, tree: KinematicTree, request: Request) -> Totals:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.inspect import totals as t
    from servicebot_cli.inspect.geometry import mesh_library
    from servicebot_cli.inspect.poses import link_transforms
    from servicebot_cli.kinematics.drive_geometry import drive_geometry
    from servicebot_cli.kinematics.link_poses import link_transforms as kinematic_poses
    from servicebot_cli.kinematics.running_gear import chassis_joints, loose_wheels

    notes: list[str] = []
    meshes = mesh_library(robot, request.resolver or PackageResolver.from_environment())
    try:
        drive = drive_geometry(robot, meshes.points)
    except DescriptionError as exc:
        drive = None
        notes.append(str(exc).split(": ", 1)[-1])
    # no drive: its wheels (one side's, or drawn as meshes only) are still no arm
    if drive is not None and (unequal := t.unequal_wheels(drive)) is not None:
        notes.append(unequal)
    wheels = {w.joint for w in drive.wheels} if drive else set(
        loose_wheels(robot, kinematic_poses(robot)))
    chassis = frozenset(chassis_joints(robot, sorted(wheels)))
    zero = link_transforms(robot)
    posed = link_transforms(robot, request.configuration, clamp=request.clamp)
    mass, centre = t.mass_and_centre(robot, posed)
    unknown = t.links_of_unknown_mass(robot)
    if unknown:
        notes.append(f"left out of the mass and its centre: {', '.join(unknown)}, whose mass "
                     "is not a finite number (check reports it as SB014)")
    negative = t.links_of_negative_mass(robot)
    if negative:
        notes.append(f"counted as written, though no body has a negative mass: "
                     f"{', '.join(negative)} (check reports it as SB302); the total and its "
                     "centre are not the robot's")
    if centre is None and mass > 0:
        notes.append(t.CENTRE_UNKNOWN)
    box = t.box_of(robot, posed, meshes)
    arm = [j for j in robot.movable_joints if j.name not in wheels and j.name not in chassis]
    notes.extend(meshes.problems)
    reach = t.arm_reach(tree, arm, zero, _tool_frame(robot) if arm else None)
    if reach is None and arm:
        notes.append(t.REACH_UNKNOWN)
    return t.Totals(
        frame=robot.root_link, configuration_rad_or_m=dict(request.configuration),
        dof=t.dof_of(robot, wheels, chassis),
        mass_kg=mass, centre_of_mass_m=centre, bounding_box_m=box,
        arm=reach, drive=t.drive_info(drive) if drive else None,
        notes=tuple(notes),
    )
