"""SB519: a ROS 1 parameter in a Gazebo plugin of a file whose plugins are ROS 2's.

One Gazebo runs every plugin of a file. A ``<ros>`` block in one of them, or a plugin only
ROS 2 has (``libgazebo_ros2_control.so``), makes the file ROS 2's (gazebo_ros), whose
gazebo_plugins read none of gazebo_ros_pkgs' ROS 1 names:
tortoisebot's ROS 2 camera writes ``<frameName>camera</frameName>``, and Gazebo stamps its
images with the link it carries the camera on. Other packages' plugins may read them
(velodyne_simulator's ROS 2 plugin reads ``<frameName>``). Pure.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.description.extensions import ROS2_ONLY_PLUGINS

if TYPE_CHECKING:
    from servicebot_cli.description.extensions import Plugin
    from servicebot_cli.description.robot import RobotDescription

_REMAP = "a <ros><remapping>DEFAULT:=NAME</remapping>"
ROS2_NAMES = {
    "frameName": "<frame_name>", "cameraName": "<camera_name>", "topicName": _REMAP,
    "imageTopicName": _REMAP, "cameraInfoTopicName": _REMAP, "commandTopic": _REMAP,
    "odometryTopic": _REMAP, "robotNamespace": "<ros><namespace>",
    "updateRate": "the sensor's <update_rate> (a drive plugin's <update_rate>)",
    "updateRateHZ": "<update_rate>", "gaussianNoise": "the sensor's SDF <noise>",
    "bodyName": "<body_name>", "hackBaseline": "<hack_baseline>",
    "leftJoint": "<left_joint>", "rightJoint": "<right_joint>",
    "wheelSeparation": "<wheel_separation>", "wheelDiameter": "<wheel_diameter>",
    "wheelAcceleration": "<max_wheel_acceleration>", "wheelTorque": "<max_wheel_torque>",
    "publishOdomTF": "<publish_odom_tf>", "publishWheelTF": "<publish_wheel_tf>",
    "publishTf": "<publish_odom>", "odometryFrame": "<odometry_frame>",
    "robotBaseFrame": "<robot_base_frame>", "odometrySource": "<odometry_source>",
    "publishWheelJointState": "a gazebo_ros_joint_state_publisher plugin",
    "legacyMode": "nothing (ROS 2's diff drive has no legacy mode)",
}
"""gazebo_ros_pkgs' ROS 1 plugin parameters, with what ROS 2's gazebo_plugins read instead."""


def check(robot: RobotDescription) -> Iterator[Issue]:
    """SB519 for each ROS 1 parameter of a plugin in a file whose plugins are ROS 2's."""
    for plugin in robot.plugins:
        if plugin.ros2_file:
            yield from _ros1_names(plugin, _evidence(robot.plugins))


def _evidence(plugins: Sequence[Plugin]) -> str:
    """What makes the file's plugins ROS 2's: a ``<ros>`` block, or a plugin only ROS 2 has."""
    if any(p.has_ros_block for p in plugins):
        return "a <ros> block"
    only = next(p.filename for p in plugins if p.filename in ROS2_ONLY_PLUGINS)
    return f"'{only}' exists for ROS 2 only"


def _ros1_names(plugin: Plugin, evidence: str) -> Iterator[Issue]:
    """One SB519 for the plugin, at its first ROS 1 parameter, naming them all."""
    if plugin.element is None:
        return
    found = {child.tag: child for child in reversed(plugin.element)
             if isinstance(child.tag, str) and child.tag in ROS2_NAMES}
    if not found:
        return
    tags = list(reversed(found))
    one = len(tags) == 1
    shown = ", ".join(f"<{tag}>" for tag in tags)
    yield Issue("SB519", f"plugin '{plugin.filename}': {shown} {'is a' if one else 'are'} ROS 1 "
                f"parameter{'' if one else 's'}, and the file's plugins are ROS 2's ({evidence}): "
                "gazebo_plugins' ROS 2 versions read no ROS 1 name, so "
                f"{'it does' if one else 'they do'} nothing and the plugin keeps its defaults",
                found[tags[0]], fix="write " + "; ".join(
                    f"{ROS2_NAMES[tag]} for <{tag}>" for tag in tags))
