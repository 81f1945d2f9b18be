"""Drive wheels a diff-drive plugin or ``<ros2_control>`` names, where links have no round shape.

Pepper's wheels are meshes: nothing in the links says their radius, but its
``libgazebo_ros_diff_drive`` plugin names the wheel joints and their diameter, and Gazebo
drives them so. Gazebo Classic's plugin (ROS 1 ``leftJoint``/``rightJoint``/``wheelDiameter``;
ROS 2 ``left_joint``/``right_joint``/``wheel_diameter``, a pair per ``num_wheel_pairs``) and
gz-sim's DiffDrive system (``left_joint``/``right_joint``/``wheel_radius``) are read. A
wheel's centre and radius are its round mesh's (:mod:`.mesh_wheels`), where it has one;
else its joint's origin and the radius the plugin says. Its side, as for every wheel, is the
sign of its y.

Without such a plugin, the joints ``<ros2_control>`` commands by velocity (what
diff_drive_controller drives) are the wheels, where each is drawn as a round mesh: a
SolidWorks export driven by gazebo_ros2_control has nothing else to say where and how
large its wheels are.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.description.extensions import Plugin, param, params_all
from servicebot_cli.description.model_plugins import ros1_plugin
from servicebot_cli.kinematics.mesh_wheels import MeshPoints, round_mesh
from servicebot_cli.kinematics.wheel_joints import (
    PARALLEL,
    Wheel,
    turns_freely,
    unit_axis,
    wheel_at,
)

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_GZ_DIFF_DRIVE = ("gz-sim-diff-drive-system", "ignition-gazebo-diff-drive-system",
                  "gz::sim::systems::DiffDrive", "ignition::gazebo::systems::DiffDrive")


def plugin_wheels(robot: RobotDescription, world: dict[str, np.ndarray],
                  meshes: MeshPoints | None = None) -> list[Wheel]:
    """The wheels of the first diff-drive plugin that names usable ones; none without.

    ``meshes``: the vertices of mesh shapes, for wheels drawn as meshes.
    """
    for plugin in robot.plugins:
        named = _named(plugin)
        if named is None:
            continue
        joints, radius_m = named
        wheels = wheels_named(robot, joints, radius_m, world, meshes)
        if {w.side for w in wheels} == {"left", "right"}:
            return wheels
    return control_wheels(robot, world, meshes)


def control_wheels(robot: RobotDescription, world: dict[str, np.ndarray],
                   meshes: MeshPoints | None) -> list[Wheel]:
    """The round-mesh wheels of the joints ``<ros2_control>`` commands by velocity; none
    unless they are on both sides.
    """  # noqa: D205
    names = dict.fromkeys(joint.name for block in robot.ros2_control for joint in block.joints
                          if any(i.name == "velocity" for i in joint.command_interfaces))
    wheels = [wheel for wheel in wheels_named(robot, names, math.nan, world, meshes)
              if math.isfinite(wheel.radius_m)]  # a round mesh said its radius
    return wheels if {w.side for w in wheels} == {"left", "right"} else []


def wheels_named(robot: RobotDescription, names: Iterable[str], radius_m: float = math.nan,
                 world: dict[str, np.ndarray] | None = None,
                 meshes: MeshPoints | None = None) -> list[Wheel]:
    """The wheels on the joints ``names`` (a plugin's, a controller's), where they are.

    ``world``: each link's pose at zero, computed when not given. A joint that does not
    turn freely across the robot is left out. ``radius_m``: what the plugin says, NaN when
    nothing says it (a controller's wheels); a wheel's round mesh, read through
    ``meshes``, says its own.
    """
    if world is None:
        from servicebot_cli.kinematics.link_poses import link_transforms

        world = link_transforms(robot)
    return [wheel for name in names
            if (wheel := _wheel(robot, name, world, radius_m, meshes)) is not None]


def _named(plugin: Plugin) -> tuple[list[str], float] | None:
    """The wheel joints and the wheel radius [m] a diff-drive ``plugin`` gives, if it is one."""
    if "gazebo_ros_diff_drive" in plugin.filename:
        if ros1_plugin(plugin):
            joints = [param(plugin.params, "leftJoint"), param(plugin.params, "rightJoint")]
            diameter = param(plugin.params, "wheelDiameter")
        else:
            joints = [*params_all(plugin.params, "left_joint"),
                      *params_all(plugin.params, "right_joint")]
            diameter = param(plugin.params, "wheel_diameter")
        radius_m = _number(diameter) / 2
    elif any(kind in (plugin.filename, plugin.name) for kind in _GZ_DIFF_DRIVE):
        joints = [*params_all(plugin.params, "left_joint"),
                  *params_all(plugin.params, "right_joint")]
        radius_m = _number(param(plugin.params, "wheel_radius"))
    else:
        return None
    names = [name.strip() for name in joints if name and name.strip()]
    if not names or not (math.isfinite(radius_m) and radius_m > 0):
        return None
    return names, radius_m


def _number(text: str | None) -> float:
    try:
        return float(text) if text is not None else math.nan
    except ValueError:
        return math.nan


def _wheel(robot: RobotDescription, name: str, world: dict[str, np.ndarray],
           radius_m: float, meshes: MeshPoints | None) -> Wheel | None:
    """The wheel on joint ``name``: one that turns freely, across the robot; else None."""
    joint = next((j for j in robot.joints if j.name == name), None)
    if joint is None or not turns_freely(joint) or joint.child not in world:
        return None
    axis = unit_axis(joint)
    if axis is None:
        return None
    transform = world[joint.child]
    axis_in_root = transform[:3, :3] @ axis
    position = transform[:3, 3]
    link = robot.find_link(joint.child)
    mesh = None if meshes is None or link is None else round_mesh(link, axis, meshes)
    if mesh is not None:
        position = (transform @ np.append(mesh[0], 1.0))[:3]
        radius_m = mesh[1]
    if abs(axis_in_root[1]) < PARALLEL or not np.all(np.isfinite(position)):
        return None
    return wheel_at(joint, position, radius_m, axis_in_root)
