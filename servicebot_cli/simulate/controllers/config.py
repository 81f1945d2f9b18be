"""diff_drive_controller's parameters from a ros2_control controllers file.

Which file: ``--controllers FILE`` when given; else those the ``gazebo_ros2_control`` (or
``gz_ros2_control``) plugin's ``<parameters>`` name (relative to the description; several
are merged as ROS merges them, later values winning); else, when a Gazebo
diff-drive plugin drives the base, none: the plugin's parameters are the controller's
(:mod:`.plugin_drive`); else ``controllers.yaml`` beside the description; else none (the
simulator's defaults). In the file, the controller
whose ``type`` is ``diff_drive_controller/DiffDriveController`` under ``controller_manager``
(or, since Jazzy, in its own ``ros__parameters``) gives its ``ros__parameters``;
``controller_manager``'s ``update_rate`` is the control rate. What the file configures is
what publishes: odometry (and odom -> base on /tf) only from a diff-drive controller, joint
states only from a ``joint_state_broadcaster/JointStateBroadcaster``; with no file, neither.
Pure apart from reading the one file.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.description.parameter_files import merged_parameters, parameter_files
from servicebot_cli.description.ros_names import PluginNode, controller_topic
from servicebot_cli.description.ros_parameters import (
    controller_types,
    node_parameters,
    read_parameters_file,
)
from servicebot_cli.simulate.controllers.classic_drive import ClassicDrive
from servicebot_cli.simulate.controllers.limiter import DIFF_DRIVE_CONTROLLER

GAZEBO_STEP_HZ = 1000.0
"""Gazebo's default physics rate (a 1 ms step): no sensor or controller updates more often."""

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

DIFF_DRIVE = "diff_drive_controller/DiffDriveController"
JOINT_STATE_BROADCASTER = "joint_state_broadcaster/JointStateBroadcaster"
_AXES = (("linear.x", "linear", "m_s"), ("angular.z", "angular", "rad_s"))
_OTHER_BASE = re.compile(r"(?i)mecanum|omni|tricycle|steering|ackermann|bicycle|swerve")
"""Base controllers other than a differential drive, by words in their type (Clearpath's
``clearpath_mecanum_drive_controller/MecanumDriveController`` too)."""
_GEOMETRY = (("wheel_separation", "wheel_separation_m"), ("wheel_radius", "wheel_radius_m"),
             ("wheel_separation_multiplier", "wheel_separation_multiplier"),
             ("left_wheel_radius_multiplier", "left_wheel_radius_multiplier"),
             ("right_wheel_radius_multiplier", "right_wheel_radius_multiplier"))
"""diff_drive_controller's wheel geometry parameters, by scenario field name."""


class ControllersFileError(ServicebotError):
    """A controllers file that cannot be read, or a parameter of the wrong type."""


@dataclass(frozen=True)
class ControllersFile:
    """The diff-drive parameters a controllers file sets, by scenario field name."""

    path: Path | None
    values: Mapping[str, Any]
    name: str | None = None
    """The diff-drive controller's name (its topics are ``/NAME/...``); None without one."""
    source: str | None = None
    """Where the values come from, when not from ``path`` (a Gazebo drive plugin)."""
    odom_topic: str | None = None
    """Where odometry is published (the diff drive's ``~/odom``, named in the ros2_control
    plugin's namespace); None: the simulator's default, when it publishes any."""
    publishes_odometry: bool = True
    """False when the base's controller publishes no Odometry (a Classic diff-drive plugin
    without ``<publish_odom>true``, a controllers file without a diff drive, or none)."""
    odom_tf: bool = True
    """Whether odom -> base is broadcast on /tf (diff_drive_controller's ``enable_odom_tf``)."""
    tf_topic: str | None = None
    """Where odom -> base is broadcast, when not on /tf (gz-sim's DiffDrive:
    ``/model/MODEL/tf``, or its ``<tf_topic>``)."""
    speed_limiter: str = DIFF_DRIVE_CONTROLLER
    """Whose speed limiter applies the limits: ``diff_drive_controller`` or ``gz-math``."""
    odom_frame: str | None = None
    """The odometry's ``header.frame_id`` and the odom tf's parent; None: ``odom``."""
    base_frame: str | None = None
    """The odometry's ``child_frame_id`` and the odom tf's child; None: the root link."""
    classic_drive: ClassicDrive | None = None
    """Gazebo Classic's diff-drive plugin's odometry source and wheel ramp, when it drives."""
    joint_state_topics: tuple[str, ...] = ()
    """Where the file's joint_state_broadcasters publish (none: no broadcaster)."""
    joint_state_update_hz: float | None = None
    """How often the broadcasters' controller manager runs, when a Gazebo drive plugin drives
    the base beside it (the file's ``update_rate``); None: as the base's controller."""
    wheel_tf_joints: tuple[str, ...] = ()
    """The wheel joints a Gazebo drive plugin puts on /tf itself, in its order (none: none)."""
    notes: tuple[str, ...] = ()
    """What the run should say of how the file was chosen (a named file that is missing)."""

    @property
    def label(self) -> str:
        """Where the values come from, for the summary."""
        return self.source or str(self.path)


