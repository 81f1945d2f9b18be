"""A run's streams as serialized ROS 2 messages on the robot's topics.

Topics follow the robot's documentation: the sensors' topics as their Gazebo plugins resolve
them (``scan``, ``imu/data``, ``pi_camera/camera_info``), ``/diff_controller/odom`` and
``/tf`` (odom -> base) as diff_drive_controller publishes them, ``/joint_states`` as
joint_state_broadcaster, ``/tf`` for movable joints, ``/tf_static`` for fixed ones and
``/robot_description`` (the URDF, once) as robot_state_publisher, and ``/clock`` at every
control tick as gazebo_ros publishes simulated time. Header stamps are simulated time; each
stream carries the QoS its publishers offer.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.rotations import quaternion_from_matrix
from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.bag import cdr, qos
from servicebot_cli.simulate.bag import quaternions as rotations
from servicebot_cli.simulate.simulator import SimResult

FloatArray = npt.NDArray[np.float64]
ODOM_TOPIC, TF_TOPIC, TF_STATIC_TOPIC = "/diff_controller/odom", "/tf", "/tf_static"
JOINT_STATES_TOPIC, ODOM_FRAME = "/joint_states", "odom"
CLOCK_TOPIC, DESCRIPTION_TOPIC = "/clock", "/robot_description"


@dataclass(frozen=True)
class Stream:
    """Messages of one topic: ROS type, stamps [ns], CDR payloads in time order, and QoS.

    ``offered_qos`` holds the profile each of the topic's publishers offers.
    """

    topic: str
    type: str
    stamps_ns: npt.NDArray[np.int64]
    payloads: list[bytes]
    offered_qos: tuple[qos.Qos, ...] = (qos.SYSTEM_DEFAULTS,)


def absolute(topic: str | None, fallback: str) -> str:
    """A topic name with its leading slash (``scan`` -> ``/scan``)."""
    name = topic or fallback
    return name if name.startswith("/") else f"/{name}"


def streams(result: SimResult) -> list[Stream]:
    """Every stream of ``result``, in a fixed order: latched topics and the clock first."""
    out = [_robot_description(result), _tf_static(result), _clock(result), _odometry(result),
           _tf(result), _joint_states(result)]
    if result.scans is not None:
        out.append(_scan(result))
    if result.imu is not None:
        out.append(_imu(result))
    if result.camera is not None:
        out.append(_camera_info(result))
    return out


def _stream(topic: str, kind: str, layout: cdr.Layout, times: FloatArray,
            fill: Mapping[str, FloatArray | float],
            offered: tuple[qos.Qos, ...] = (qos.SYSTEM_DEFAULTS,)) -> Stream:
    records = layout.records(len(times))
    cdr.set_stamps(records, times)
    for name, values in fill.items():
        records[name] = values
    return Stream(topic, kind, cdr.stamps_ns(times), cdr.split(records), offered)


def _clock(result: SimResult) -> Stream:
    """Simulated time at every control tick, from 0 to the end of the run."""
    layout = cdr.Layout()
    layout.field("sec", "<i4")
    layout.field("nanosec", "<u4")
    times = np.arange(len(result.truth.x_m), dtype=np.float64) * result.truth.dt_s
    return _stream(CLOCK_TOPIC, "rosgraph_msgs/msg/Clock", layout, times, {}, (qos.CLOCK,))


def _robot_description(result: SimResult) -> Stream:
    """The URDF the run used, once at time 0 (transient local: late subscribers get it)."""
    layout = cdr.Layout()
    layout.string(result.body.robot.xml_text)
    return Stream(DESCRIPTION_TOPIC, "std_msgs/msg/String", np.zeros(1, dtype=np.int64),
                  cdr.split(layout.records(1)), (qos.ROBOT_DESCRIPTION,))


def _scan(result: SimResult) -> Stream:
    scans = result.scans
    assert scans is not None
    spec, rays = scans.spec, len(scans.angles_rad)
    layout = cdr.Layout()
    layout.header(spec.frame or result.body.root_link)
    for name in ("angle_min", "angle_max", "angle_increment", "time_increment", "scan_time",
                 "range_min", "range_max"):
        layout.field(name, "<f4")
    layout.sequence("ranges", "<f4", rays)
    layout.sequence("intensities", "<f4", 0)
    step = (scans.angles_rad[-1] - scans.angles_rad[0]) / max(rays - 1, 1)
    period = float(np.diff(scans.times_s[:2])[0]) if len(scans.times_s) > 1 else 0.0
    return _stream(absolute(spec.topic, "scan"), "sensor_msgs/msg/LaserScan", layout,
                   scans.times_s, {
                       "angle_min": scans.angles_rad[0], "angle_max": scans.angles_rad[-1],
                       "angle_increment": step, "time_increment": 0.0, "scan_time": period,
                       "range_min": spec.min_range_m or 0.0,
                       "range_max": spec.max_range_m or np.inf,
                       "ranges": scans.ranges_m.astype(np.float32)}, (qos.SENSOR_DATA,))


def _imu(result: SimResult) -> Stream:
    imu = result.imu
    assert imu is not None
    layout = cdr.Layout()
    layout.header(imu.spec.frame or result.body.root_link)
    for name, count in (("orientation", 4), ("orientation_covariance", 9),
                        ("angular_velocity", 3), ("angular_velocity_covariance", 9),
                        ("linear_acceleration", 3), ("linear_acceleration_covariance", 9)):
        layout.field(name, "<f8", count)
    return _stream(absolute(imu.spec.topic, "imu"), "sensor_msgs/msg/Imu", layout, imu.times_s, {
        "orientation": imu.orientation_xyzw,
        "angular_velocity": imu.angular_velocity_rad_s,
        "angular_velocity_covariance": np.diag(imu.angular_velocity_variance).ravel(),
        "linear_acceleration": imu.linear_acceleration_m_s2,
        "linear_acceleration_covariance": np.diag(imu.linear_acceleration_variance).ravel()},
        (qos.SENSOR_DATA,))


def _odometry(result: SimResult) -> Stream:
    odom = result.odometry
    layout = cdr.Layout()
    layout.header(ODOM_FRAME)
    layout.string(result.body.root_link)
    for name, count in (("position", 3), ("orientation", 4), ("pose_covariance", 36),
                        ("linear", 3), ("angular", 3), ("twist_covariance", 36)):
        layout.field(name, "<f8", count)
    zeros = np.zeros_like(odom.x_m)
    controller = result.scenario.controller  # the diagonals diff_drive_controller publishes
    return _stream(ODOM_TOPIC, "nav_msgs/msg/Odometry", layout, odom.times_s, {
        "pose_covariance": np.diag(controller.pose_covariance_diagonal).ravel(),
        "twist_covariance": np.diag(controller.twist_covariance_diagonal).ravel(),
        "position": np.column_stack((odom.x_m, odom.y_m, zeros)),
        "orientation": rotations.yaw(odom.yaw_rad),
        "linear": np.column_stack((odom.linear_m_s, zeros, zeros)),
        "angular": np.column_stack((zeros, zeros, odom.angular_rad_s))})


def _joint_states(result: SimResult) -> Stream:
    joints = result.joints
    layout = cdr.Layout()
    layout.header("")
    layout.strings(joints.names)
    layout.sequence("position", "<f8", len(joints.names))
    layout.sequence("velocity", "<f8", len(joints.names))
    layout.sequence("effort", "<f8", 0)
    return _stream(JOINT_STATES_TOPIC, "sensor_msgs/msg/JointState", layout, joints.times_s,
                   {"position": joints.positions, "velocity": joints.velocities})


def _camera_info(result: SimResult) -> Stream:
    camera, spec = result.camera, result.body.camera
    assert camera is not None and spec is not None
    layout = cdr.Layout()
    layout.header(spec.spec.frame or result.body.root_link)
    layout.constant("<I", camera.height_px)
    layout.constant("<I", camera.width_px)
    layout.string(camera.distortion_model)
    layout.sequence("d", "<f8", len(camera.d))
    for name, count in (("k", 9), ("r", 9), ("p", 12)):
        layout.field(name, "<f8", count)
    for _ in range(6):  # binning_x, binning_y, roi x_offset, y_offset, height, width
        layout.constant("<I", 0)
    layout.constant("<B", 0)  # roi.do_rectify
    topic = absolute(spec.spec.info_topic, "camera_info")
    return _stream(topic, "sensor_msgs/msg/CameraInfo", layout, result.camera_times_s, {
        "d": np.array(camera.d), "k": np.array(camera.k),
        "r": np.eye(3).ravel(), "p": np.array(camera.p)}, (qos.SENSOR_DATA,))


def _transforms(frames: list[tuple[str, str]]) -> cdr.Layout:
    layout = cdr.Layout()
    layout.constant("<I", len(frames))
    for i, (parent, child) in enumerate(frames):
        layout.field(f"sec{i}", "<i4")
        layout.field(f"nanosec{i}", "<u4")
        layout.string(parent)
        layout.string(child)
        layout.field(f"translation{i}", "<f8", 3)
        layout.field(f"rotation{i}", "<f8", 4)
    return layout


def _tf_stream(topic: str, frames: list[tuple[str, str]], times: FloatArray,
               translations: list[FloatArray], quaternions: list[FloatArray],
               offered: tuple[qos.Qos, ...]) -> Stream:
    layout = _transforms(frames)
    records = layout.records(len(times))
    stamps = cdr.stamps_ns(times)
    for i in range(len(frames)):
        records[f"sec{i}"] = stamps // 1_000_000_000
        records[f"nanosec{i}"] = stamps % 1_000_000_000
        records[f"translation{i}"] = translations[i]
        records[f"rotation{i}"] = quaternions[i]
    return Stream(topic, "tf2_msgs/msg/TFMessage", stamps, cdr.split(records), offered)


def _tf(result: SimResult) -> Stream:
    """The base in ``odom`` (drive controller) and movable joints (robot_state_publisher)."""
    odom, robot = result.odometry, result.body.robot
    zeros = np.zeros_like(odom.x_m)
    base = _tf_stream(TF_TOPIC, [(ODOM_FRAME, result.body.root_link)], odom.times_s,
                      [np.column_stack((odom.x_m, odom.y_m, zeros))], [rotations.yaw(odom.yaw_rad)],
                      (qos.SYSTEM_DEFAULTS,))
    joints = result.joints
    frames, translations, quaternions = [], [], []
    for i, name in enumerate(joints.names):
        joint = robot.joint(name)
        axis = np.array(joint.axis, float) / np.linalg.norm(joint.axis)
        fixed = quaternion_from_matrix(rpy_matrix(*joint.origin.rpy))
        q = joints.positions[:, i]
        offset = np.array(joint.origin.xyz)
        slide = q[:, None] * (rpy_matrix(*joint.origin.rpy) @ axis) if joint.type == "prismatic" \
            else np.zeros((len(q), 3))
        turn = rotations.about_axis(axis, q if joint.type != "prismatic" else np.zeros_like(q))
        frames.append((joint.parent or "", joint.child or ""))
        translations.append(offset + slide)
        quaternions.append(rotations.multiply(fixed, turn))
    moving = _tf_stream(TF_TOPIC, frames, joints.times_s, translations, quaternions,
                        (qos.DYNAMIC_TF,))
    # Two publishers (the drive controller and robot_state_publisher), one topic.
    order = np.argsort(np.concatenate((base.stamps_ns, moving.stamps_ns)), kind="stable")
    payloads = base.payloads + moving.payloads
    return Stream(TF_TOPIC, base.type,
                  np.concatenate((base.stamps_ns, moving.stamps_ns))[order],
                  [payloads[i] for i in order.tolist()], base.offered_qos + moving.offered_qos)


def _tf_static(result: SimResult) -> Stream:
    """Fixed joints, once at time 0, latched (robot_state_publisher)."""
    static = [(f.parent, f.name, f.origin) for f in result.body.robot.fixed_frames]
    return _tf_stream(TF_STATIC_TOPIC, [(p, c) for p, c, _ in static], np.zeros(1),
                      [np.array(o.xyz)[None] for _, _, o in static],
                      [quaternion_from_matrix(rpy_matrix(*o.rpy))[None] for _, _, o in static],
                      (qos.STATIC_TF,))
