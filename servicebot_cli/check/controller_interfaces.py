"""What a controller claims of the hardware: each joint's command and state interfaces.

The controller manager activates a controller only once the hardware exports every interface
the controller claims; the URDF's ``<ros2_control>`` blocks say what it exports. What each
ros2_controllers type claims follows from its parameters (Humble to Jazzy). Pure: YAML nodes
in, claims out.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.controller_sections import get

_GROUPS = {
    "position_controllers/JointGroupPositionController": "position",
    "velocity_controllers/JointGroupVelocityController": "velocity",
    "effort_controllers/JointGroupEffortController": "effort",
}
"""Controllers that command one interface, named by their type, of each of their ``joints``."""
# rcl_yaml_param_parser's booleans (parse.c): y and n are booleans there, as in YAML 1.1
RCL_TRUE = ("true", "True", "TRUE", "yes", "Yes", "YES", "on", "On", "ON", "y", "Y")
RCL_FALSE = ("false", "False", "FALSE", "no", "No", "NO", "off", "Off", "OFF", "n", "N")


@dataclass(frozen=True)
class Claim:
    """One interface of one joint that a controller claims.

    Attributes:
        kind: ``command`` or ``state``.
        interface: Its name (``position``, ``velocity``...).
        key: The parameter naming the joint (``joints``, ``left_wheel_names``...).
        joint: Where the joint is named.
        named_at: Where the interface is named; the joint's node when the type implies it.
        humble_only: Only Humble's controller claims it (later ones do not, as configured).
        sensor: ``joint`` names a ``<ros2_control>`` sensor (a broadcaster's sensor_name).
    """

    kind: str
    interface: str
    key: str
    joint: yaml.ScalarNode
    named_at: yaml.Node
    humble_only: bool = False
    sensor: bool = False


def claims(controller_type: str, params: yaml.MappingNode) -> Iterator[Claim]:
    """The interfaces a controller of ``controller_type`` claims, by its ``params``.

    Nothing for a type whose claims this does not know (joint_state_broadcaster reads
    whatever is exported; a third party's controller).
    """
    if controller_type == "diff_drive_controller/DiffDriveController":
        yield from _diff_drive(params)
    elif controller_type == "joint_trajectory_controller/JointTrajectoryController":
        yield from _trajectory(params)
    elif controller_type == "forward_command_controller/ForwardCommandController":
        for name in _scalars(get(params, "interface_name")):
            yield from _each(params, "joints", "command", name)
    elif controller_type == "forward_command_controller/MultiInterfaceForwardCommandController":
        for name in _scalars(get(params, "interface_names")):
            yield from _each(params, "joint", "command", name)
    elif controller_type in _GROUPS:
        for joint in _scalars(get(params, "joints")):
            yield Claim("command", _GROUPS[controller_type], "joints", joint, joint)
    elif controller_type == "pid_controller/PidController":
        yield from _pid(params)
    elif controller_type in _GRIPPERS:
        yield from _gripper(params, _GRIPPERS[controller_type])
    elif controller_type in _SENSOR_STATES:
        for sensor in _scalars(get(params, "sensor_name")):
            for state in _SENSOR_STATES[controller_type]:
                yield Claim("state", state, "sensor_name", sensor, sensor, sensor=True)


_GRIPPERS = {
    "position_controllers/GripperActionController": "position",
    "effort_controllers/GripperActionController": "effort",
    "parallel_gripper_action_controller/GripperActionController": "position",
}
"""Gripper action controllers, and the interface each commands of its ``joint``."""
_SENSOR_STATES = {
    "imu_sensor_broadcaster/IMUSensorBroadcaster": tuple(
        f"{part}.{axis}" for part, axes in (("orientation", "xyzw"), ("angular_velocity", "xyz"),
                                            ("linear_acceleration", "xyz")) for axis in axes),
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster": tuple(
        f"{part}.{axis}" for part in ("force", "torque") for axis in "xyz"),
    "range_sensor_broadcaster/RangeSensorBroadcaster": ("range",),
}
"""Broadcasters of one ``<ros2_control>`` sensor (``sensor_name``), and the states they read of
it (ros2_control's semantic components: IMUSensor, ForceTorqueSensor, RangeSensor)."""


def _gripper(params: yaml.MappingNode, command: str) -> Iterator[Claim]:
    """A gripper action controller's claims: its joint's command, and position and velocity.

    parallel_gripper_action_controller reads the ``state_interfaces`` it is given (position
    and velocity by default), and commands also the full interface names its
    ``max_effort_interface`` and ``max_velocity_interface`` give (``joint/effort``).
    """
    states = _scalars(get(params, "state_interfaces")) if get(
        params, "state_interfaces") is not None else None
    for joint in _scalars(get(params, "joint")):
        yield Claim("command", command, "joint", joint, joint)
        if states is None:
            for state in ("position", "velocity"):
                yield Claim("state", state, "joint", joint, joint)
        for state in states or ():
            yield Claim("state", str(state.value), "joint", joint, state)
    for key in ("max_effort_interface", "max_velocity_interface"):
        for full in _scalars(get(params, key)):
            joint_name, slash, interface = str(full.value).rpartition("/")
            if slash and joint_name and interface:
                named = yaml.ScalarNode(full.tag, joint_name, full.start_mark, full.end_mark)
                yield Claim("command", interface, key, named, full)


def _diff_drive(params: yaml.MappingNode) -> Iterator[Claim]:
    """Each wheel's velocity command, and its position (or velocity) state.

    ``position_feedback`` (true by default) reads the wheels' positions for odometry; false,
    their velocities. With ``open_loop: true`` the odometry integrates the commands, and
    since ros2_controllers' Jazzy releases the controller claims no state interface then;
    Humble's still claims it.
    """
    feedback = get(params, "position_feedback")
    state = "velocity" if isinstance(feedback, yaml.ScalarNode) and \
        feedback.value in RCL_FALSE else "position"
    open_loop = get(params, "open_loop")
    humble_only = isinstance(open_loop, yaml.ScalarNode) and open_loop.value in RCL_TRUE
    for key in ("left_wheel_names", "right_wheel_names"):
        for wheel in _scalars(get(params, key)):
            yield Claim("command", "velocity", key, wheel, wheel)
            yield Claim("state", state, key, wheel, wheel, humble_only)


def _pid(params: yaml.MappingNode) -> Iterator[Claim]:
    """pid_controller's claims: its ``command_interface`` of each of its ``dof_names``.

    And its ``reference_and_state_interfaces`` as states, unless it takes the measured states
    from a topic (``use_external_measured_states``).
    """
    external = get(params, "use_external_measured_states")
    states = [] if isinstance(external, yaml.ScalarNode) and external.value in RCL_TRUE \
        else _scalars(get(params, "reference_and_state_interfaces"))
    for command in _scalars(get(params, "command_interface")):
        yield from _each(params, "dof_names", "command", command)
    for state in states:
        yield from _each(params, _state_dofs_key(params), "state", state)


def state_dofs(params: yaml.MappingNode) -> list[yaml.ScalarNode]:
    """A pid_controller's dofs whose states it reads and whose references it exports."""
    return _scalars(get(params, _state_dofs_key(params)))


def _state_dofs_key(params: yaml.MappingNode) -> str:
    """``reference_and_state_dof_names`` where the controller names them, else ``dof_names``."""
    return "reference_and_state_dof_names" if _scalars(
        get(params, "reference_and_state_dof_names")) else "dof_names"


def _trajectory(params: yaml.MappingNode) -> Iterator[Claim]:
    """JointTrajectoryController's claims.

    Its ``command_interfaces`` of its ``command_joints`` (else of its ``joints``), and its
    ``state_interfaces`` of its ``joints``.
    """
    commanded = "command_joints" if _scalars(get(params, "command_joints")) else "joints"
    for interface in _scalars(get(params, "command_interfaces")):
        yield from _each(params, commanded, "command", interface)
    for interface in _scalars(get(params, "state_interfaces")):
        if interface.value in ("position", "velocity", "acceleration"):  # it reads no other
            yield from _each(params, "joints", "state", interface)


def _each(params: yaml.MappingNode, key: str, kind: str,
          interface: yaml.ScalarNode) -> Iterator[Claim]:
    for joint in _scalars(get(params, key)):
        yield Claim(kind, str(interface.value), key, joint, interface)


def _scalars(node: yaml.Node | None) -> list[yaml.ScalarNode]:
    """The names a list (or a single name) holds; anything else (``~``, a list) holds none."""
    items = node.value if isinstance(node, yaml.SequenceNode) else [node]
    return [item for item in items if isinstance(item, yaml.ScalarNode) and item.value
            and item.tag != _NULL]


_NULL = "tag:yaml.org,2002:null"
