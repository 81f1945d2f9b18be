"""The sensors table: type, link, rate, topics, range, resolution and noise.

The typed views come from :mod:`servicebot_cli.description.sensors`; this module only picks
the view that fits each sensor and names the ROS topics with their message types.
"""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.description.extensions import Sensor, param, params_all
from servicebot_cli.description.sensors import (
    CAMERA_TYPES,
    LIDAR_TYPES,
    CameraSpec,
    ImuSpec,
    LidarSpec,
    camera_spec,
    imu_spec,
    lidar_spec,
)


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


def _message(name: str) -> str:
    """``sensor_msgs/LaserScan`` in the ROS 2 spelling ``sensor_msgs/msg/LaserScan``."""
    package, _, rest = name.partition("/")
    return name if not rest or rest.startswith("msg/") else f"{package}/msg/{rest}"


def sensor_info(sensor: Sensor) -> SensorInfo:
    """The summary of ``sensor``."""
    plugin = sensor.plugins[0] if sensor.plugins else None
    base = {"name": sensor.name, "type": sensor.type, "link": sensor.reference,
            "update_rate_hz": sensor.update_rate_hz,
            "plugin": plugin.filename if plugin else None}
    if sensor.type in LIDAR_TYPES:
        spec = lidar_spec(sensor)
        output = param(plugin.params, "output_type") if plugin else None
        topics = (Topic(spec.topic, _message(output or "sensor_msgs/LaserScan")),)
        return SensorInfo(**base, kind="lidar", frame=spec.frame, lidar=spec,
                          topics=_present(topics))
    if sensor.type in CAMERA_TYPES:
        cam = camera_spec(sensor)
        topics = (Topic(cam.image_topic, "sensor_msgs/msg/Image"),
                  Topic(cam.info_topic, "sensor_msgs/msg/CameraInfo"))
        return SensorInfo(**base, kind="camera", frame=cam.frame, camera=cam,
                          topics=_present(topics))
    if sensor.type == "imu":
        imu = imu_spec(sensor)
        topics = (Topic(imu.topic, "sensor_msgs/msg/Imu"),)
        return SensorInfo(**base, kind="imu", frame=imu.frame, imu=imu, topics=_present(topics))
    return SensorInfo(**base, kind="other", frame=sensor.reference, topics=_other_topics(sensor))


def _present(topics: tuple[Topic, ...]) -> tuple[Topic, ...]:
    return tuple(t for t in topics if t.name)


def _other_topics(sensor: Sensor) -> tuple[Topic, ...]:
    """Topics of a sensor without a typed view: remapping targets, else ``<topic>``."""
    targets = [rule.partition(":=")[2].strip() for plugin in sensor.plugins
               for rule in params_all(plugin.params, "ros/remapping")]
    topic = param(sensor.params, "topic")
    names = [t for t in targets if t] or ([topic] if topic else [])
    return tuple(Topic(name, None) for name in names)


def sensors_info(sensors: tuple[Sensor, ...]) -> tuple[SensorInfo, ...]:
    """Every sensor, in document order."""
    return tuple(sensor_info(s) for s in sensors)
