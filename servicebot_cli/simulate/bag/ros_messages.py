"""A run's messages as serialized ROS 2 messages on the robot's topics, a piece at a time.

Topics follow the robot's documentation: the sensors' topics as their Gazebo plugins resolve
them, a ray sensor's in the type its plugin names (:mod:`.ray_messages`), (``scan``,
``imu/data``, ``pi_camera/camera_info``; with images ``pi_camera/image_raw``
(rgb8) and, with depth, ``pi_camera/depth/image_raw`` (32FC1), as gazebo_ros_camera names
them), ``/CONTROLLER/odom`` (the controllers file's diff drive) and ``/tf`` (odom -> base)
as diff_drive_controller publishes them, in its ``odom_frame_id`` and ``base_frame_id`` (or
a Gazebo drive plugin's topic and frames; none when nothing configured publishes odometry),
``/joint_states`` where a joint_state_broadcaster or a Gazebo plugin publishes them,
``/tf`` for movable joints (with joint states), the wheels on ``/tf`` where a Gazebo drive
plugin puts them there itself, ``/tf_static`` for fixed ones and
``/robot_description`` (the URDF, once) as robot_state_publisher, and
``/clock`` at every control tick as gazebo_ros publishes simulated time. Header stamps are
simulated time; each publisher offers the QoS its ROS node does. ``/tf`` has two publishers.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.bag import camera_messages, cdr, qos, ray_messages
from servicebot_cli.simulate.bag import quaternions as rotations
from servicebot_cli.simulate.bag.byte_rows import ByteRows, Payloads
from servicebot_cli.simulate.bag.tf_messages import (
    ODOM_FRAME,
    JointTransforms,
    WheelTransform,
    tf_base,
    tf_static,
)
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.controllers.config import ControllersFile
from servicebot_cli.simulate.scenario.camera import CameraImages
from servicebot_cli.simulate.simulator import SimResult

FloatArray = npt.NDArray[np.float64]
ODOM_TOPIC, TF_TOPIC, TF_STATIC_TOPIC = "/diff_controller/odom", "/tf", "/tf_static"
JOINT_STATES_TOPIC = "/joint_states"
CLOCK_TOPIC, DESCRIPTION_TOPIC = "/clock", "/robot_description"
TF_TYPE = "tf2_msgs/msg/TFMessage"
IMAGE_TYPE = "sensor_msgs/msg/Image"
CAMERA_INFO_TYPE = "sensor_msgs/msg/CameraInfo"
NO_IMAGES = CameraImages()


@dataclass(frozen=True)
class Publisher:
    """One ROS node's messages on one topic, and the QoS the node offers.

    ``times`` gives a piece's message stamps [s] and ``serialize`` their CDR payloads, one
    row of bytes per message (rows of a few sizes for a point cloud, in order).
    """

    topic: str
    type: str
    qos: qos.Qos
    times: Callable[[SimResult], FloatArray]
    serialize: Callable[[SimResult], ByteRows | Payloads]


@dataclass(frozen=True)
class Topic:
    """A topic of the run: its type and the profile each of its publishers offers."""

    name: str
    type: str
    offered_qos: tuple[qos.Qos, ...]


def absolute(topic: str | None, fallback: str) -> str:
    """A topic name with its leading slash (``scan`` -> ``/scan``)."""
    name = topic or fallback
    return name if name.startswith("/") else f"/{name}"


def odom_topic(controllers: ControllersFile) -> str | None:
    """Where the base's controller of ``controllers`` publishes odometry.

    The diff-drive controller's ``~/odom`` as the controllers file names it, or a Gazebo
    drive plugin's topic when the plugin drives the base; None when it publishes none.
    """
    if not controllers.publishes_odometry:
        return None
    return controllers.odom_topic or ODOM_TOPIC  # a controllers file names its diff drive's


def odom_frames(controllers: ControllersFile, body: SimRobot) -> tuple[str, str]:
    """The frames of the odometry and of odom -> base: the controller's, else odom and root."""
    return controllers.odom_frame or ODOM_FRAME, controllers.base_frame or body.root_link