def named_controllers_file(robot: RobotDescription,
                           explicit: str | None) -> tuple[Path, ...] | None:
    """``explicit``, else the files a ros2_control plugin's ``<parameters>`` name, else None.

    Of the plugin's files (all of them, in order: :mod:`~servicebot_cli.description.
    parameter_files`), those that exist; None when none does.
    """
    if explicit is not None:
        return (Path(explicit),)
    named = tuple(p for p in parameter_files(robot.plugins, robot.path.parent) if os.path.isfile(p))
    return named or None


def missing_parameter_files(robot: RobotDescription, explicit: str | None) -> tuple[Path, ...]:
    """The files a ros2_control plugin's ``<parameters>`` name that do not exist.

    None with ``explicit`` (``--controllers`` replaces them). Gazebo would pass each to the
    controller manager, which does not start without it.
    """
    if explicit is not None:
        return ()
    return tuple(p for p in parameter_files(robot.plugins, robot.path.parent)
                 if not os.path.isfile(p))


def controllers_beside(robot: RobotDescription) -> Path | None:
    """``controllers.yaml`` beside the description, if there is one."""
    near = robot.path.parent / "controllers.yaml"
    return near if os.path.isfile(near) else None


def read_controllers_file(path: Path | tuple[Path, ...] | None,
                          plugin_node: PluginNode | None = None) -> ControllersFile:
    """The scenario fields the diff-drive controller in ``path`` sets.

    Several files are read in order, later values overriding earlier ones, as ROS reads
    several ``--params-file`` (:func:`~servicebot_cli.description.parameter_files.
    merged_parameters`). Topics and frames are named in ``plugin_node``'s namespace, under
    its remap rules (the ros2_control Gazebo plugin's node; the root without one).

    Raises:
        ControllersFileError: Unreadable, not YAML, or a parameter that is not a number.
    """
    paths = (path,) if isinstance(path, Path) else path or ()
    if not paths:  # nothing is configured: no controller publishes
        return ControllersFile(None, {}, publishes_odometry=False, odom_tf=False)
    documents = [_document(p) for p in paths]
    document = documents[0] if len(documents) == 1 else merged_parameters(documents)
    for p, one in zip(paths, documents, strict=True):
        if not isinstance(one, dict):
            raise ControllersFileError(f"{p}: expected a mapping of controllers")
    where = paths[-1]
    label = None if len(paths) == 1 else " + ".join(str(p) for p in paths)
    nodes = node_parameters(document)
    manager = nodes.get("controller_manager", {})
    types = controller_types(nodes)
    name = next((n for n, kind in types.items() if kind == DIFF_DRIVE), None)
    params = _flat(nodes.get(name, {})) if name else {}
    values: dict[str, Any] = {}
    notes: tuple[str, ...] = ()
    if "update_rate" in manager:
        rate = _number(where, "update_rate", manager["update_rate"])
        if rate <= 0:
            raise ControllersFileError(
                f"{where}: controller_manager.update_rate: must be above 0, got "
                f"{manager['update_rate']!r}; the controller manager does not run with it "
                "(check controllers says so)")
        if rate > GAZEBO_STEP_HZ:  # gazebo_ros2_control warns and steps them with physics
            notes += (f"note: {where}: controller_manager.update_rate {rate:g} Hz is faster "
                      "than Gazebo's 1 ms physics step, and gazebo_ros2_control runs the "
                      f"controllers once a step ({GAZEBO_STEP_HZ:g} Hz)",)
            rate = GAZEBO_STEP_HZ
        values["update_rate_hz"] = rate
    for key, field in (("publish_rate", "publish_rate_hz"),
                       ("cmd_vel_timeout", "cmd_vel_timeout_s")):
        if key in params:
            values[field] = _number(where, key, params[key])
    for key, field in _GEOMETRY:  # the controller refuses a geometry that is not positive
        if key in params:
            values[field] = _number(where, key, params[key])
            if values[field] <= 0:
                raise ControllersFileError(f"{where}: {name}.{key}: must be positive, "
                                           f"got {params[key]!r}")
    for prefix, axis, unit in _AXES:
        values.update(_limits(where, params, prefix, axis, unit))
    for key in ("pose_covariance_diagonal", "twist_covariance_diagonal"):
        if key in params:
            diagonal = params[key]
            if not isinstance(diagonal, list) or len(diagonal) != 6:
                raise ControllersFileError(f"{where}: {name}.{key}: expected 6 numbers")
            values[key] = tuple(_number(where, key, v) for v in diagonal)
    namespace = plugin_node.namespace if plugin_node else "/"
    odom_frame, base_frame = _frames(where, params, namespace) if name else (None, None)
    other = next(((n, kind) for n, kind in types.items() if _OTHER_BASE.search(kind)), None)
    notes += (f"note: {where}: the base's controller '{other[0]}' is a {other[1]}, which "
              "simulate does not model: the base is driven as a differential drive on its "
              "wheels, and no odometry is published",) if other and not name else ()
    return ControllersFile(where, values, name, source=label, publishes_odometry=bool(name),
                           odom_topic=controller_topic(plugin_node, name, "~/odom")
                           if name else None,
                           odom_tf=bool(name) and params.get("enable_odom_tf") is not False,
                           odom_frame=odom_frame, base_frame=base_frame,
                           joint_state_topics=_broadcaster_topics(nodes, types, plugin_node),
                           notes=notes)


