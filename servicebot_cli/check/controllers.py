"""Controller configuration rules: a ros2_control controllers YAML against a URDF (SB601-SB607).

What the file's parameters are worth whatever the robot (SB608) is
:mod:`~servicebot_cli.check.controller_params`'s.

Pure: YAML text and a RobotDescription in, issues out, each placed at its YAML line.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.controller_interfaces import state_dofs
from servicebot_cli.check.controller_sections import (
    JOINT_KEYS,
    Sections,
    controller_types,
    get,
)
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.ros2_control import GAZEBO_PID, exported_as, exports_as_listed
from servicebot_cli.check.substitutions import leading_substitution, substituted
from servicebot_cli.check.wheel_numbers import driven, mismatch, track_m
from servicebot_cli.common.errors import DescriptionError, NameNotFound
from servicebot_cli.common.listing import some_of

if TYPE_CHECKING:
    from servicebot_cli.check.controller_interfaces import Claim
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.drive_geometry import DriveGeometry
    from servicebot_cli.kinematics.mesh_wheels import MeshPoints

_PID = "pid_controller/PidController"

ROS2_CONTROLLERS = frozenset((
    "ackermann_steering_controller", "admittance_controller", "bicycle_steering_controller",
    "diff_drive_controller", "effort_controllers", "force_torque_sensor_broadcaster",
    "forward_command_controller", "gpio_controllers", "gripper_controllers",
    "imu_sensor_broadcaster", "joint_state_broadcaster", "joint_trajectory_controller",
    "mecanum_drive_controller", "omni_wheel_drive_controller", "parallel_gripper_controller",
    "parallel_gripper_action_controller",  # the plugin's namespace in parallel_gripper_controller
    "gps_sensor_broadcaster",
    "pid_controller", "pose_broadcaster", "position_controllers", "range_sensor_broadcaster",
    "steering_controllers_library", "tricycle_controller", "tricycle_steering_controller",
    "velocity_controllers",
))
"""The packages of ros-controls/ros2_controllers: their ``joint``/``joints`` name URDF joints."""


def check(found: Sections, display: str, robot: RobotDescription,
          meshes: MeshPoints | None = None,
          spawned: frozenset[str] | None = None) -> Iterator[Issue]:
    """Every issue of the controller sections ``found`` (of file ``display``) against ``robot``.

    ``meshes``: the vertices of mesh shapes (wheels drawn as meshes are where those are).
    ``spawned``: the controllers checked (those a launch spawns); None: every one.
    """
    checker = _Checker(display, robot, found, meshes)
    checker.every_controller = spawned is None
    for name, params in found.items():
        kind = checker.types.get(name)
        if spawned is not None and name not in spawned:
            continue
        if name != "controller_manager" and _names_joints(kind):
            for section in checker.for_this_robot(params):
                yield from checker.section(name, section)
                yield from checker.interfaces(name, kind, section)


def _names_joints(controller_type: str | None) -> bool:
    """Whether a controller's ``joint``/``joints`` are URDF joint names, as far as known.

    True for a ros2_controllers type and for a controller whose type the file does not say.
    A third party's controller is not checked: Kortex's twist controller takes
    ``joint: tcp``, the prefix of interfaces its hardware exports, not a URDF joint.
    """
    return controller_type is None or controller_type.partition("/")[0] in ROS2_CONTROLLERS


def _items(node: yaml.Node | None) -> list[yaml.Node]:
    """The items of a list node, a scalar as a list of one; none for no node."""
    if node is None:
        return []
    return list(node.value) if isinstance(node, yaml.SequenceNode) else [node]


def _number(node: yaml.Node | None) -> float | None:
    """A finite number, or None (a wheel radius of 1e400 or a multiplier of nan is none)."""
    if not isinstance(node, yaml.ScalarNode):
        return None
    try:
        value = float(node.value)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


class _Checker:
    def __init__(self, display: str, robot: RobotDescription,
                 sections: Sections | None = None, meshes: MeshPoints | None = None) -> None:
        self.display = display
        self.robot = robot
        self.meshes = meshes
        self.sections = sections or {}
        self.controllers = frozenset(self.sections)
        self.joints = robot.joints_by_name
        self.types = controller_types(self.sections)
        self._geometry: DriveGeometry | None | str = None
        self._exported: dict[str, dict[str, list[str]]] | None = None
        self._drivers: dict[str, list[str]] = {}  # plugins that may export more than listed
        self.every_controller = True  # not only those --spawned names

    def where(self, node: yaml.Node) -> tuple[str, int, int]:
        return (self.display, node.start_mark.line + 1, node.start_mark.column + 1)

    def geometry(self) -> DriveGeometry | str:
        if self._geometry is None:
            from servicebot_cli.kinematics.drive_geometry import drive_geometry

            try:
                self._geometry = drive_geometry(self.robot, self.meshes)
            except DescriptionError as exc:
                self._geometry = str(exc).split(": ", 1)[-1]
        return self._geometry

    def for_this_robot(self, sections: list[yaml.MappingNode]) -> list[yaml.MappingNode]:
        """The sections of one controller that are for this robot.

        Of a controller configured in several namespaces, those whose joint names are all
        this robot's, when some are: the others configure another robot's controller (the
        other controller manager of ros2_control_demos' example 15). Else every section.
        """
        naming = [s for s in sections if any(get(s, key) is not None for key in JOINT_KEYS)]
        fitting = [s for s in naming if self.fits(s)]
        if not fitting or len(fitting) == len(naming):
            return sections
        return [s for s in sections if s not in naming or s in fitting]

    def fits(self, params: yaml.MappingNode) -> bool:
        """Whether every joint name of ``params`` is a joint of the robot."""
        for key in JOINT_KEYS:
            for item in _items(get(params, key)):
                if not isinstance(item, yaml.ScalarNode):
                    return False
                if self.prefixed_ends(str(item.value)) == []:
                    return False
                if not self.not_a_joint(str(item.value)) and item.value not in self.joints:
                    return False
        return True

    def section(self, name: str, params: yaml.MappingNode) -> Iterator[Issue]:
        for key in JOINT_KEYS:
            node = get(params, key)
            if node is not None:
                yield from self.names(name, key, node)
        if get(params, "left_wheel_names") is not None:
            yield from self.wheels(name, params)

    def names(self, section: str, key: str, node: yaml.Node) -> Iterator[Issue]:
        if isinstance(node, yaml.ScalarNode) and str(node.value).lstrip().startswith("["):
            return  # a list in quotes: one string, which SB608 reports
        items = _items(node)
        if not items and key.endswith("_wheel_names"):
            yield Issue("SB601", f"{section}.{key} names no wheel: diff_drive_controller "
                        "refuses an empty list", where=self.where(node),
                        fix=f"{key}: [the wheel joints of that side]")
        for item in items:
            if not isinstance(item, yaml.ScalarNode):
                yield Issue("SB601", f"{section}.{key} must be a list of joint names",
                            where=self.where(item))
                continue
            reference = self.unexported_reference(str(item.value))
            if reference is not None:
                yield Issue("SB602", f"{section}.{key}: '{item.value}' names {reference}",
                            where=self.where(item), fix="name one of those references")
                continue
            prefixed = self.prefixed_issue(section, key, str(item.value))
            if prefixed is not None:
                yield dataclasses.replace(prefixed, where=self.where(item))
                continue
            if self.not_a_joint(item.value):
                continue
            joint = self.joints.get(item.value)
            if joint is None and item.value in self.components():  # a gpio or a sensor
                continue
            if joint is None:
                hint = [self.closest(section, str(item.value))]
                only = (" (only its <ros2_control> names it: Gazebo's ros2_control skips "
                        "such a joint, and robot_state_publisher has no state of it)"
                        if item.value in self.exported() else "")
                close = hint[-1].startswith("did you mean")
                unspawned = (f"; if the launch spawns no '{section}' (a file shared by "
                             "several robots), check with --spawned NAME[,NAME]"
                             if self.every_controller else "")
                yield Issue("SB602", f"{section}.{key}: joint '{item.value}' is not in "
                            f"{self.robot.display}{only}; {hint[-1]}", where=self.where(item),
                            fix=None if close else f"name a joint of the URDF{unspawned}")
            elif not joint.movable:
                yield Issue("SB606", f"{section}.{key}: joint '{item.value}' is {joint.type} "
                            "in the URDF", where=self.where(item))

    def prefixed_ends(self, name: str) -> list[str] | None:
        """The robot's joints, sensors and GPIOs a prefixed name may be; None: not prefixed.

        A joint a launch file prefixes (``$(var tf_prefix)elbow_joint``) ends as written
        whatever the prefix: those whose names end so.
        """
        found = leading_substitution(name)
        return None if found is None else self.ending(found[1])

    def ending(self, tail: str) -> list[str]:
        """The robot's joints, sensors and GPIOs whose names end in ``tail``."""
        return [other for other in (*self.joints, *self.components()) if other.endswith(tail)]

    def prefixed_issue(self, section: str, key: str, name: str) -> Issue | None:
        """SB602 for a prefixed name no joint ends like, SB606 when only fixed ones do."""
        found = leading_substitution(name)
        if found is None:
            return None
        prefix, tail = found
        ends = self.ending(tail)
        if not ends:
            candidates = self.suggestible(section)
            close = difflib.get_close_matches(tail, candidates, n=1, cutoff=0.6)
            meant = f"; did you mean '{prefix}{close[0]}'?" if close else ""
            return Issue("SB602", f"{section}.{key}: joint '{name}': no joint of "
                         f"{self.robot.display} ends in '{tail}', so none is named so whatever "
                         f"{prefix} is{meant}", fix=None if close else "name a joint of the URDF")
        joints = [self.joints[end] for end in ends if end in self.joints]
        if len(joints) == len(ends) and not any(joint.movable for joint in joints):
            return Issue("SB606", f"{section}.{key}: joint '{name}' can only be "
                         f"{', '.join(repr(j.name) for j in joints)} with a prefix, "
                         f"{joints[0].type} in the URDF")
        return None

    def suggestible(self, section: str) -> list[str]:
        """Joints worth suggesting in ``section``: moving, and named by none of its lists."""
        taken = {str(item.value) for params in self.sections.get(section, [])
                 for key in JOINT_KEYS
                 for item in _items(get(params, key)) if isinstance(item, yaml.ScalarNode)}
        taken |= {prefixed[1] for name in taken if (prefixed := leading_substitution(name))}
        return [j for j, joint in self.joints.items() if joint.movable and j not in taken]

    def closest(self, section: str, name: str) -> str:
        """The names ``name`` may have meant: 'did you mean ...', or what the URDF has.

        A chained reference whose controller is misspelled is said as that controller's
        reference. Only joints that move, and that none of the section's lists names already
        (the same list's other joints, the other side's wheels), are suggested: the
        controller refuses a joint twice, and a fixed one.
        """
        head, slash, rest = name.partition("/")
        controller = difflib.get_close_matches(head, sorted(self.controllers), n=1,
                                               cutoff=0.8) if slash else []
        if controller:
            return (f"did you mean '{controller[0]}/{rest}', a reference of the controller "
                    f"'{controller[0]}'?")
        joints = self.suggestible(section)
        if not joints:
            moving = any(joint.movable for joint in self.joints.values())
            return ("every joint of the URDF that moves is listed already" if moving
                    else "the URDF has no joint that moves")
        return str(NameNotFound.for_name(name, joints)).split("; ", 1)[-1]

    def components(self) -> set[str]:
        """The sensors and GPIOs of every ``<ros2_control>``: names that are no joints."""
        return {item.name for block in self.robot.ros2_control
                for item in (*block.sensors, *block.gpios)}

    def exported(self) -> dict[str, dict[str, list[str]]]:
        """Each joint's exported interfaces by kind (``command``, ``state``).

        Of every ``<ros2_control>`` block: one joint may be in two (an actuator and a sensor).
        """
        if self._exported is None:
            self._exported = {}
            for block in self.robot.ros2_control:  # a gpio's or sensor's too: component/name
                for item in (*block.joints, *block.sensors, *block.gpios):
                    kinds = self._exported.setdefault(item.name, {"command": [], "state": []})
                    if not exports_as_listed(block.plugin):
                        self._drivers.setdefault(item.name, []).append(str(block.plugin).strip())
                    for kind, interfaces in (("command", item.command_interfaces),
                                             ("state", item.state_interfaces)):
                        names = (exported_as(i.name, block.plugin) for i in interfaces)
                        kinds[kind] += [name for name in names if name not in kinds[kind]]
        return self._exported

    def interfaces(self, section: str, controller_type: str | None,
                   params: yaml.MappingNode) -> Iterator[Issue]:
        """SB607 for what the controller claims and the URDF's ``<ros2_control>`` lacks.

        Only where the URDF has ``<ros2_control>`` joints (else the hardware is described
        elsewhere), and for URDF joints that can move (a fixed one is SB606; an unknown one
        SB602; a chained controller's reference is that controller's, not the hardware's).
        """
        from servicebot_cli.check.controller_interfaces import claims

        exported = self.exported()
        if controller_type is None or not exported:
            return
        absent: dict[str, Claim] = {}
        lacking: dict[tuple[str, str, int], list[Claim]] = {}
        unknown_dofs: dict[str, Claim] = {}
        sensors: dict[str, list[Claim]] = {}  # each sensor's claims it does not export
        chained: dict[tuple[str, str, str], tuple[Claim, list[str]]] = {}
        for claim in claims(controller_type, params):
            name = str(claim.joint.value)
            through = self.chained_exports(name)
            if through is not None:  # a pid_controller's reference: what it exports
                if claim.interface not in through and not claim.humble_only:
                    chained.setdefault((name, claim.kind, claim.interface), (claim, through))
                continue
            if claim.sensor:
                if not self.not_a_joint(name) and claim.interface not in exported.get(
                        name, {}).get(claim.kind, ()):
                    sensors.setdefault(name, []).append(claim)
                continue
            joint = self.joints.get(name)
            if joint is None and claim.key.endswith("dof_names") and name not in exported \
                    and not self.not_a_joint(name):
                unknown_dofs.setdefault(name, claim)
            if joint is None or not joint.movable or substituted(claim.interface) \
                    or self.not_a_joint(name):
                continue
            if name not in exported:
                absent.setdefault(name, claim)
            elif claim.interface not in exported[name][claim.kind]:
                lacking.setdefault((claim.kind, claim.interface, id(claim.named_at)),
                                   []).append(claim)
        for name, claim in unknown_dofs.items():
            hint = str(NameNotFound.for_name(name, [*self.joints, *exported])).split("; ", 1)
            yield Issue("SB602", f"{section}.{claim.key}: '{name}' is no joint and no "
                        f"<ros2_control> component of {self.robot.display}: its interfaces do "
                        f"not exist; {hint[-1]}", where=self.where(claim.joint),
                        fix="name a joint or a component of the URDF's <ros2_control>")
        yield from self.sensor_claims(section, sensors, exported)
        for (name, kind, interface), (claim, through) in chained.items():
            head = name.partition("/")[0]
            feedback = (kind == "state" and interface == "position" and "velocity" in through
                        and claim.key.endswith("_wheel_names"))
            yield Issue("SB607", f"{section} claims the {kind} interface '{interface}' of "
                        f"'{name}', which pid_controller '{head}' does not export (it exports "
                        f"{', '.join(through) or 'none'}, its reference_and_state_interfaces): "
                        "the controller manager cannot activate it",
                        where=self.where(claim.named_at),
                        fix="position_feedback: false (odometry from the wheels' velocities)"
                        if feedback else f"add {interface} to {head}'s "
                        "reference_and_state_interfaces, or claim one it exports")
        for name, claim in absent.items():
            yield Issue("SB607", f"{section}.{claim.key}: joint '{name}' is in no "
                        f"<ros2_control> of {self.robot.display}: the hardware exports none of "
                        f"its interfaces, and the controller manager cannot activate {section}",
                        where=self.where(claim.joint),
                        fix=f"add '{name}' with its interfaces to the URDF's <ros2_control>")
        for (kind, interface, _), found in lacking.items():
            names = list(dict.fromkeys(str(c.joint.value) for c in found))
            which = (f"joint '{names[0]}'" if len(names) == 1
                     else "joints " + ", ".join(f"'{n}'" for n in names))
            if all(c.humble_only for c in found):  # open_loop: only Humble claims it
                yield Issue("SB607", f"{section} has open_loop: true, and Humble's "
                            f"diff_drive_controller still claims the {kind} interface "
                            f"'{interface}' of {which}, which {self.robot.display} does not "
                            f"export ({_exports(exported, names, kind)}): on Humble the "
                            "controller manager cannot activate it (from Jazzy on, an open "
                            "loop claims no state interface)", severity=Severity.WARNING,
                            where=self.where(found[0].named_at),
                            fix=_interface_fix(kind, interface) + ", for Humble")
                continue
            drivers = list(dict.fromkeys(p for n in names for p in self._drivers.get(n, ())))
            if drivers:  # its driver's code, not the URDF, may say what it exports
                yield Issue("SB607", f"{section} claims the {kind} interface '{interface}' of "
                            f"{which}, which {self.robot.display}'s <ros2_control> does not "
                            f"list ({_exports(exported, names, kind)}): the controller manager "
                            f"cannot activate it, unless the hardware plugin '{drivers[0]}' "
                            "exports it unlisted (some drivers export interfaces of their own)",
                            where=self.where(found[0].named_at), severity=Severity.WARNING,
                            fix=_interface_fix(kind, interface) + ", if the driver does not "
                            "export it")
                continue
            yield Issue("SB607", f"{section} claims the {kind} interface '{interface}' of "
                        f"{which}, which {self.robot.display} does not export "
                        f"({_exports(exported, names, kind)}): the controller manager cannot "
                        "activate it",
                        where=self.where(found[0].named_at), fix=_interface_fix(kind, interface))

    def sensor_claims(self, section: str, sensors: dict[str, list[Claim]],
                      exported: dict[str, dict[str, list[str]]]) -> Iterator[Issue]:
        """SB602 and SB607 for the sensors a broadcaster reads.

        SB602 for a sensor_name no ``<ros2_control>`` sensor has; SB607 for the states of a
        sensor it reads and the sensor does not export (one issue a sensor).
        """
        for name, found in sensors.items():
            claim = found[0]
            wanted = some_of([c.interface for c in found], 4)
            if name not in exported:
                components = [n for n in exported if n not in self.joints]
                hint = str(NameNotFound.for_name(name, components)).split("; ", 1)
                yield Issue("SB602", f"{section}.sensor_name: '{name}' is no <ros2_control> "
                            f"sensor of {self.robot.display}: the states it reads ({wanted}) "
                            f"do not exist, and the controller manager cannot activate "
                            f"{section}; {hint[-1]}", where=self.where(claim.joint),
                            fix="name a <sensor> of the URDF's <ros2_control>")
                continue
            driver = self._drivers.get(name)
            yield Issue("SB607", f"{section} reads the state interfaces {wanted} of sensor "
                        f"'{name}', which {self.robot.display} does not export "
                        f"({_exports(exported, [name], 'state')}): the controller manager "
                        "cannot activate it" + (f", unless the hardware plugin '{driver[0]}' "
                                                "exports them unlisted" if driver else ""),
                        where=self.where(claim.joint),
                        severity=Severity.WARNING if driver else None,
                        fix=f"add <state_interface name=\"{found[0].interface}\"/> and the "
                        "others to the sensor's <ros2_control> entry")

    def chained_exports(self, name: str) -> list[str] | None:
        """What a pid_controller of this file exports for ``name`` (``pid/DOF``), or None.

        Its reference and state interfaces are ``pid/DOF/INTERFACE`` for each of its
        reference_and_state_interfaces (pid_controller.cpp); None for any other name.
        """
        head, slash, dof = name.partition("/")
        if not slash or self.types.get(head) != _PID:
            return None
        for params in self.sections.get(head, []):
            if dof in {str(d.value) for d in state_dofs(params)}:
                listed = get(params, "reference_and_state_interfaces")
                items = listed.value if isinstance(listed, yaml.SequenceNode) else [listed]
                return [str(i.value) for i in items if isinstance(i, yaml.ScalarNode)
                        and i.value]
        return None

    def not_a_joint(self, name: str) -> bool:
        """A name that is not a URDF joint's and is right as written.

        A chained controller's reference interface (``pid_controller_left_wheel_joint/
        left_wheel_joint``: a controller of this file, a slash, its reference) and a name a
        launch file fills in (``$(var joint_prefix)1``; PAL's ``${EE_SIDE_PREFIX}_...``,
        which launch_pal's ``parse_parametric_yaml`` rewrites).
        """
        return substituted(name) or name.partition("/")[0] in self.controllers

    def unexported_reference(self, name: str) -> str | None:
        """Why a chained reference ``CONTROLLER/DOF`` names no reference that controller has.

        A chainable controller with ``dof_names`` (pid_controller) exports a reference
        interface per name: ``pid_controller_left_wheel_joint/left_wheel_joint``. None when
        the reference is one of them, or its controller names no dof_names here.
        """
        head, slash, rest = name.partition("/")
        if not slash or head not in self.controllers or substituted(name):
            return None
        dofs = [str(dof.value) for section in self.sections.get(head, [])
                for dof in state_dofs(section)]
        if not dofs or rest.partition("/")[0] in dofs:
            return None
        return (f"a reference of controller '{head}', which exports references of its "
                f"dof names only ({', '.join(dofs)})")

    def joint_of(self, name: str) -> str:
        """The joint a chain of controller references ends at, or ``name`` itself.

        ``position_controller/joint1_position_controller/joint1`` ends at ``joint1``; a
        reference ``joint1/position`` (an interface) at ``joint1``, when that is a joint.
        """
        head, slash, rest = name.partition("/")
        while slash and head in self.controllers:
            name = rest
            head, slash, rest = name.partition("/")
        return head if slash and head in self.joints and name not in self.joints else name

    def wheels(self, section: str, params: yaml.MappingNode) -> Iterator[Issue]:
        found = self.geometry()
        # No round wheels in the URDF (mesh wheels: igus ReBeL's platform): the joints the
        # controller names still place its wheels, which is all the separation needs
        geometry = self.named_geometry(params) if isinstance(found, str) else found
        if geometry is None:
            return
        for key, side in (("left_wheel_names", "left"), ("right_wheel_names", "right")):
            node = get(params, key)
            items = node.value if isinstance(node, yaml.SequenceNode) else []
            for item in items:
                joint = self.joint_of(str(item.value))
                wheel = next((w for w in geometry.wheels if w.joint == joint), None)
                if wheel is not None and wheel.side != side:
                    via = f" (joint '{joint}')" if joint != item.value else ""
                    yield Issue("SB605", f"{section}.{key}: '{item.value}'{via} is on the "
                                f"{wheel.side} (y = {wheel.position_m[1]:g} m in the URDF)",
                                where=self.where(item))
        radius_m, track_m = self.driven(params, geometry)
        if not math.isnan(radius_m):  # mesh wheels: no radius to compare with
            yield from self.value(section, params, "wheel_radius", radius_m, "SB603",
                                  ("left_wheel_radius_multiplier",))
        per_side = [sum(w.side == side for w in geometry.wheels) for side in ("left", "right")]
        yield from self.value(section, params, "wheel_separation", track_m, "SB604",
                              ("wheel_separation_multiplier",), skid=min(per_side) >= 2)

    def named_geometry(self, params: yaml.MappingNode) -> DriveGeometry | None:
        """The wheels on the joints the controller names; None unless on both sides.

        Their radius is their round meshes' (NaN, unknown, where a wheel has none).
        """
        from servicebot_cli.kinematics.drive_geometry import DriveGeometry
        from servicebot_cli.kinematics.plugin_wheels import wheels_named

        wheels = wheels_named(self.robot, self.named_wheels(params), meshes=self.meshes)
        track = track_m(wheels)
        radius_m = sum(w.radius_m for w in wheels) / len(wheels) if wheels else math.nan
        return None if track is None else DriveGeometry(tuple(wheels), radius_m, track,
                                                        math.inf)

    def named_wheels(self, params: yaml.MappingNode) -> set[str]:
        """The wheel joints the controller names, chains of references followed."""
        return {self.joint_of(str(item.value))
                for key in ("left_wheel_names", "right_wheel_names")
                for node in [get(params, key)] if isinstance(node, yaml.SequenceNode)
                for item in node.value if isinstance(item, yaml.ScalarNode)}

    def driven(self, params: yaml.MappingNode, geometry: DriveGeometry) -> tuple[float, float]:
        """Wheel radius and track of the wheels the controller drives, as far as it names them.

        As :func:`.wheel_numbers.driven` reads them.
        """
        radius, track, _ = driven(geometry, self.named_wheels(params))
        return radius, track

    def value(self, section: str, params: yaml.MappingNode, key: str, expected: float,
              code: str, multipliers: tuple[str, ...], skid: bool = False) -> Iterator[Issue]:
        """SB603/SB604 where ``key`` is not the URDF's ``expected``.

        ``skid``: the robot has two or more wheels a side, which skid when it turns; a
        wider effective track, up to twice the wheels' (:mod:`.wheel_numbers`), is how its
        odometry is calibrated (Clearpath's Warthog writes 1.5 m on a 1.14 m track, the
        Jackal multiplies by 1.5): a warning.
        """
        node = get(params, key)
        if isinstance(node, yaml.ScalarNode) and substituted(str(node.value)):
            return  # the launch file fills it in
        given = _number(node)
        if node is None or given is None:
            yield Issue(code, f"{section}: {key} is missing or not a number; the URDF implies "
                        f"{expected:.6g} m", where=self.where(node or params),
                        fix=f"{key}: {expected:.6g}")
            return
        effective = given
        for multiplier in multipliers:
            effective *= _number(get(params, multiplier)) or 1.0
        # A multiplier calibrates the geometric value to the floor (a skid-steer robot turns
        # as if its wheels were further apart): either may match the URDF's geometry.
        off = mismatch((given, effective), expected, skid)
        if off is None:
            return
        yield Issue(code, f"{section}: {key} {_stated(given, effective, expected)} "
                    f"disagrees with the URDF's {expected:.6g} m{off.purpose}",
                    where=self.where(node), fix=f"{key}: {expected:.6g}", severity=off.severity)


def _interface_fix(kind: str, interface: str) -> str:
    """Export the interface; or, for a name the hardware renames, claim what it exports."""
    plain = GAZEBO_PID.get(interface)
    if plain is not None:
        return (f"claim '{plain}': gazebo_ros2_control exports its {interface} loop under "
                "that name")
    return (f"add <{kind}_interface name=\"{interface}\"/> to the joint's <ros2_control> "
            "entry, or claim an interface it exports")


def _exports(exported: dict[str, dict[str, list[str]]], names: list[str], kind: str) -> str:
    """What the joints ``names`` export of ``kind``: once when they all export the same."""
    def listed(name: str) -> str:
        return ", ".join(exported[name][kind]) or "none"

    if len({listed(name) for name in names}) == 1:
        return f"{kind} interfaces: {listed(names[0])}"
    return "; ".join(f"'{name}' exports {listed(name)}" for name in names)


def _stated(given: float, effective: float, expected: float) -> str:
    """The controller's value closest to the URDF's first: the one that nearly matched.

    A skid-steer robot's multiplier (Husarion's 1.6 on a 0.45 m track) puts the effective
    value far from the geometry; the given one may be a few per cent off it, or the other way.
    """
    if effective == given:
        return f"{given:g} m"
    if abs(given - expected) <= abs(effective - expected):
        if not expected:
            return f"{given:g} m ({effective:g} m with the multipliers)"
        off = abs(given - expected) / abs(expected) * 100
        shown = f"{off:.0f}" if off >= 10 else f"{off:.2g}"
        return f"{given:g} m ({shown} % off; {effective:g} m with the multipliers)"
    return f"{effective:g} m ({given:g} m times the multipliers)"