def publishers(body: SimRobot, images: CameraImages = NO_IMAGES,
               odom_topic: str | None = ODOM_TOPIC, odom_tf: bool = True,
               frames: tuple[str, str] | None = None,
               joint_states: Sequence[str] = (JOINT_STATES_TOPIC,),
               wheel_tf: Sequence[str] = (), tf_topic: str | None = None) -> list[Publisher]:
    """Every publisher of a run of ``body``: latched topics and the clock first.

    Camera images only when ``images`` are on; odometry on ``odom_topic`` (the diff-drive
    controller's ``~/odom``; None: none) and odom -> base on ``tf_topic`` (None: /tf) when
    ``odom_tf``, both in
    ``frames`` (odometry frame, base frame; None: ``odom`` and the root link); joint states
    on each of ``joint_states`` and, from them, the movable joints on /tf (none without);
    the ``wheel_tf`` joints on /tf at the odometry's times (a Gazebo drive plugin's).
    Messages with equal stamps are in this order in a bag.
    """
    out = [Publisher(DESCRIPTION_TOPIC, "std_msgs/msg/String", qos.ROBOT_DESCRIPTION, _once,
                     _robot_description),
           Publisher(TF_STATIC_TOPIC, TF_TYPE, qos.STATIC_TF, _once, tf_static),
           Publisher(CLOCK_TOPIC, "rosgraph_msgs/msg/Clock", qos.CLOCK, _tick_times, _clock)]
    if odom_topic is not None:
        out.append(Publisher(odom_topic, "nav_msgs/msg/Odometry", qos.SYSTEM_DEFAULTS,
                             lambda r: r.odometry.times_s, partial(_odometry, frames=frames)))
    out += [Publisher(TF_TOPIC, TF_TYPE, qos.DYNAMIC_TF, lambda r: r.odometry.times_s,
                      WheelTransform(joint)) for joint in wheel_tf]
    if odom_tf:
        out.append(Publisher(tf_topic or TF_TOPIC, TF_TYPE, qos.SYSTEM_DEFAULTS,
                             lambda r: r.odometry.times_s, partial(tf_base, frames=frames)))
    if joint_states:  # robot_state_publisher's transforms come from joint states
        out.append(Publisher(TF_TOPIC, TF_TYPE, qos.DYNAMIC_TF, lambda r: r.joints.times_s,
                             JointTransforms()))
    out += [Publisher(topic, "sensor_msgs/msg/JointState", qos.SYSTEM_DEFAULTS,
                      lambda r: r.joints.times_s, _joint_states) for topic in joint_states]
    out += _ray_publishers(body)
    if body.imu is not None:
        out.append(Publisher(absolute(body.imu.spec.topic, "imu"), "sensor_msgs/msg/Imu",
                             qos.SENSOR_DATA,
                             lambda r: r.imu.times_s if r.imu else np.zeros(0), _imu))
    if body.camera is not None:
        spec = body.camera.spec
        depth = dict(spec.depth_topics)  # a depth camera's plugin: its own depth outputs
        infos = [spec.info_topic, *(t for t, kind in depth.items() if kind == CAMERA_INFO_TYPE)]
        out += [Publisher(absolute(topic, "camera_info"), CAMERA_INFO_TYPE, qos.SENSOR_DATA,
                          lambda r: r.camera_times_s, camera_messages.camera_info)
                for topic in infos]
        if images.enabled:
            image_topic = absolute(spec.image_topic, "image_raw")
            if spec.colour:  # a gz depth camera's topic carries its depth image alone
                out.append(Publisher(image_topic, IMAGE_TYPE, qos.SENSOR_DATA,
                                     lambda r: r.camera_times_s, camera_messages.colour_images))
            if images.depth or not spec.colour:
                named = next((t for t, kind in depth.items() if kind == IMAGE_TYPE), None)
                out.append(Publisher(absolute(named, "") if named else depth_topic(image_topic),
                                     IMAGE_TYPE, qos.SENSOR_DATA,
                                     lambda r: r.camera_times_s, camera_messages.depth_images))
    return out


def _ray_publishers(body: SimRobot) -> list[Publisher]:
    """Each ray sensor's publisher, in the type its plugin names, on its topic and frame.

    Ray sensor ``i``'s scans are ``SimResult.scans[i]``; a type the simulator cannot write
    has no publisher (the run notes it, :func:`.ray_messages.unpublished_note`).
    """
    out = []
    for index, mounted in enumerate(body.ray_sensors):
        spec = mounted.spec
        if ray_messages.unpublished_note(spec) is not None:
            continue
        message, serialize = ray_messages.serializer_for(spec)
        frame = spec.frame or body.root_link
        out.append(Publisher(absolute(spec.topic, "scan"), message, qos.SENSOR_DATA,
                             partial(_scan_times, index=index),
                             partial(_scan_messages, index=index, serialize=serialize,
                                     frame=frame)))
    return out


def _scan_times(result: SimResult, index: int) -> FloatArray:
    """Ray sensor ``index``'s scan times in the piece [s]."""
    return result.scans[index].times_s


