"""Topics of model-level Gazebo plugins that drive the base or publish joint states.

Gazebo Classic's ROS 2 plugins (gazebo_ros_pkgs) name relative topics in their node's
``<ros><namespace>``, renamed by ``<ros><remapping>`` and ``<ros><argument>`` rules
(:mod:`.ros_names`); their ROS 1 ancestors use
``<commandTopic>``, ``<odometryTopic>``, ``<topicName>`` and ``<robotNamespace>``:

- ``gazebo_ros_diff_drive``: consumes ``cmd_vel``; publishes ``odom`` only with
  ``<publish_odom>true`` and ``/tf`` only with ``<publish_odom_tf>`` or ``<publish_wheel_tf>``
  (all three default to false), and no joint states. The ROS 1 plugin publishes ``odom``
  unless ``<publishTf>false``, odom -> base on ``/tf`` unless ``<publishTf>`` or
  ``<publishOdomTF>`` is false, the wheels on ``/tf`` with ``<publishWheelTF>true`` and their
  joint states on ``joint_states`` with ``<publishWheelJointState>true``;
- ``gazebo_ros_planar_move``: ``cmd_vel`` in, ``odom`` and ``/tf`` out (both default true);
- ``gazebo_ros_joint_state_publisher``: ``joint_states`` out;
- ``gazebo_ros_p3d``: ``odom`` out (ROS 1: ``<topicName>``), its body's ground truth;
- ``gazebo_ros_imu`` (ROS 1 only, a model plugin: ROS 2 has the sensor plugin instead):
  ``<topicName>`` out (default ``/default_imu``), stamped ``<frameName>`` (default
  ``<bodyName>``), the link it measures;
- hector_gazebo_plugins' ``hector_gazebo_ros_gps``: ``<topicName>`` (``fix``) and
  ``<velocityTopicName>`` (``fix_velocity``) out.

gz-sim systems publish gz-transport topics, which ros_gz_bridge shows under the same name:

- ``DiffDrive``: consumes ``<topic>`` (default ``/model/MODEL/cmd_vel``), publishes
  ``<odom_topic>`` (``/model/MODEL/odometry``) and ``<tf_topic>`` (``/model/MODEL/tf``);
- ``OdometryPublisher``: ``<odom_topic>`` (``/model/MODEL/odometry``), ``<tf_topic>``
  (``/model/MODEL/pose``);
- ``JointStatePublisher``: ``<topic>`` (default ``/world/WORLD/model/MODEL/joint_state``).

MODEL is the name the robot is spawned with and WORLD the world's, neither of which the
description knows.

Their odometry's frames (:func:`odometry_frames`) are ``<odometry_frame>`` and
``<robot_base_frame>`` (ROS 1: ``<odometryFrame>``, ``<robotBaseFrame>``), by default ``odom``
and ``base_footprint``; gz-sim's DiffDrive's ``<frame_id>`` and ``<child_frame_id>``, by
default ``MODEL/odom`` and ``MODEL/`` its canonical link, which ros_gz_bridge keeps.
"""

from __future__ import annotations

from collections.abc import Callable

from servicebot_cli.description.elements import parse_float
from servicebot_cli.description.extensions import Plugin, param, params_all, sdf_true
from servicebot_cli.description.sensors import ImuSpec, NoiseSpec, plugin_topic

Row = tuple[str, str, str, str | None]
"""direction, topic, message type, note."""

TWIST, ODOMETRY = "geometry_msgs/msg/Twist", "nav_msgs/msg/Odometry"
TF, JOINT_STATE = "tf2_msgs/msg/TFMessage", "sensor_msgs/msg/JointState"
IMU = "sensor_msgs/msg/Imu"
NAV_SAT_FIX, VECTOR3_STAMPED = "sensor_msgs/msg/NavSatFix", "geometry_msgs/msg/Vector3Stamped"
GZ_NOTE = "gz topic (ros_gz_bridge keeps the name unless configured otherwise)"
MODEL_NOTE = GZ_NOTE + "; MODEL: the name the robot is spawned with"


def _flag(plugin: Plugin, key: str, default: bool) -> bool:
    text = (param(plugin.params, key) or "").strip()
    return default if not text else sdf_true(text)


def _absolute(topic: str) -> str:
    return "/" + "/".join(part for part in topic.split("/") if part)


