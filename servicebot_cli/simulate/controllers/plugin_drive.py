"""The controller of a base that a Gazebo diff-drive plugin drives, with no ros2_control.

sam_bot (Nav2's tutorial) and Leo Rover drive their base with a model-level plugin, not
diff_drive_controller; the simulator then publishes odometry where that plugin does, at its
rate, with its limits and covariances:

- Gazebo Classic's ``gazebo_ros_diff_drive`` (ROS 2; gazebo_ros_pkgs' source): the plugin
  commands the wheels and publishes odometry once per ``<update_rate>`` (default 100 Hz; ROS 1:
  ``<updateRate>``), the odometry's rate here (the simulator's control loop stays its own:
  Gazebo's sensors do not wait for the plugin); the odometry's pose and twist covariances
  are ``<covariance_x>``, ``<covariance_y>`` and ``<covariance_yaw>`` (defaults 1e-5, 1e-5,
  1e-3) with 1e12 for z, roll and pitch; its odometry source and wheel acceleration are
  :mod:`.classic_drive`'s. It publishes odometry only with
  ``<publish_odom>true`` and odom -> base on /tf only with ``<publish_odom_tf>true`` (ROS 1:
  both by default). With ``<publish_wheel_tf>true`` (ROS 1: ``<publishWheelTF>``) it puts
  each wheel's parent -> wheel transform on /tf at the same rate, whether or not anything
  publishes joint states.
- gz-sim's ``DiffDrive`` system (gz-sim's ``DiffDrive.cc``): commands the wheels at every
  physics step and publishes odometry at ``<odom_publish_frequency>`` (default 50 Hz); its
  speed limiter takes ``<max_velocity>``, ``<max_acceleration>`` and ``<max_jerk>`` (and their
  ``min_``) for both axes, overridden per axis by ``<max_linear_velocity>``,
  ``<max_angular_acceleration>``, and so on; a minimum it is not given stays unbounded
  (gz-math's ``SpeedLimiter``, not diff_drive_controller's mirror).

Both make wheel speeds from their own separation and radius, written or their defaults
(:mod:`~servicebot_cli.description.drive_plugin_wheels`); the URDF's wheels roll the robot.
Neither plugin times a command out: the last one holds until the next. The odometry topic
is the one ``inspect`` lists for the plugin (its ROS namespace and
remapping; a gz ``<odom_topic>``, else ``/model/MODEL/odometry`` with MODEL the robot's
name, the name it is usually spawned with). Pure.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

from servicebot_cli.description.drive_plugin_wheels import plugin_wheels
from servicebot_cli.description.extensions import Plugin, param
from servicebot_cli.description.model_plugins import (
    ODOMETRY,
    TF,
    diff_drive_kind,
    model_plugin_rows,
    odometry_frames,
    publishes_odom_tf,
    ros1_plugin,
    wheel_tf_joints,
)
from servicebot_cli.description.ros_names import manager_node
from servicebot_cli.kinematics.drive_geometry import LARGEST_RADIUS_M, SMALLEST_RADIUS_M
from servicebot_cli.simulate.controllers.classic_drive import ClassicDrive, odometry_source
from servicebot_cli.simulate.controllers.config import (
    ControllersFile,
    ControllersFileError,
    controllers_beside,
    missing_parameter_files,
    named_controllers_file,
    read_controllers_file,
)
from servicebot_cli.simulate.controllers.limiter import DIFF_DRIVE_CONTROLLER, GZ_MATH

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_UNKNOWN_AXES = 1e12  # z, roll and pitch: what the classic plugin writes for them
_GZ_LIMITS = (("velocity", "m_s", "rad_s"), ("acceleration", "m_s2", "rad_s2"),
              ("jerk", "m_s3", "rad_s3"))


def controllers_for(robot: RobotDescription, explicit: str | None) -> ControllersFile:
    """The controller a run of ``robot`` uses, as :mod:`.config` says which.

    A Gazebo drive plugin drives the base unless the controllers file (named, or a
    ros2_control plugin's) has a diff-drive controller: turtlebot3_manipulation's file holds
    only its arm's controllers and a joint_state_broadcaster, which then publishes beside
    the plugin.

    Raises:
        ControllersFileError: An unreadable file, or a parameter that is not a number.
    """
    named = named_controllers_file(robot, explicit)
    manager = manager_node(robot.model_plugins)
    from_file = None if named is None else read_controllers_file(named, manager)
    plugin = drive_plugin(robot) if from_file is None or from_file.name is None else None
    if plugin is not None:
        chosen = read_drive_plugin(robot, plugin)
        if from_file is not None:  # Gazebo runs both: the file's broadcasters publish too
            chosen = dataclasses.replace(
                chosen, joint_state_topics=from_file.joint_state_topics,
                joint_state_update_hz=from_file.values.get("update_rate_hz"))
    else:
        chosen = from_file or read_controllers_file(controllers_beside(robot), manager)
    missing = missing_parameter_files(robot, explicit)
    if not missing:
        return chosen
    instead = (f"the base follows {chosen.label} instead" if plugin is not None
               else f"{chosen.label} is read without it" if named
               else f"{chosen.label} is read instead" if chosen.path is not None
               else "no controller publishes odometry or joint states; give the file with "
               "--controllers FILE")
    notes = tuple(f"note: the ros2_control plugin's parameter file {path} does not exist (the "
                  f"controller manager would not start in Gazebo); {instead}" for path in missing)
    return dataclasses.replace(chosen, notes=notes)


def drive_plugin(robot: RobotDescription) -> Plugin | None:
    """The first model-level Gazebo plugin that drives a differential base, or None."""
    return next((plugin for plugin in robot.model_plugins if diff_drive_kind(plugin)), None)


def read_drive_plugin(robot: RobotDescription, plugin: Plugin) -> ControllersFile:
    """The scenario fields ``plugin`` sets, and where it publishes odometry.

    Raises:
        ControllersFileError: A parameter that is not a finite number.
    """
    label = f"Gazebo plugin {plugin.filename or plugin.name}"
    where = f"{robot.display}: {label}"
    values: dict[str, Any] = {"cmd_vel_timeout_s": math.inf}  # neither plugin has one
    classic_drive = None
    classic = diff_drive_kind(plugin) == "classic"
    if classic:
        rate = _number(plugin, where, "update_rate", "updateRate", default=100.0)
        if rate > 0:  # 0: every physics step, as often as the control loop runs
            values["publish_rate_hz"] = rate
        x, y, yaw = (_number(plugin, where, f"covariance_{axis}", default=default)
                     for axis, default in (("x", 1e-5), ("y", 1e-5), ("yaw", 1e-3)))
        diagonal = (x, y, _UNKNOWN_AXES, _UNKNOWN_AXES, _UNKNOWN_AXES, yaw)
        values["pose_covariance_diagonal"] = values["twist_covariance_diagonal"] = diagonal
        classic_drive = _classic_drive(plugin, where, rate)
    else:
        rate = _number(plugin, where, "odom_publish_frequency", default=50.0)
        if rate > 0:
            values["publish_rate_hz"] = rate
        values.update(_gz_limits(plugin, where))
    values.update(_wheels(plugin, where))
    rows = model_plugin_rows(plugin)
    topic = next((name for direction, name, message, _ in rows
                  if direction == "out" and message == ODOMETRY), None)
    if topic is not None:
        topic = topic.replace("/MODEL/", f"/{robot.name}/")
    tf_topic = None if classic else next(  # gz-sim's DiffDrive: its own tf topic
        (name.replace("/MODEL/", f"/{robot.name}/") for direction, name, message, _ in rows
         if direction == "out" and message == TF), None)
    odom_frame, base_frame = odometry_frames(plugin, robot.name, robot.root_link or "base_link")
    return ControllersFile(None, values, None, source=label, odom_topic=topic,
                           odom_frame=odom_frame, base_frame=base_frame,
                           publishes_odometry=topic is not None,
                           odom_tf=publishes_odom_tf(plugin) if classic else True,
                           tf_topic=tf_topic,
                           speed_limiter=DIFF_DRIVE_CONTROLLER if classic else GZ_MATH,
                           classic_drive=classic_drive,
                           wheel_tf_joints=_wheel_tf(robot, plugin))


def _wheels(plugin: Plugin, where: str) -> dict[str, float]:
    """The separation and radius the plugin makes wheel speeds with, written or its defaults.

    Where a number is not known (the ROS 1 skid-steer drive's own defaults), the URDF's
    wheels stand in.

    Raises:
        ControllersFileError: A value written that is no number, or not one a wheel can be
            (0 makes infinite wheel speeds).
    """
    numbers = plugin_wheels(plugin)
    if numbers is None:
        return {}
    out = {}
    for field, number in (("wheel_separation_m", numbers.separation),
                          ("wheel_radius_m", numbers.radius)):
        known = number.known_m
        if number.given and (known is None
                             or not SMALLEST_RADIUS_M <= known <= LARGEST_RADIUS_M):
            raise ControllersFileError(
                f"{where}: <{number.key}>{number.text}</{number.key}> is "
                f"{'no number' if known is None else 'no size a wheel has'}, and the plugin "
                "makes wheel speeds with it; write the wheels' own (check reports it as "
                "SB516)")
        if known is not None:
            out[field] = known
    return out



def _wheel_tf(robot: RobotDescription, plugin: Plugin) -> tuple[str, ...]:
    """The plugin's wheel joints on /tf; none when one is not a movable joint (it fails to load)."""
    movable = {j.name for j in robot.movable_joints}
    joints = wheel_tf_joints(plugin)
    return joints if movable.issuperset(joints) else ()


def _classic_drive(plugin: Plugin, where: str, rate_hz: float) -> ClassicDrive:
    """The Classic plugin's odometry source and wheel limits (:mod:`.classic_drive`)."""
    ros1 = ros1_plugin(plugin)
    source = param(plugin.params, "odometrySource" if ros1 else "odometry_source")
    return ClassicDrive(
        odometry_source=odometry_source(source, ros1=ros1),
        wheel_acceleration_m_s2=_number(
            plugin, where, "wheelAcceleration" if ros1 else "max_wheel_acceleration",
            default=0.0),
        wheel_torque_nm=_number(plugin, where, "wheelTorque" if ros1 else "max_wheel_torque",
                                default=5.0),
        update_rate_hz=rate_hz, ros1=ros1)


def _gz_limits(plugin: Plugin, where: str) -> dict[str, float]:
    """The speed limiter's bounds: each axis's own, else those for both axes."""
    out: dict[str, float] = {}
    for kind, linear, angular in _GZ_LIMITS:
        for bound in ("max", "min"):
            both = _given(plugin, where, f"{bound}_{kind}")
            for axis, unit in (("linear", linear), ("angular", angular)):
                own = _given(plugin, where, f"{bound}_{axis}_{kind}")
                value = own if own is not None else both
                if value is not None:
                    out[f"{bound}_{axis}_{kind}_{unit}"] = value
    return out


def _number(plugin: Plugin, where: str, *keys: str, default: float) -> float:
    """The parameter under the first of ``keys`` the plugin has; ``default`` without one."""
    value = _given(plugin, where, *keys)
    return default if value is None else value


def _given(plugin: Plugin, where: str, *keys: str) -> float | None:
    """The parameter under the first of ``keys`` the plugin has, or None.

    Raises:
        ControllersFileError: It is not a finite number.
    """
    for key in keys:
        text = param(plugin.params, key)
        if text is None or not text.strip():
            continue
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            raise ControllersFileError(
                f"{where}: <{key}>: expected a finite number, got {text.strip()!r}")
        return value
    return None
