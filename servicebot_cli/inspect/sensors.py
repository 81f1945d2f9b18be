"""The sensors table: type, link, rate, topics, range, resolution and noise.

The typed views come from :mod:`servicebot_cli.description.sensors`; this module only picks
the view that fits each sensor and names the ROS topics with their message types.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from servicebot_cli.description.extensions import Sensor, params_all
from servicebot_cli.description.sensors import (
    CAMERA_TYPES,
    LIDAR_TYPES,
    CameraSpec,
    ImuSpec,
    LidarSpec,
    camera_spec,
    gz_topic,
    imu_spec,
    lidar_spec,
    plugin_topic,
    ros_plugin,
    topic_origin,
)

GPU_LIDAR_TYPES = ("gpu_ray", "gpu_lidar")


@dataclass(frozen=True)
class Topic:
    """A ROS topic and its message type."""

    name: str
    message: str | None


@dataclass(frozen=True)
class SensorInfo:
    """One Gazebo sensor.

    Attributes:
        kind: ``lidar``, ``camera``, ``imu`` or ``other``; says which of the typed views is set.
        link: The link it is attached to.
        plugin: The ROS plugin's file (``libgazebo_ros_ray_sensor.so``), if any.
        frame: The frame its messages are stamped with.
        topics: What it publishes.
        topics_from: How the topic names were found (the ROS plugin, or gz-sim's ``<topic>``).
        carrier: The link Gazebo carries it on: ``link``, or the link a fixed joint lumps
            ``link`` into.
    """

    name: str
    type: str
    kind: str
    link: str | None
    update_rate_hz: float | None
    plugin: str | None
    frame: str | None
    topics: tuple[Topic, ...]
    lidar: LidarSpec | None = None
    camera: CameraSpec | None = None
    imu: ImuSpec | None = None
    topics_from: str | None = None
    carrier: str | None = None


def sensor_info(sensor: Sensor) -> SensorInfo:
    """The summary of ``sensor``."""
    plugin = ros_plugin(sensor)
    base = SensorInfo(sensor.name, sensor.type, "other", sensor.reference,
                      sensor.update_rate_hz, plugin.filename if plugin else None,
                      sensor.reference, (), topics_from=topic_origin(sensor),
                      carrier=sensor.carrier)
    if sensor.type in LIDAR_TYPES:
        spec = lidar_spec(sensor)
        # gz-sensors' GPU lidar also publishes its points beside the scan
        points = f"{spec.topic}/points" if gz_topic(sensor) and sensor.type in GPU_LIDAR_TYPES \
            else None
        topics = _present((spec.topic, spec.output.message if spec.output else ""),
                          (points, "sensor_msgs/msg/PointCloud2"))
        return replace(base, kind="lidar", frame=spec.frame, lidar=spec, topics=topics)
    if sensor.type in CAMERA_TYPES:
        cam = camera_spec(sensor)
        # a gz depth camera's image is its depth image, on the image's topic
        image, *depth = ((cam.image_topic, "sensor_msgs/msg/Image"), *cam.depth_topics) \
            if cam.colour else cam.depth_topics
        topics = _present(image, (cam.info_topic, "sensor_msgs/msg/CameraInfo"), *depth)
        return replace(base, kind="camera", frame=cam.frame, camera=cam, topics=topics,
                       update_rate_hz=cam.update_rate_hz)  # a ROS 1 plugin's throttle
    if sensor.type == "imu":
        imu = imu_spec(sensor)
        topics = _present((imu.topic, "sensor_msgs/msg/Imu"))
        return replace(base, kind="imu", frame=imu.frame, imu=imu, topics=topics)
    return replace(base, topics=_other_topics(sensor))


def _present(*topics: tuple[str | None, str]) -> tuple[Topic, ...]:
    """The topics that have a name."""
    return tuple(Topic(name, message) for name, message in topics if name)


_KNOWN_PLUGINS = {  # gazebo_plugins' gazebo_ros_bumper.cpp: ROS 2 and ROS 1 alike
    "libgazebo_ros_bumper.so": ("bumper_states", "bumperTopicName",
                                "gazebo_msgs/msg/ContactsState"),
}
"""Gazebo ROS sensor plugins without a typed view: the topic each publishes on (ROS 2's
name, ROS 1's tag for it) and its message type."""


def _other_topics(sensor: Sensor) -> tuple[Topic, ...]:
    """Topics of a sensor without a typed view: a known plugin's, or remapping targets."""
    known = [(plugin, _KNOWN_PLUGINS[plugin.filename]) for plugin in sensor.plugins
             if plugin.filename in _KNOWN_PLUGINS]
    if known:
        return tuple(Topic(plugin_topic(plugin, default, ros1), message)
                     for plugin, (default, ros1, message) in known)
    targets = [rule.partition(":=")[2].strip() for plugin in sensor.plugins
               for rule in params_all(plugin.params, "ros/remapping")]
    topic = gz_topic(sensor)
    names = [t for t in targets if t] or ([topic] if topic else [])
    return tuple(Topic(name, None) for name in names)


def sensors_info(sensors: tuple[Sensor, ...]) -> tuple[SensorInfo, ...]:
    """Every sensor, in document order."""
    return tuple(sensor_info(s) for s in sensors)