_ROS1_KEYS = frozenset((
    "commandTopic", "odometryTopic", "robotNamespace", "topicName", "leftJoint", "rightJoint",
    "wheelSeparation", "wheelDiameter", "updateRate", "publishOdomTF", "publishWheelTF",
    "publishTf", "odometryFrame", "robotBaseFrame", "odometrySource", "wheelAcceleration",
    "wheelTorque", "legacyMode", "publishWheelJointState"))
"""Parameters only gazebo_ros_pkgs' ROS 1 plugins read (camelCase), defaults or not."""


def ros1_plugin(plugin: Plugin) -> bool:
    """Whether ``plugin`` is written for gazebo_ros_pkgs' ROS 1 plugins (no ``<ros>`` block).

    Not in a file another plugin of which has a ``<ros>`` block: that file is for ROS 2.
    """
    return not plugin.for_ros2 and any(key in _ROS1_KEYS for key, _ in plugin.params)


def publishes_odometry(plugin: Plugin, default: bool = False) -> bool:
    """Whether a Classic drive plugin publishes Odometry.

    ROS 2: ``<publish_odom>`` (``default``: false for diff drive, true for planar move);
    ROS 1: ``<publishTf>`` (default true), which gates the whole odometry publication.
    """
    if ros1_plugin(plugin):
        return _flag(plugin, "publishTf", True)
    return _flag(plugin, "publish_odom", default)


def publishes_odom_tf(plugin: Plugin, default: bool = False) -> bool:
    """Whether a Classic drive plugin broadcasts odom -> base on /tf.

    ROS 2: ``<publish_odom_tf>`` (``default``: false for diff drive, true for planar move);
    ROS 1: ``<publishOdomTF>`` (default true) and ``<publishTf>`` (default true).
    """
    if ros1_plugin(plugin):
        return _flag(plugin, "publishOdomTF", True) and _flag(plugin, "publishTf", True)
    return _flag(plugin, "publish_odom_tf", default)


def _publishes_wheel_tf(plugin: Plugin) -> bool:
    """``<publish_wheel_tf>`` (ROS 1: ``<publishWheelTF>``, not gated by ``<publishTf>``)."""
    return _flag(plugin, "publishWheelTF" if ros1_plugin(plugin) else "publish_wheel_tf", False)


def wheel_tf_joints(plugin: Plugin) -> tuple[str, ...]:
    """The joints whose parent -> child transforms a Classic diff drive puts on ``/tf``.

    With ``<publish_wheel_tf>true`` (ROS 1: ``<publishWheelTF>``), one TFMessage per joint,
    each pair's right joint before its left, pairs in document order (ROS 2 repeats
    ``<left_joint>``/``<right_joint>`` for ``<num_wheel_pairs>``, and loads nothing when the
    counts differ; ROS 1 has one ``<leftJoint>``/``<rightJoint>`` pair); none without.
    """
    if "gazebo_ros_diff_drive" not in plugin.filename or not _publishes_wheel_tf(plugin):
        return ()
    if ros1_plugin(plugin):
        return ((param(plugin.params, "rightJoint") or "right_joint").strip(),
                (param(plugin.params, "leftJoint") or "left_joint").strip())
    lefts, rights = (params_all(plugin.params, key) for key in ("left_joint", "right_joint"))
    try:
        pairs = max(1, int(_text(plugin, "num_wheel_pairs") or 1))
    except ValueError:
        return ()
    if not len(lefts) == len(rights) == pairs:
        return ()
    return tuple(name.strip() for pair in zip(rights, lefts, strict=True) for name in pair)


def _classic_drive(plugin: Plugin, odom_default: bool, tf_default: bool) -> list[Row]:
    rows: list[Row] = [("in", _absolute(plugin_topic(plugin, "cmd_vel", "commandTopic")),
                        TWIST, None)]
    if publishes_odometry(plugin, odom_default):
        rows.append(("out", _absolute(plugin_topic(plugin, "odom", "odometryTopic")),
                     ODOMETRY, None))
    if publishes_odom_tf(plugin, tf_default) or _publishes_wheel_tf(plugin):
        rows.append(("out", "/tf", TF, None))
    return rows


