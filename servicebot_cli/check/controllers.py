"""Controller configuration rules: a ros2_control controllers YAML against a URDF (SB601-SB606).

Pure: YAML text and a RobotDescription in, issues out, each placed at its YAML line.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import DescriptionError, NameNotFound
from servicebot_cli.description.yaml_size import MOST_NODES, unfolded_nodes

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.drive_geometry import DriveGeometry

TOLERANCE = 0.01
"""Relative difference allowed between the YAML and the URDF's wheel numbers."""

ROS2_CONTROLLERS = frozenset((
    "ackermann_steering_controller", "admittance_controller", "bicycle_steering_controller",
    "diff_drive_controller", "effort_controllers", "force_torque_sensor_broadcaster",
    "forward_command_controller", "gpio_controllers", "gripper_controllers",
    "imu_sensor_broadcaster", "joint_state_broadcaster", "joint_trajectory_controller",
    "mecanum_drive_controller", "omni_wheel_drive_controller", "parallel_gripper_controller",
    "pid_controller", "pose_broadcaster", "position_controllers", "range_sensor_broadcaster",
    "steering_controllers_library", "tricycle_controller", "tricycle_steering_controller",
    "velocity_controllers",
))
"""The packages of ros-controls/ros2_controllers: their ``joint``/``joints`` name URDF joints."""
_NAMESPACE_DEPTH = 3


def check(found: dict[str, yaml.MappingNode], display: str,
          robot: RobotDescription) -> Iterator[Issue]:
    """Every issue of the controller sections ``found`` (of file ``display``) against ``robot``."""
    checker = _Checker(display, robot, frozenset(found))
    types = _types(found)
    for name, params in found.items():
        if name != "controller_manager" and _names_joints(types.get(name)):
            yield from checker.section(name, params)


def sections(text: str, display: str) -> dict[str, yaml.MappingNode] | Issue:
    """The controller sections of ``text``, read once for every robot it is checked against.

    Or the SB601 issue that makes ``text`` no controllers file at all, whatever the robot:
    not YAML, empty, or without a ``NAME: ros__parameters:`` section.
    """
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = (display, mark.line + 1, mark.column + 1) if mark else (display, 0, 0)
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        return Issue("SB601", f"not valid YAML: {problem}", where=where)
    except RecursionError:  # PyYAML's composer recurses once per level of nesting
        return Issue("SB601", "not valid YAML: lists and mappings nested too deep to read",
                     where=(display, 0, 0))
    if root is not None and unfolded_nodes(root) is None:
        return Issue("SB601", f"its aliases (*name) unfold to over {MOST_NODES:,} items (an "
                     "alias bomb?); no controllers file is that large", where=(display, 0, 0))
    if root is None:
        return Issue("SB601", "the file holds no YAML (it is empty, or only comments)",
                     where=(display, 0, 0),
                     fix="write each controller's parameters under NAME: ros__parameters:")
    sections = _sections(root)
    if not sections:
        ros1 = _ros1_controllers(root)
        found = (f"a ROS 1 ros_control file ('{ros1}: type: ...' with no ros__parameters), "
                 "which ros2_control does not read; ") if ros1 else ""
        return Issue("SB601", f"{found}no controller sections (NAME: ros__parameters: ...) "
                     "found", where=(display, 1, 1),
                     fix="check ROS 2 controllers files only, or port this one: each "
                         "controller's parameters under NAME: ros__parameters:" if ros1 else None)
    return sections


def _ros1_controllers(root: yaml.Node | None) -> str | None:
    """The first controller a ROS 1 file declares (``NAME: {type: pkg/Class}``), or None."""
    if not isinstance(root, yaml.MappingNode):
        return None
    for key, value in root.value:
        kind = _get(value, "type")
        if isinstance(kind, yaml.ScalarNode) and "/" in str(kind.value):
            return str(key.value)
    return None


def _sections(root: yaml.Node | None, depth: int = 0) -> dict[str, yaml.MappingNode]:
    """Each node's ``ros__parameters`` by node name.

    A node may sit under namespaces, as ROS 2 parameter files allow: ``/**:`` (any
    namespace, as irobot_create_control's ``control.yaml``) or ``robot1:`` above the node's
    own key. A node keyed by a path (``/robot1/controller_manager``) is named by its last part.
    """
    found: dict[str, yaml.MappingNode] = {}
    if not isinstance(root, yaml.MappingNode) or depth > _NAMESPACE_DEPTH:
        return found
    for key, value in root.value:
        params = _get(value, "ros__parameters")
        if isinstance(params, yaml.MappingNode):
            found[str(key.value).rstrip("/").rpartition("/")[2]] = params
        elif isinstance(value, yaml.MappingNode):
            for name, inner in _sections(value, depth + 1).items():
                found.setdefault(name, inner)
    return found


def _types(sections: dict[str, yaml.MappingNode]) -> dict[str, str]:
    """Each controller's ``type`` (``package/Class``), by controller name.

    Declared in ``controller_manager``'s parameters, or in the controller's own (ros2_control
    since Jazzy).
    """
    types: dict[str, str] = {}
    manager = sections.get("controller_manager")
    for name, params in sections.items():
        for node in (_get(_get(manager, name), "type"), _get(params, "type")):
            if isinstance(node, yaml.ScalarNode) and node.value:
                types[name] = str(node.value)
    return types


