"""The topics a robot consumes and publishes, and where each one comes from.

Sensors publish what their Gazebo ROS plugins (or gz-sim ``<topic>``) say. Controllers consume
and publish what their type does in ROS 2 Humble (``~/`` is the controller's own namespace).
Model-level Gazebo plugins that drive the base or publish joint states give theirs
(:mod:`servicebot_cli.description.model_plugins`). Hardware parameters that name a serial port are
listed as a device, since the motors are reached through it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from typing import Any

from servicebot_cli.description.extensions import Plugin
from servicebot_cli.description.model_plugins import model_plugin_rows
from servicebot_cli.description.ros_names import PluginNode, controller_topic, manager_node
from servicebot_cli.inspect.controllers import Controller, Controllers
from servicebot_cli.inspect.plugins import HardwareInfo, PluginInfo
from servicebot_cli.inspect.sensors import SensorInfo

_PORT_KEYS = ("port", "serial_port", "device", "serial_device", "device_name")
_BAUD_KEYS = ("baud_rate", "baudrate", "baud")


@dataclass(frozen=True)
class TopicInfo:
    """One way in or out of the robot.

    Attributes:
        direction: ``in`` (the robot consumes it) or ``out`` (it publishes it).
        kind: ``topic``, ``action`` or ``device``.
        name: Topic, action or device name (relative names resolve in the node's namespace).
        message: Message or action type, ROS 2 spelling; for a device, its settings.
        provider: The controller, sensor or ros2_control system that provides it.
        source: The provider's type and the file it is declared in.
        note: Anything a user must know to see it under this name.
    """

    direction: str
    kind: str
    name: str
    message: str | None
    provider: str
    source: str
    note: str | None = None


_UNSTAMPED = "~/cmd_vel_unstamped"
_UNSTAMPED_NOTE = (f"Humble subscribes {_UNSTAMPED} when use_stamped_vel is false; remap it to "
                   "~/cmd_vel")


def _unstamped_note(manager: PluginNode | None, controller: str) -> str:
    """:data:`_UNSTAMPED_NOTE`, or where the plugin's own remap rule already sends that topic."""
    remapped = controller_topic(manager, controller, _UNSTAMPED)
    if manager is None or remapped == controller_topic(replace(manager, rules=()), controller,
                                                       _UNSTAMPED):
        return _UNSTAMPED_NOTE
    return (f"Humble subscribes {_UNSTAMPED} when use_stamped_vel is false, which the "
            f"ros2_control plugin remaps to {remapped}")


Row = tuple[str, str, str, str, str | None]
"""direction, kind, name (before the manager's namespace and remap rules), message, note."""


def _diff_drive(c: Controller, manager: PluginNode | None) -> list[Row]:
    stamped = c.params.get("use_stamped_vel", True) is not False
    note = None if stamped else _unstamped_note(manager, c.name)
    rows = [("in", "topic", "~/cmd_vel",
             "geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist", note),
            ("out", "topic", "~/odom", "nav_msgs/msg/Odometry", None)]
    if c.params.get("enable_odom_tf", True) is not False:
        rows.append(("out", "topic", "/tf", "tf2_msgs/msg/TFMessage", None))
    return rows


def _trajectory(c: Controller, manager: PluginNode | None) -> list[Row]:
    return [("in", "topic", "~/joint_trajectory", "trajectory_msgs/msg/JointTrajectory", None),
            ("in", "action", "~/follow_joint_trajectory",
             "control_msgs/action/FollowJointTrajectory", None)]


def _joint_states(c: Controller, manager: PluginNode | None) -> list[Row]:
    local = c.params.get("use_local_topics", False) is True
    prefix = "~/" if local else ""  # relative: in the controller manager's namespace
    return [("out", "topic", f"{prefix}joint_states", "sensor_msgs/msg/JointState", None)]


def _commands(c: Controller, manager: PluginNode | None) -> list[Row]:
    return [("in", "topic", "~/commands", "std_msgs/msg/Float64MultiArray", None)]


def _published(name: str, message: str) -> Callable[[Controller, PluginNode | None], list[Row]]:
    """A sensor broadcaster's one topic (force/torque, IMU, range)."""
    return lambda c, manager: [("out", "topic", name, message, None)]


def _gripper(c: Controller, manager: PluginNode | None) -> list[Row]:
    return [("in", "action", "~/gripper_cmd", "control_msgs/action/GripperCommand", None)]


_KNOWN = {
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster":
        _published("~/wrench", "geometry_msgs/msg/WrenchStamped"),
    "imu_sensor_broadcaster/IMUSensorBroadcaster": _published("~/imu", "sensor_msgs/msg/Imu"),
    "range_sensor_broadcaster/RangeSensorBroadcaster":
        _published("~/range", "sensor_msgs/msg/Range"),
    "position_controllers/GripperActionController": _gripper,
    "effort_controllers/GripperActionController": _gripper,
    "parallel_gripper_action_controller/GripperActionController": _gripper,
    "diff_drive_controller/DiffDriveController": _diff_drive,
    "joint_trajectory_controller/JointTrajectoryController": _trajectory,
    "joint_state_broadcaster/JointStateBroadcaster": _joint_states,
    "forward_command_controller/ForwardCommandController": _commands,
    "position_controllers/JointGroupPositionController": _commands,
    "velocity_controllers/JointGroupVelocityController": _commands,
    "effort_controllers/JointGroupEffortController": _commands,
}


def controller_topics(controllers: Controllers,
                      manager: PluginNode | None = None) -> list[TopicInfo]:
    """What each controller of a known type consumes and publishes.

    Named as ROS names them in ``manager``'s namespace, under its remap rules
    (:func:`~servicebot_cli.description.ros_names.manager_node`); at the root without one.
    """
    rows = []
    file_name = controllers.file.rsplit("/", 1)[-1]
    for c in controllers.controllers:
        derive = _KNOWN.get(c.type)
        if derive is None:
            continue
        source = f"{file_name}: {c.name} ({c.type})"
        for direction, kind, name, message, note in derive(c, manager):
            resolved = controller_topic(manager, c.name, name)
            rows.append(TopicInfo(direction, kind, resolved, message, c.name, source, note))
    return rows


def sensor_topics(sensors: tuple[SensorInfo, ...]) -> list[TopicInfo]:
    """What each sensor publishes."""
    return [TopicInfo("out", "topic", t.name, t.message, s.name,
                      f"{s.type} sensor on {s.link} ({s.plugin or 'no ROS plugin'})")
            for s in sensors for t in s.topics]


def device_topics(hardware: tuple[HardwareInfo, ...]) -> list[TopicInfo]:
    """Serial ports named by ros2_control hardware parameters."""
    rows = []
    for system in hardware:
        params: dict[str, Any] = {p.name: p.value for p in system.params}
        port = next((params[k] for k in _PORT_KEYS if params.get(k)), None)
        if port is None:
            continue
        baud = next((params[k] for k in _BAUD_KEYS if params.get(k)), None)
        settings = f"serial, {baud} baud" if baud else "serial"
        rows.append(TopicInfo("in", "device", port, settings, "ros2_control",
                              f"ros2_control hardware {system.plugin} (system {system.name})"))
    return rows


def plugin_topics(plugins: tuple[PluginInfo, ...]) -> list[TopicInfo]:
    """What the model-level Gazebo plugins of a known kind consume and publish."""
    rows = []
    for info, plugin in _model_plugins(plugins):
        source = f"Gazebo plugin {info.filename or info.name} (model)"
        rows += [TopicInfo(direction, "topic", name, message, info.name or info.filename,
                           source, note)
                 for direction, name, message, note in model_plugin_rows(plugin)]
    return rows


def _model_plugins(plugins: tuple[PluginInfo, ...]) -> Iterator[tuple[PluginInfo, Plugin]]:
    """Each model-level plugin of ``plugins``, as listed and as the description reads it."""
    for info in plugins:
        if info.attached_to == "model":
            yield info, Plugin(info.name, info.filename,
                               tuple((p.name, p.value) for p in info.params),
                               ros2_file=info.ros2_file)


def topics_info(sensors: tuple[SensorInfo, ...], hardware: tuple[HardwareInfo, ...],
                controllers: Controllers | None,
                gazebo: tuple[PluginInfo, ...] = ()) -> tuple[TopicInfo, ...]:
    """Inputs first, then outputs; within each, controllers, plugins, devices, then sensors.

    ``gazebo``: the description's Gazebo plugins (``PluginsInfo.gazebo``); the model-level
    ones that drive the base or publish joint states add their topics.
    """
    manager = manager_node(plugin for _, plugin in _model_plugins(gazebo))
    rows = (controller_topics(controllers, manager) if controllers else []) \
        + plugin_topics(gazebo) + device_topics(hardware) + sensor_topics(sensors)
    return tuple(sorted(rows, key=lambda r: r.direction != "in"))