def odometry_frames(plugin: Plugin, model: str, root_link: str) -> tuple[str, str]:
    """The frame and child frame of a drive plugin's odometry, and of its odom -> base tf.

    ``model`` is the name the robot is spawned with and ``root_link`` its first link (gz-sim's
    canonical link). gazebo_ros_pkgs' ROS 2 plugins use their tags as written; the ROS 1 ones
    pass them through ``tf::resolve`` with no ``tf_prefix``, which drops a leading ``/``.
    """
    odom_tag, base_tag = odometry_frame_tags(plugin)
    if diff_drive_kind(plugin) == "gz":
        return (_text(plugin, odom_tag) or f"{model}/odom",
                _text(plugin, base_tag) or f"{model}/{root_link}")
    if ros1_plugin(plugin):
        return ((_text(plugin, odom_tag) or "odom").lstrip("/"),
                (_text(plugin, base_tag) or "base_footprint").lstrip("/"))
    return _text(plugin, odom_tag) or "odom", _text(plugin, base_tag) or "base_footprint"


def odometry_frame_tags(plugin: Plugin) -> tuple[str, str]:
    """The tags a drive plugin reads its odometry frame and its base frame from."""
    if diff_drive_kind(plugin) == "gz":
        return "frame_id", "child_frame_id"
    if ros1_plugin(plugin):
        return "odometryFrame", "robotBaseFrame"
    return "odometry_frame", "robot_base_frame"


def _text(plugin: Plugin, key: str) -> str:
    return (param(plugin.params, key) or "").strip()


def _diff_drive(plugin: Plugin) -> list[Row]:
    rows = _classic_drive(plugin, odom_default=False, tf_default=False)
    if "gazebo_ros_diff_drive" in plugin.filename and ros1_plugin(plugin) \
            and _flag(plugin, "publishWheelJointState", False):  # not skid steer's
        rows += _joint_states(plugin)
    return rows


def _planar_move(plugin: Plugin) -> list[Row]:
    return _classic_drive(plugin, odom_default=True, tf_default=True)


def _joint_states(plugin: Plugin) -> list[Row]:
    return [("out", _absolute(plugin_topic(plugin, "joint_states")), JOINT_STATE, None)]


def _imu(plugin: Plugin) -> list[Row]:
    if param(plugin.params, "topicName") == "":  # written empty: the plugin advertises none
        return []
    return [("out", _absolute(plugin_topic(plugin, "/default_imu")), IMU, None)]


def _hector_gps(plugin: Plugin) -> list[Row]:
    """hector_gazebo_plugins' GPS (``gazebo_ros_gps.cpp``): NavSatFix on ``<topicName>``
    (default ``fix``) and its velocity on ``<velocityTopicName>`` (``fix_velocity``), in the
    node's ``<robotNamespace>``.
    """  # noqa: D205
    return [("out", _hector_topic(plugin, "topicName", "fix"), NAV_SAT_FIX, None),
            ("out", _hector_topic(plugin, "velocityTopicName", "fix_velocity"),
             VECTOR3_STAMPED, None)]


def _hector_topic(plugin: Plugin, key: str, default: str) -> str:
    """A hector plugin's topic: ``key`` as written, else ``default``, in its namespace."""
    if _text(plugin, key):
        return _absolute(plugin_topic(plugin, default, key))
    namespace = _text(plugin, "robotNamespace") or _text(plugin, "ros/namespace")
    return _absolute(f"{namespace}/{default}")


def _p3d(plugin: Plugin) -> list[Row]:
    """``gazebo_ros_p3d``: its body's pose and twist as Odometry, the simulator's ground truth.

    ROS 2 publishes on ``odom`` and loads nothing without ``<body_name>``; ROS 1 publishes on
    ``<topicName>`` and needs it and ``<bodyName>`` (gazebo_plugins' gazebo_ros_p3d.cpp).
    """
    body = _text(plugin, "body_name") or _text(plugin, "bodyName")
    legacy = ros1_plugin(plugin) or bool(_text(plugin, "bodyName"))
    if not body or (legacy and not _text(plugin, "topicName")):
        return []
    return [("out", _absolute(plugin_topic(plugin, "odom")), ODOMETRY,
             f"ground truth of {body}")]