def _names_joints(controller_type: str | None) -> bool:
    """Whether a controller's ``joint``/``joints`` are URDF joint names, as far as known.

    True for a ros2_controllers type and for a controller whose type the file does not say.
    A third party's controller is not checked: Kortex's twist controller takes
    ``joint: tcp``, the prefix of interfaces its hardware exports, not a URDF joint.
    """
    return controller_type is None or controller_type.partition("/")[0] in ROS2_CONTROLLERS


def _get(node: yaml.Node | None, key: str) -> yaml.Node | None:
    if isinstance(node, yaml.MappingNode):
        for k, v in node.value:
            if isinstance(k, yaml.ScalarNode) and k.value == key:
                return v
    return None


def _number(node: yaml.Node | None) -> float | None:
    if not isinstance(node, yaml.ScalarNode):
        return None
    try:
        return float(node.value)
    except ValueError:
        return None


class _Checker:
    def __init__(self, display: str, robot: RobotDescription,
                 controllers: frozenset[str] = frozenset()) -> None:
        self.display = display
        self.robot = robot
        self.controllers = controllers
        self.joints = {j.name: j for j in robot.joints}
        self._geometry: DriveGeometry | None | str = None

    def where(self, node: yaml.Node) -> tuple[str, int, int]:
        return (self.display, node.start_mark.line + 1, node.start_mark.column + 1)

    def geometry(self) -> DriveGeometry | str:
        if self._geometry is None:
            from servicebot_cli.kinematics.drive_geometry import drive_geometry

            try:
                self._geometry = drive_geometry(self.robot)
            except DescriptionError as exc:
                self._geometry = str(exc).split(": ", 1)[-1]
        return self._geometry

    def section(self, name: str, params: yaml.MappingNode) -> Iterator[Issue]:
        for key in ("left_wheel_names", "right_wheel_names", "joints", "joint"):
            node = _get(params, key)
            if node is not None:
                yield from self.names(name, key, node)
        if _get(params, "left_wheel_names") is not None:
            yield from self.wheels(name, params)

    def names(self, section: str, key: str, node: yaml.Node) -> Iterator[Issue]:
        items = node.value if isinstance(node, yaml.SequenceNode) else [node]
        for item in items:
            if not isinstance(item, yaml.ScalarNode):
                yield Issue("SB601", f"{section}.{key} must be a list of joint names",
                            where=self.where(item))
                continue
            if self.not_a_joint(item.value):
                continue
            joint = self.joints.get(item.value)
            if joint is None:
                hint = str(NameNotFound.for_name(item.value, list(self.joints))).split("; ", 1)
                yield Issue("SB602", f"{section}.{key}: joint '{item.value}' is not in "
                            f"{self.robot.display}; {hint[-1]}", where=self.where(item))
            elif not joint.movable:
                yield Issue("SB606", f"{section}.{key}: joint '{item.value}' is {joint.type} "
                            "in the URDF", where=self.where(item))

    def not_a_joint(self, name: str) -> bool:
        """A name that is not a URDF joint's and is right as written.

        A chained controller's reference interface (``pid_controller_left_wheel_joint/
        left_wheel_joint``: a controller of this file, a slash, its reference) and a name a
        launch file fills in (``$(var joint_prefix)1``).
        """
        return "$(" in name or name.partition("/")[0] in self.controllers

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
        geometry = self.geometry()
        if isinstance(geometry, str):
            # The URDF's wheels are not cylinders on continuous joints (gz_ros2_control_demos'
            # diff drive rolls on spheres): nothing to compare the YAML with, and no defect.
            return
        for key, side in (("left_wheel_names", "left"), ("right_wheel_names", "right")):
            node = _get(params, key)
            items = node.value if isinstance(node, yaml.SequenceNode) else []
            for item in items:
                joint = self.joint_of(str(item.value))
                wheel = next((w for w in geometry.wheels if w.joint == joint), None)
                if wheel is not None and wheel.side != side:
                    via = f" (joint '{joint}')" if joint != item.value else ""
                    yield Issue("SB605", f"{section}.{key}: '{item.value}'{via} is on the "
                                f"{wheel.side} (y = {wheel.position_m[1]:g} m in the URDF)",
                                where=self.where(item))
        yield from self.value(section, params, "wheel_radius", geometry.wheel_radius_m, "SB603",
                              ("left_wheel_radius_multiplier",))
        yield from self.value(section, params, "wheel_separation", geometry.track_m, "SB604",
                              ("wheel_separation_multiplier",))

    def value(self, section: str, params: yaml.MappingNode, key: str, expected: float,
              code: str, multipliers: tuple[str, ...]) -> Iterator[Issue]:
        node = _get(params, key)
        given = _number(node)
        if node is None or given is None:
            yield Issue(code, f"{section}: {key} is missing or not a number; the URDF implies "
                        f"{expected:.6g} m", where=self.where(node or params),
                        fix=f"{key}: {expected:.6g}")
            return
        effective = given
        for multiplier in multipliers:
            effective *= _number(_get(params, multiplier)) or 1.0
        # A multiplier calibrates the geometric value to the floor (a skid-steer robot turns
        # as if its wheels were further apart): either may match the URDF's geometry.
        if all(abs(value - expected) > TOLERANCE * abs(expected) for value in (given, effective)):
            times = f" ({given:g} m times the multipliers)" if effective != given else ""
            yield Issue(code, f"{section}: {key} {effective:g} m{times} disagrees with the "
                        f"URDF's {expected:.6g} m", where=self.where(node),
                        fix=f"{key}: {expected:.6g}")
