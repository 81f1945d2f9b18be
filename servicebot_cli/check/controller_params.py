"""SB608: controller parameters of a type rcl reads and the controller then refuses.

rcl_yaml_param_parser types each plain scalar by its text: a boolean word (``true``, ``on``,
``y``...), an integer, a floating-point number, else a string; a quoted scalar is a string
whatever it holds, and a list takes the one type of its items. A list whose items differ in
type (``[0.001, 0]``, or joints ``[x, y, z]`` where ``y`` is a boolean) makes rcl refuse the
whole file ("Sequence should be of same type"). A ros2_controllers controller declares each
of its parameters with one type (generate_parameter_library) and, at configure, refuses a
value of another ("Wrong parameter type ... setting it to {string} is not allowed"): a
wheel_separation of ``"0.10"`` or ``1``, a wheel list written as one name. Pure: YAML nodes
in, issues out.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Iterator

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.controller_interfaces import RCL_FALSE, RCL_TRUE
from servicebot_cli.check.controller_presence import presence_issues
from servicebot_cli.check.controller_sections import Sections, at, type_nodes
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.rcl_layout import no_value
from servicebot_cli.check.substitutions import substituted

_INTEGER = re.compile(r"[+-]?(?:0[xX][0-9a-fA-F]+|[0-9]+)")  # strtol, base 0
_DOUBLE = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*(?:[eE][+-]?[0-9]+)?|\.[0-9]+(?:[eE][+-]?[0-9]+)?"
                     r"|0[xX](?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?"
                     r"|(?i:inf|infinity|nan)"  # strtod
                     r"|\.(?:inf|Inf|INF))|\.(?:nan|NaN|NAN)")  # rcl's own spellings, these only
_LIMITS = tuple(f"{axis}.{limit}" for axis in ("linear.x", "angular.z") for limit in (
    "max_velocity", "min_velocity", "max_acceleration", "min_acceleration", "max_deceleration",
    "min_deceleration", "max_acceleration_reverse", "max_deceleration_reverse", "max_jerk",
    "min_jerk"))
_LIMIT_FLAGS = tuple(f"{axis}.has_{kind}_limits" for axis in ("linear.x", "angular.z")
                     for kind in ("velocity", "acceleration", "jerk"))
_DIFF_DRIVE = {
    "left_wheel_names": "string_array", "right_wheel_names": "string_array",
    "wheel_separation": "double", "wheel_radius": "double", "wheels_per_side": "integer",
    "wheel_separation_multiplier": "double", "left_wheel_radius_multiplier": "double",
    "right_wheel_radius_multiplier": "double", "odom_frame_id": "string",
    "base_frame_id": "string", "pose_covariance_diagonal": "double_array",
    "twist_covariance_diagonal": "double_array", "open_loop": "bool",
    "position_feedback": "bool", "enable_odom_tf": "bool", "cmd_vel_timeout": "double",
    "publish_limited_velocity": "bool", "velocity_rolling_window_size": "integer",
    "publish_rate": "double", "use_stamped_vel": "bool", "tf_frame_prefix_enable": "bool",
    "tf_frame_prefix": "string",
    **dict.fromkeys(_LIMITS, "double"), **dict.fromkeys(_LIMIT_FLAGS, "bool"),
}
_SOME_RELEASES = frozenset((
    "use_stamped_vel", "wheels_per_side", "publish_rate", *_LIMIT_FLAGS,
    *(f"{axis}.{limit}" for axis in ("linear.x", "angular.z") for limit in (
        "max_deceleration", "min_deceleration", "max_acceleration_reverse",
        "max_deceleration_reverse")),
    "state_publish_rate", "open_loop_control",
))
"""Parameters some releases declare and others do not read: Humble's diff drive flags and
stamped-velocity switch, JTC's state_publish_rate (gone from Jazzy), open_loop_control
(gone from Kilted), the newer deceleration limits. A controller node takes an undeclared
override as it is written and never reads it, so a wrong type there breaks only the
releases that declare it: a warning."""
_JOINT_GROUP = {"joints": "string_array"}
_GRIPPER = {"joint": "string", "goal_tolerance": "double", "max_effort": "double",
            "stall_timeout": "double", "action_monitor_rate": "double",
            "allow_stalling": "bool", "stall_velocity_threshold": "double"}
_SENSOR = {"sensor_name": "string", "frame_id": "string"}
DECLARED: dict[str, dict[str, str]] = {
    "diff_drive_controller/DiffDriveController": _DIFF_DRIVE,
    "joint_trajectory_controller/JointTrajectoryController": {
        "joints": "string_array", "command_joints": "string_array",
        "command_interfaces": "string_array", "state_interfaces": "string_array",
        "allow_partial_joints_goal": "bool", "open_loop_control": "bool",
        "allow_integration_in_goal_trajectories": "bool", "state_publish_rate": "double",
        "action_monitor_rate": "double", "interpolation_method": "string",
        "allow_nonzero_velocity_at_trajectory_end": "bool",
        "constraints.stopped_velocity_tolerance": "double", "constraints.goal_time": "double",
    },
    "forward_command_controller/ForwardCommandController": {
        "joints": "string_array", "interface_name": "string"},
    "position_controllers/JointGroupPositionController": _JOINT_GROUP,
    "velocity_controllers/JointGroupVelocityController": _JOINT_GROUP,
    "effort_controllers/JointGroupEffortController": _JOINT_GROUP,
    "position_controllers/GripperActionController": _GRIPPER,
    "effort_controllers/GripperActionController": _GRIPPER,
    "parallel_gripper_action_controller/GripperActionController": {
        **_GRIPPER, "state_interfaces": "string_array", "max_effort_interface": "string",
        "max_velocity": "double", "max_velocity_interface": "string"},
    "imu_sensor_broadcaster/IMUSensorBroadcaster": _SENSOR,
    "range_sensor_broadcaster/RangeSensorBroadcaster": _SENSOR,
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster": _SENSOR,
    "joint_state_broadcaster/JointStateBroadcaster": {
        "joints": "string_array", "interfaces": "string_array",
        "extra_joints": "string_array", "use_local_topics": "bool"},
}
"""The parameter types ros2_controllers declare (their ``*_parameters.yaml``), by type."""

TYPE_ARTICLE = {"integer": "an integer", "double": "a double", "bool": "a boolean",
            "string": "a string"}


def parameter_issues(found: Sections, display: str) -> Iterator[Issue]:
    """Every SB608 of the controller sections ``found``: the same against every robot."""
    nodes = type_nodes(found)
    types = {name: str(node.value) for name, node in nodes.items()}
    for name, node in nodes.items():
        typo = misspelled_type(node, name, display)
        if typo is not None:
            yield typo
    yield from presence_issues(found, display)
    for name, params in found.items():
        for section in params:
            yield from mixed_lists(section, name, display)
            yield from declared_types(types.get(name), section, name, display)
            yield from validated_values(types.get(name), section, name, display,
                                        tuple(other for other in params if other is not section))


def rcl_type(node: yaml.ScalarNode) -> str:
    """``bool``, ``integer``, ``double`` or ``string``: what rcl makes of a scalar."""
    if node.style in ("'", '"'):
        return "string"
    text = str(node.value)
    if text in RCL_TRUE or text in RCL_FALSE:
        return "bool"
    if c_integer(text) is not None:
        return "integer"  # beyond 64 bits, or '08', strtoll stops, and rcl reads a double
    return "double" if _c_double(text) is not None else "string"


def rcl_number(text: str) -> float | None:
    """The number rcl reads ``text`` as (an integer's value as a float); None: a string.

    As C reads it, not Python: ``010`` is 8 (octal), ``0x10`` 16, ``.inf`` infinite.
    """
    whole = c_integer(text)
    return float(whole) if whole is not None else _c_double(text)


def _c_double(text: str) -> float | None:
    """``text`` read whole by rcl as a double (its .inf and .nan, then strtod); None: not."""
    if not _DOUBLE.fullmatch(text):
        return None
    word = text.lstrip("+-").lower()
    if word in (".inf", "inf", "infinity"):
        return -math.inf if text.startswith("-") else math.inf
    if word in (".nan", "nan"):
        return math.nan
    try:
        value = float.fromhex(text) if "x" in word else float(text)
    except (ValueError, OverflowError):  # strtod would stop early: rcl keeps the text
        return None
    # strtod's ERANGE (1e400, 1e-400), after which rcl keeps the text, a string
    mantissa = word.partition("x")[2].partition("p")[0] if "x" in word else word.partition("e")[0]
    if math.isinf(value) or (value == 0 and mantissa.strip("0.")) \
            or (0 < abs(value) < sys.float_info.min and "x" not in word):  # inexact: ERANGE
        return None
    return value


_INT64_LOW, _INT64_HIGH = -(2 ** 63), 2 ** 63 - 1


def c_integer(text: str) -> int | None:
    """``text`` read whole by ``strtoll`` base 0 (``010`` octal, ``0x10`` hex), in 64 bits.

    None where strtoll stops before the end (``08``: 8 is no octal digit) or overflows: rcl
    then reads a double, or a string.
    """
    if not _INTEGER.fullmatch(text):
        return None
    digits = text.lstrip("+-")
    sign = -1 if text.startswith("-") else 1
    if digits[:2].lower() == "0x":
        value = int(digits, 16)
    elif len(digits) > 1 and digits.startswith("0"):
        if not set(digits) <= set("01234567"):
            return None
        value = int(digits, 8)
    else:
        value = int(digits)
    value *= sign
    return value if _INT64_LOW <= value <= _INT64_HIGH else None


def mixed_lists(params: yaml.MappingNode, section: str,
                display: str) -> Iterator[Issue]:
    """SB608 for each list under ``params`` whose items rcl reads as different types."""
    for key, node in _flat(params):
        if not isinstance(node, yaml.SequenceNode):
            continue
        scalars = [item for item in node.value if isinstance(item, yaml.ScalarNode)]
        if _filled_in(node):
            continue
        kinds = list(dict.fromkeys(rcl_type(item) for item in scalars))
        if len(kinds) > 1:
            odd = next(item for item in scalars if rcl_type(item) != kinds[0])
            yield Issue("SB608", f"{section}.{key}: rcl reads '{odd.value}' as "
                        f"{TYPE_ARTICLE[rcl_type(odd)]} among {kinds[0]}s, and refuses the whole "
                        "file ('Sequence should be of same type')",
                        where=at(display, odd.start_mark), fix=_fix(odd, kinds[0]))


def declared_types(controller_type: str | None, params: yaml.MappingNode, section: str,
                   display: str) -> Iterator[Issue]:
    """SB608 for each parameter of a known controller that rcl reads as another type."""
    declared = DECLARED.get(controller_type or "")
    if declared is None:
        return
    for key, node in _flat(params):
        wanted = declared.get(key)
        if wanted is None or no_value(node) or _filled_in(node):
            continue
        got = _type_of(node)
        if got is None or got == wanted or (got == "empty_array" and wanted.endswith("_array")):
            continue
        if got.endswith("_array") and wanted.endswith("_array"):
            shown = next(i for i in node.value if rcl_type(i) != wanted.removesuffix("_array"))
            what = f"its items as {got.removesuffix('_array')}s ('{shown.value}')"
            fix = _fix(shown, wanted.removesuffix("_array"))
        elif isinstance(node, yaml.ScalarNode):
            what = f"'{node.value}' as {TYPE_ARTICLE[got]}"
            listed = str(node.value).strip()
            fix = (f"{key}: {listed} (no quotes)" if listed.startswith("[") and
                   listed.endswith("]") else f"{key}: [{node.value}]") \
                if wanted.endswith("_array") else _fix(node, wanted)
        else:
            what = f"it as a {got.replace('_', ' ')}"
            fix = f"write {key} as a {wanted.replace('_', ' ')}"
        some = key in _SOME_RELEASES
        yield Issue("SB608", f"{section}.{key}: rcl reads {what}, and {controller_type} "
                    f"declares a {wanted.replace('_', ' ')}"
                    + (" in the releases that read it (not all do)" if some else "")
                    + ": it refuses the value at configure ('Wrong parameter type')",
                    where=at(display, node.start_mark), fix=fix,
                    severity=Severity.WARNING if some else None)


def _filled_in(node: yaml.Node) -> bool:
    """Whether a launch file fills the value in (``$(var wheel_separation)``) before rcl."""
    scalars = node.value if isinstance(node, yaml.SequenceNode) else [node]
    return any(isinstance(item, yaml.ScalarNode) and substituted(str(item.value))
               for item in scalars)


def _type_of(node: yaml.Node) -> str | None:
    """The type rcl gives a parameter's value; None for what it reads otherwise (a mapping)."""
    if isinstance(node, yaml.ScalarNode):
        return rcl_type(node)
    if isinstance(node, yaml.SequenceNode):
        kinds = {rcl_type(i) for i in node.value if isinstance(i, yaml.ScalarNode)}
        if not node.value:
            return "empty_array"
        return f"{kinds.pop()}_array" if len(kinds) == 1 else None  # mixed: mixed_lists says
    return None


def _fix(node: yaml.ScalarNode, wanted: str) -> str | None:
    """How to write ``node`` so that rcl reads it as ``wanted``."""
    text = str(node.value)
    if wanted == "double" and rcl_type(node) == "integer":
        return f"write {text}.0"
    if (wanted in ("double", "integer") and rcl_number(text) is not None) or (
            wanted == "bool" and (text in RCL_TRUE or text in RCL_FALSE)):
        return f"write {text} without quotes"
    if wanted == "string":
        return f"quote it: '{text}'"
    return None


def _flat(node: yaml.MappingNode, prefix: str = "") -> Iterator[tuple[str, yaml.Node]]:
    """Each parameter under ``node`` by its dotted name, as rcl flattens nested mappings."""
    for key, value in node.value:
        if not isinstance(key, yaml.ScalarNode):
            continue
        name = f"{prefix}{key.value}"
        if isinstance(value, yaml.MappingNode):
            yield from _flat(value, f"{name}.")
        else:
            yield name, value


KNOWN_TYPES = (
    "ackermann_steering_controller/AckermannSteeringController",
    "admittance_controller/AdmittanceController",
    "battery_state_broadcaster/BatteryStateBroadcaster",
    "bicycle_steering_controller/BicycleSteeringController",
    "chained_filter_controller/ChainedFilter",
    "diff_drive_controller/DiffDriveController",
    "effort_controllers/GripperActionController", "effort_controllers/JointGroupEffortController",
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster",
    "forward_command_controller/ForwardCommandController",
    "forward_command_controller/MultiInterfaceForwardCommandController",
    "gpio_controllers/GpioCommandController", "gps_sensor_broadcaster/GPSSensorBroadcaster",
    "imu_sensor_broadcaster/IMUSensorBroadcaster",
    "joint_state_broadcaster/JointStateBroadcaster",
    "joint_trajectory_controller/JointTrajectoryController",
    "magnetometer_broadcaster/MagnetometerBroadcaster",
    "mecanum_drive_controller/MecanumDriveController",
    "motion_primitives_controllers/MotionPrimitivesForwardController",
    "omni_wheel_drive_controller/OmniWheelDriveController",
    "parallel_gripper_action_controller/GripperActionController",
    "pid_controller/PidController", "pose_broadcaster/PoseBroadcaster",
    "position_controllers/GripperActionController",
    "position_controllers/JointGroupPositionController",
    "range_sensor_broadcaster/RangeSensorBroadcaster",
    "state_interfaces_broadcaster/StateInterfacesBroadcaster",
    "tricycle_controller/TricycleController",
    "tricycle_steering_controller/TricycleSteeringController",
    "velocity_controllers/JointGroupVelocityController",
)
"""ros2_controllers' plugin names (each package's plugin ``.xml``, on every branch)."""


def misspelled_type(node: yaml.ScalarNode, section: str, display: str) -> Issue | None:
    """SB608 for a ``type`` whose class is a letter or two off one of :data:`KNOWN_TYPES`.

    In a namespace of ros2_controllers' plugins (``diff_drive_controller/``), pluginlib finds
    no such class, and the controller manager cannot load the controller. Another namespace
    may be a third party's (or a newer release's) controller: not judged.
    """
    import difflib

    written = str(node.value).strip()
    namespace = written.partition("/")[0] + "/"
    siblings = [known for known in KNOWN_TYPES if known.startswith(namespace)]
    if written in KNOWN_TYPES or not siblings:
        return None
    close = difflib.get_close_matches(written, siblings, n=1, cutoff=0.9)
    if not close:
        return None
    return Issue("SB608", f"{section}.type '{written}' is no controller pluginlib can load; did "
                 f"you mean '{close[0]}'?", where=at(display, node.start_mark),
                 fix=f"type: {close[0]}")


_AT_LEAST_0 = {"parallel_gripper_action_controller/GripperActionController": (
    "max_effort", "max_velocity", "goal_tolerance", "stall_timeout")}
"""Parameters a controller validates as at least 0 (gt_eq), by its type."""
_JTC = "joint_trajectory_controller/JointTrajectoryController"
_JTC_LISTS = {  # each list: unique, not empty, and of these (its parameters' validation)
    "joints": None,
    "command_interfaces": ("position", "velocity", "acceleration", "effort"),
    "state_interfaces": ("position", "velocity", "acceleration"),
}


def validated_values(controller_type: str | None, params: yaml.MappingNode, section: str,
                     display: str, siblings: tuple[yaml.MappingNode, ...] = ()
                     ) -> Iterator[Issue]:
    """SB608 for values a controller's parameter validation refuses at configure.

    JointTrajectoryController: its joints and interfaces unique and not empty, command
    interfaces of position, velocity, acceleration and effort, state interfaces of position,
    velocity and acceleration, and no velocity state without position nor acceleration
    without both (state_interface_type_combinations). ForwardCommandController: an
    interface_name (in this section or another that configures the same node, ``/fwd``
    beside ``fwd``: ``siblings``).
    """
    if controller_type == "forward_command_controller/ForwardCommandController" and not any(
            _last(other, "interface_name") is not None for other in siblings):
        node = _last(params, "interface_name")
        if node is None or (isinstance(node, yaml.ScalarNode) and not str(node.value).strip()):
            yield Issue("SB608", f"{section}: no interface_name; ForwardCommandController "
                        "refuses to configure without one",
                        where=at(display, (node or params).start_mark),
                        fix="interface_name: position")
    for key in _AT_LEAST_0.get(controller_type or "", ()):
        node = _last(params, key)
        if not isinstance(node, yaml.ScalarNode) or _filled_in(node) \
                or rcl_type(node) not in ("double", "integer"):
            continue
        value = rcl_number(str(node.value))
        if value is not None and value < 0:
            yield Issue("SB608", f"{section}.{key} is {node.value}: {controller_type} refuses a "
                        "negative value at configure (gt_eq 0)", where=at(display, node.start_mark),
                        fix=f"{key}: {str(node.value).lstrip('-')}")
    if controller_type != _JTC:
        return
    for key, allowed in _JTC_LISTS.items():
        node = _last(params, key)
        if node is None or _filled_in(node) or not isinstance(node, yaml.SequenceNode):
            continue  # absent: the empty default, which SB601-SB607 and rcl see otherwise
        names = [str(i.value) for i in node.value if isinstance(i, yaml.ScalarNode)]
        twice = next((n for k, n in enumerate(names) if n in names[:k]), None)
        if not names:
            problem = "is empty"
            fix = f"name at least one {'joint' if key == 'joints' else 'interface'}"
        elif twice is not None:
            problem, fix = f"names '{twice}' twice", f"name '{twice}' once"
        elif allowed and (odd := [n for n in names if n not in allowed]):
            problem = f"holds '{odd[0]}', which is none of {', '.join(allowed)}"
            fix = f"replace '{odd[0]}' with one of {', '.join(allowed)}"
        elif key == "state_interfaces" and "velocity" in names and "position" not in names:
            problem = "holds velocity without position"
            fix = f"{key}: [{', '.join(['position', *names])}]"
        elif key == "state_interfaces" and "acceleration" in names \
                and not {"position", "velocity"} <= set(names):
            problem = "holds acceleration without both position and velocity"
            fix = f"{key}: [position, velocity, acceleration]"
        else:
            continue
        yield Issue("SB608", f"{section}.{key} {problem}: JointTrajectoryController refuses "
                    "it at configure", where=at(display, node.start_mark), fix=fix)


def _last(params: yaml.MappingNode, dotted: str) -> yaml.Node | None:
    """The value of the parameter ``dotted`` (the last one written), or None."""
    found = None
    for key, node in _flat(params):
        if key == dotted:
            found = node
    return found