def _broadcaster_topics(nodes: Mapping[str, Any], types: Mapping[str, str],
                        manager: PluginNode | None) -> tuple[str, ...]:
    """Where each joint_state_broadcaster publishes: ``joint_states``, else ``~/joint_states``.

    ``~/`` (the controller's own namespace) with ``use_local_topics: true``; either in the
    controller manager's namespace.
    """
    return tuple(controller_topic(manager, name, "~/joint_states" if _flat(
                     nodes.get(name, {})).get("use_local_topics") is True else "joint_states")
                 for name, kind in types.items()
                 if kind == JOINT_STATE_BROADCASTER)


def _document(path: Path) -> Any:
    """One controllers file, parsed.

    Raises:
        ControllersFileError: Unreadable or not YAML.
    """
    return read_parameters_file(path, ControllersFileError)


def _frames(path: Path, params: Mapping[str, Any], namespace: str = "/") -> tuple[str, str]:
    """``odom_frame_id`` (default ``odom``) and ``base_frame_id`` (``base_link``), prefixed.

    diff_drive_controller puts ``tf_frame_prefix`` before both (``~`` is the controller's
    ``namespace``; a trailing ``/`` added, a leading one dropped), unless
    ``tf_frame_prefix_enable`` is false; an empty prefix is the namespace's, none at the root.
    """
    frames = []
    for key, default in (("odom_frame_id", "odom"), ("base_frame_id", "base_link")):
        value = params.get(key, default)
        if not isinstance(value, str):
            raise ControllersFileError(f"{path}: {key}: expected a frame name, got {value!r}")
        frames.append(value)
    prefix = params.get("tf_frame_prefix", "") or namespace
    if params.get("tf_frame_prefix_enable") is not False and isinstance(prefix, str) \
            and prefix.strip("/"):
        prefix = prefix.replace("~", namespace.rstrip("/") + "/", 1)
        prefix = (prefix if prefix.endswith("/") else prefix + "/").removeprefix("/")
        frames = [prefix + frame for frame in frames]
    return frames[0], frames[1]


def _limits(path: Path, params: Mapping[str, Any], prefix: str, axis: str,
            unit: str) -> dict[str, float]:
    """Velocity, acceleration and jerk limits of one axis.

    Humble's ``has_*_limits`` flag switches a kind of limit on or off; without the flag (Jazzy
    deprecated it: a limit is on when its value is given) the values given are the limits.
    """
    out: dict[str, float] = {}
    for kind, suffix in (("velocity", unit), ("acceleration", f"{unit[:-2]}_s2"),
                         ("jerk", f"{unit[:-2]}_s3")):
        flag = params.get(f"{prefix}.has_{kind}_limits")
        if flag is not None and not flag:  # limits switched off: none, whatever the values say
            out[f"max_{axis}_{kind}_{suffix}"] = math.inf
            out[f"min_{axis}_{kind}_{suffix}"] = -math.inf
            continue
        high = params.get(f"{prefix}.max_{kind}")
        if high is not None:
            out[f"max_{axis}_{kind}_{suffix}"] = _number(path, f"{prefix}.max_{kind}", high)
        low = params.get(f"{prefix}.min_{kind}")
        if low is not None:
            out[f"min_{axis}_{kind}_{suffix}"] = _number(path, f"{prefix}.min_{kind}", low)
    return out


def _flat(mapping: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested parameters (``linear: {x: {max_velocity: 1}}``) as dotted names."""
    out: dict[str, Any] = {}
    for key, value in mapping.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(_flat(value, f"{name}."))
        else:
            out[name] = value
    return out


def _number(path: Path, key: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) \
            or not math.isfinite(float(value)):
        raise ControllersFileError(f"{path}: {key}: expected a finite number, got {value!r}")
    return float(value)