def model_imu(plugin: Plugin) -> tuple[str, ImuSpec] | None:
    """A ROS 1 ``gazebo_ros_imu`` model plugin's link and the IMU it publishes; None for others.

    As noetic ``gazebo_ros_imu.cpp`` reads its tags: ``<topicName>`` (default
    ``/default_imu``; written empty, it publishes nothing: None), ``<frameName>`` (default
    ``<bodyName>``), ``<updateRate>`` (default 0: every step), ``<gaussianNoise>`` (default 0:
    that standard deviation on each axis of the angular velocity and the acceleration, its
    square on all three covariance diagonals, the orientation's too). It measures its link
    itself: no ``<sensor type="imu">`` is needed. None too without ``<bodyName>``, which the
    plugin cannot run without.
    """
    body = _text(plugin, "bodyName")
    rows = _imu(plugin) if "gazebo_ros_imu.so" in plugin.filename and body else []
    if not rows:
        return None
    rate = parse_float(param(plugin.params, "updateRate")) or 0.0
    sigma = parse_float(param(plugin.params, "gaussianNoise")) or 0.0
    axis = NoiseSpec("gaussian", 0.0, sigma) if sigma > 0 else None
    return body, ImuSpec(rate if rate > 0 else None, (axis, axis, axis), (axis, axis, axis),
                         _text(plugin, "frameName") or body, rows[0][1],
                         orientation_variance=sigma**2)


def _gz(plugin: Plugin, key: str, default: str) -> tuple[str, str]:
    text = (param(plugin.params, key) or "").strip()
    return (_absolute(text), GZ_NOTE) if text else (default, MODEL_NOTE)


def _gz_diff_drive(plugin: Plugin) -> list[Row]:
    rows: list[Row] = []
    for direction, key, default, message in (
            ("in", "topic", "/model/MODEL/cmd_vel", TWIST),
            ("out", "odom_topic", "/model/MODEL/odometry", ODOMETRY),
            ("out", "tf_topic", "/model/MODEL/tf", TF)):
        topic, note = _gz(plugin, key, default)
        rows.append((direction, topic, message, note))
    return rows


def _gz_odometry(plugin: Plugin) -> list[Row]:
    odom, odom_note = _gz(plugin, "odom_topic", "/model/MODEL/odometry")
    tf, tf_note = _gz(plugin, "tf_topic", "/model/MODEL/pose")
    return [("out", odom, ODOMETRY, odom_note), ("out", tf, TF, tf_note)]


def _gz_joint_states(plugin: Plugin) -> list[Row]:
    topic, note = _gz(plugin, "topic", "/world/WORLD/model/MODEL/joint_state")
    return [("out", topic, JOINT_STATE, note.replace("MODEL:", "WORLD, MODEL: the world's and"))]


_KNOWN: tuple[tuple[tuple[str, ...], Callable[[Plugin], list[Row]]], ...] = (
    (("gazebo_ros_diff_drive", "gazebo_ros_skid_steer_drive"), _diff_drive),
    (("gazebo_ros_planar_move",), _planar_move),
    (("gazebo_ros_joint_state_publisher",), _joint_states),
    (("gazebo_ros_imu.so",), _imu),
    (("hector_gazebo_ros_gps",), _hector_gps),
    (("gazebo_ros_p3d",), _p3d),
    (("diff-drive-system", "::DiffDrive"), _gz_diff_drive),
    (("odometry-publisher-system", "::OdometryPublisher"), _gz_odometry),
    (("joint-state-publisher-system", "::JointStatePublisher"), _gz_joint_states),
)


DIFF_DRIVES = {"gazebo_ros_diff_drive": "classic", "gazebo_ros_skid_steer_drive": "classic",
               "diff-drive-system": "gz", "::DiffDrive": "gz"}
"""The plugins that drive a differential base, by kind: Gazebo Classic's or gz-sim's."""


def diff_drive_kind(plugin: Plugin) -> str | None:
    """``classic`` or ``gz`` for a plugin of :data:`DIFF_DRIVES`; None for any other."""
    return next((kind for needle, kind in DIFF_DRIVES.items() if _is(plugin, needle)), None)


def _is(plugin: Plugin, needle: str) -> bool:
    return plugin.name.endswith(needle) if needle.startswith("::") else needle in plugin.filename


def model_plugin_rows(plugin: Plugin) -> list[Row]:
    """What a known model-level plugin consumes and publishes; [] for any other plugin."""
    for needles, derive in _KNOWN:
        if any(_is(plugin, n) for n in needles):
            return derive(plugin)
    return []