def _scan_messages(result: SimResult, index: int, serialize: ray_messages.Serializer,
                   frame: str) -> ByteRows | Payloads:
    """Ray sensor ``index``'s messages of the piece, stamped in ``frame``."""
    return serialize(result.scans[index], frame)


def depth_topic(image_topic: str) -> str:
    """gazebo_ros_camera's depth topic beside ``image_topic``: ``NAME/depth/image_raw``."""
    return f"{image_topic.rsplit('/', 1)[0]}/depth/image_raw"


def topics(publishers: Sequence[Publisher]) -> list[Topic]:
    """The publishers' topics, in the order each first appears."""
    names = list(dict.fromkeys(p.topic for p in publishers))
    return [Topic(name, next(p.type for p in publishers if p.topic == name),
                  tuple(p.qos for p in publishers if p.topic == name)) for name in names]


def _once(result: SimResult) -> FloatArray:
    """Time 0 in the first piece, nothing after: a message published once."""
    return np.zeros(1 if result.first else 0)


def _tick_times(result: SimResult) -> FloatArray:
    """Each tick's start [s], and the run's end in its last piece."""
    count = result.plan.ticks + (1 if result.last else 0)
    return np.arange(result.first_tick, result.first_tick + count,
                     dtype=np.float64) * result.plan.dt_s


def _clock(result: SimResult) -> ByteRows:
    """Simulated time at every control tick, from 0 to the end of the run."""
    layout = cdr.Layout()
    layout.field("sec", "<i4")
    layout.field("nanosec", "<u4")
    return cdr.serialize(layout, _tick_times(result), {})


def _robot_description(result: SimResult) -> ByteRows:
    """The URDF the run used, once at time 0 (transient local: late subscribers get it)."""
    layout = cdr.Layout()
    layout.string(result.body.robot.xml_text)
    return cdr.rows(layout.records(len(_once(result))))


def _imu(result: SimResult) -> ByteRows:
    imu = result.imu
    assert imu is not None
    layout = cdr.Layout()
    layout.header(imu.spec.frame or result.body.root_link)
    for name, count in (("orientation", 4), ("orientation_covariance", 9),
                        ("angular_velocity", 3), ("angular_velocity_covariance", 9),
                        ("linear_acceleration", 3), ("linear_acceleration_covariance", 9)):
        layout.field(name, "<f8", count)
    variance = imu.spec.orientation_variance
    return cdr.serialize(layout, imu.times_s, {
        **({"orientation_covariance": np.diag([variance] * 3).ravel()} if variance else {}),
        "orientation": imu.orientation_xyzw,
        "angular_velocity": imu.angular_velocity_rad_s,
        "angular_velocity_covariance": np.diag(imu.angular_velocity_variance).ravel(),
        "linear_acceleration": imu.linear_acceleration_m_s2,
        "linear_acceleration_covariance": np.diag(imu.linear_acceleration_variance).ravel()})


def _odometry(result: SimResult, frames: tuple[str, str] | None = None) -> ByteRows:
    odom = result.odometry
    parent, child = frames or (ODOM_FRAME, result.body.root_link)
    layout = cdr.Layout()
    layout.header(parent)
    layout.string(child)
    for name, count in (("position", 3), ("orientation", 4), ("pose_covariance", 36),
                        ("linear", 3), ("angular", 3), ("twist_covariance", 36)):
        layout.field(name, "<f8", count)
    zeros = np.zeros_like(odom.x_m)
    lateral = zeros if odom.lateral_m_s is None else odom.lateral_m_s
    controller = result.scenario.controller  # the diagonals diff_drive_controller publishes
    return cdr.serialize(layout, odom.times_s, {
        "pose_covariance": np.diag(controller.pose_covariance_diagonal).ravel(),
        "twist_covariance": np.diag(controller.twist_covariance_diagonal).ravel(),
        "position": np.column_stack((odom.x_m, odom.y_m, zeros + odom.z_m)),
        "orientation": rotations.yaw(odom.yaw_rad),
        "linear": np.column_stack((odom.linear_m_s, lateral, zeros)),
        "angular": np.column_stack((zeros, zeros, odom.angular_rad_s))})


def _joint_states(result: SimResult) -> ByteRows:
    joints = result.joints
    layout = cdr.Layout()
    layout.header("")
    layout.strings(joints.names)
    layout.sequence("position", "<f8", len(joints.names))
    layout.sequence("velocity", "<f8", len(joints.names))
    layout.sequence("effort", "<f8", 0)
    return cdr.serialize(layout, joints.times_s,
                      {"position": joints.positions, "velocity": joints.velocities})
