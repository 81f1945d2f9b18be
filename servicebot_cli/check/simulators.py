"""Whether a description is meant for a simulator, which decides how much some defects matter.

A kinematic-only description (a MoveIt configuration, an RViz model, a ROS-Industrial support
package) is valid without masses or effort limits; one that Gazebo or MuJoCo runs is not.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_SIMULATOR_PLUGINS = (("gz_ros2_control", "gz sim"), ("ign_ros2_control", "Ignition Gazebo"),
                      ("gazebo_ros2_control", "Gazebo"), ("mujoco", "MuJoCo"),
                      ("gazebo", "Gazebo"))


def simulated_by(robot: RobotDescription) -> str | None:
    """The simulator the description is meant for, or None for a kinematic-only description.

    A ``<gazebo>`` element, or a ros2_control hardware plugin for Gazebo, Ignition, gz or
    MuJoCo, says the file is simulated.
    """
    if robot.root.find("gazebo") is not None:
        return "Gazebo"
    for plugin in robot.root.iterfind("ros2_control/hardware/plugin"):
        text = (plugin.text or "").strip().lower()
        for prefix, name in _SIMULATOR_PLUGINS:
            if text.startswith(prefix) or ("/" in text and prefix in text):
                return name
    return None
