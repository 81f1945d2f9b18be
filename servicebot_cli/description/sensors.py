"""Typed views of Gazebo sensors: LIDAR, IMU and camera, and the ROS topics they publish.

Reads both Gazebo Classic (``<ray>``, ``libgazebo_ros_*`` plugins, ``<ros><remapping>``)
and gz-sim (``<lidar>``, ``<topic>``) spellings. Missing values are None, never guessed,
so ``check`` can tell absent from wrong and the simulator can apply Gazebo's defaults.

A sensor's topics come from its Gazebo ROS plugin when it has one (a plugin whose file or
parameters are ROS's: ``libgazebo_ros_ray_sensor.so``, ``<ros>``, ``<topicName>``); other
plugins inside a sensor (gz-sim systems, a placeholder) say nothing about topics. Without one,
a gz-sim sensor publishes on its ``<topic>`` made absolute (gz-transport puts a relative name
in the root namespace), and ros_gz_bridge gives the ROS topic the same name unless its
configuration renames it. A gz camera's info goes beside its image: ``<topic>``'s parent
``/camera_info`` (gz-sensors ``CameraSensor::AdvertiseInfo``), unless
``<camera><camera_info_topic>`` names it; its frame is ``<frame_id>``, ``<gz_frame_id>`` or
(Fortress) ``<ignition_frame_id>``.
"""

from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass

from servicebot_cli.description.elements import parse_float
from servicebot_cli.description.extensions import Params, Plugin, Sensor, param
from servicebot_cli.description.ray_output import (
    VELODYNE_PLUGINS,
    RayOutput,
    ray_output,
    velodyne_band,
)
from servicebot_cli.description.ros_names import PluginNode

LIDAR_TYPES = ("ray", "gpu_ray", "lidar", "gpu_lidar")
CAMERA_TYPES = ("camera", "depth", "depth_camera", "rgbd_camera", "wideanglecamera")


@dataclass(frozen=True)
class NoiseSpec:
    """Gazebo noise: gaussian with an optional bias drawn once per run.

    Units are those of the measured quantity ([m], [rad/s], [m/s^2]).
    """

    type: str
    mean: float
    stddev: float
    bias_mean: float = 0.0
    bias_stddev: float = 0.0


@dataclass(frozen=True)
class LidarSpec:
    """A scanning range sensor.

    Attributes:
        samples: Rays per horizontal scan.
        min_angle_rad, max_angle_rad: Scan span; the first and last rays sit on these angles.
        min_range_m, max_range_m: Valid range; returns outside it are reported as out of range.
        range_resolution_m: Quantisation of the ranges.
        update_rate_hz: Scans per second.
        vertical_samples, vertical_min_angle_rad, vertical_max_angle_rad: Rings of rays and
            their span in inclination (None where not written: one level ring).
        output: What its ROS plugin (or gz-sim's ``<topic>``) publishes
            (:mod:`.ray_output`); None when nothing does, and then ``topic`` is None too.
    """

    samples: int | None
    resolution: float | None
    min_angle_rad: float | None
    max_angle_rad: float | None
    min_range_m: float | None
    max_range_m: float | None
    range_resolution_m: float | None
    update_rate_hz: float | None
    noise: NoiseSpec | None
    frame: str | None
    topic: str | None
    vertical_samples: int | None = None
    vertical_min_angle_rad: float | None = None
    vertical_max_angle_rad: float | None = None
    output: RayOutput | None = None


@dataclass(frozen=True)
class ImuSpec:
    """An IMU; noise per axis x, y, z (None where the description gives none)."""

    update_rate_hz: float | None
    angular_velocity_noise: tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None]
    linear_acceleration_noise: tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None]
    frame: str | None
    topic: str | None
    orientation_variance: float = 0.0
    """The orientation covariance's diagonal [rad^2] (ROS 1 ``gazebo_ros_imu``'s noise)."""


@dataclass(frozen=True)
class CameraSpec:
    """A camera: image size [px], horizontal field of view [rad], clip planes [m]."""

    width_px: int | None
    height_px: int | None
    horizontal_fov_rad: float | None
    image_format: str | None
    near_clip_m: float | None
    far_clip_m: float | None
    update_rate_hz: float | None
    noise: NoiseSpec | None
    frame: str | None
    image_topic: str | None
    info_topic: str | None
    depth_topics: tuple[tuple[str, str], ...] = ()
    """What its plugin publishes of depth, each topic with its message type: gazebo_ros_camera
    on a ``depth`` sensor, gazebo_ros_openni_kinect and gazebo_ros_depth_camera (ROS 1);
    gz-sensors' depth and RGBD cameras (:func:`_gz_depth_topics`)."""
    colour: bool = True
    """Whether it publishes a colour image: a gz ``depth_camera`` publishes its depth image
    on ``image_topic`` instead."""
    centred: bool = False
    """Its camera_info puts the principal point at the image's centre, (w/2, h/2), as
    gz-sensors does (gz-rendering's projectionToCameraIntrinsic); gazebo_ros_camera writes
    ((w + 1)/2, (h + 1)/2)."""


_DEPTH_PLUGINS = ("libgazebo_ros_openni_kinect.so", "libgazebo_ros_depth_camera.so")
"""ROS 1 depth camera plugins (gazebo_ros_pkgs); ROS 2's gazebo_ros_camera on a depth sensor
publishes the same three."""
_DEPTH_OUTPUTS = (
    ("depth/image_raw", "depthImageTopicName", "sensor_msgs/msg/Image"),
    ("depth/camera_info", "depthImageCameraInfoTopicName", "sensor_msgs/msg/CameraInfo"),
    ("points", "pointCloudTopicName", "sensor_msgs/msg/PointCloud2"),
)
"""Each depth output: its name under the camera's, the ROS 1 tag naming it, its type."""


def _depth_topics(sensor: Sensor, plugin: Plugin, name: str) -> tuple[tuple[str, str], ...]:
    """The depth image, its camera_info and the point cloud a depth camera plugin adds."""
    ros2_depth = sensor.type == "depth" and plugin.filename == "libgazebo_ros_camera.so"
    if not ros2_depth and plugin.filename not in _DEPTH_PLUGINS:
        return ()
    return tuple((plugin_topic(plugin, f"{name}/{default}", ros1, name), message)
                 for default, ros1, message in _DEPTH_OUTPUTS)


def _float(params: Params, path: str) -> float | None:
    return parse_float(param(params, path))


def _int(params: Params, path: str) -> int | None:
    value = _float(params, path)
    return int(value) if value is not None and value == value and value.is_integer() else None


def _samples(params: Params, path: str) -> int | None:
    """A ray count as sdformat reads it (see :func:`sdf_unsigned`)."""
    return sdf_unsigned(param(params, path))


_LEADING_DIGITS = re.compile(r"[ \t\n\r\f\v]*\+?([0-9]+)")


def sdf_unsigned(text: str | None) -> int | None:
    """``text`` as sdformat reads an ``unsigned int`` (``std::stoul``): its leading digits.

    A xacro that computes a LIDAR's samples from its resolution writes ``666.518...``
    (PAL's pmb2 and TIAGo): Gazebo reads 666 and says nothing. None when ``text`` does not
    start with digits (sdformat refuses it).
    """
    match = None if text is None else _LEADING_DIGITS.match(text)
    return None if match is None else int(match[1])


def _noise(params: Params, prefix: str) -> NoiseSpec | None:
    kind = param(params, f"{prefix}/type") or param(params, f"{prefix}@type")
    if kind is None:
        return None
    return NoiseSpec(
        type=kind,
        mean=_float(params, f"{prefix}/mean") or 0.0,
        stddev=_float(params, f"{prefix}/stddev") or 0.0,
        bias_mean=_float(params, f"{prefix}/bias_mean") or 0.0,
        bias_stddev=_float(params, f"{prefix}/bias_stddev") or 0.0,
    )


_GAUSSIAN_NOISE_PLUGINS = frozenset(("libgazebo_ros_range.so", "libgazebo_ros_block_laser.so",
                                     "libgazebo_ros_imu_sensor.so"))
"""ROS 1 sensor plugins that read ``<gaussianNoise>`` (gazebo_ros_laser does not)."""


def _plus_plugin_noise(noise: NoiseSpec | None, plugin: Plugin | None) -> NoiseSpec | None:
    """``noise`` with a ROS 1 plugin's ``<gaussianNoise>`` added, or a Velodyne plugin's.

    gazebo_ros_range, gazebo_ros_block_laser and gazebo_ros_imu_sensor add N(0, that) to
    every reading, on top of the sensor's own noise: the two standard deviations add in
    quadrature. velodyne_simulator's plugins add their ``<gaussian_noise>`` (ROS 1's:
    ``<gaussianNoise>``) to every range they keep.
    """
    if plugin is None:
        return noise
    if plugin.filename in VELODYNE_PLUGINS:
        sigma = parse_float(param(plugin.params, "gaussian_noise")
                            or param(plugin.params, "gaussianNoise"))
    elif plugin.filename not in _GAUSSIAN_NOISE_PLUGINS or plugin.for_ros2:
        return noise  # ROS 2's read the SDF noise only
    else:
        sigma = parse_float(param(plugin.params, "gaussianNoise"))
    if sigma is None or not sigma > 0 or not math.isfinite(sigma):
        return noise
    if noise is None:
        return NoiseSpec("gaussian", 0.0, sigma)
    return dataclasses.replace(noise, stddev=math.hypot(noise.stddev, sigma))


_ROS1_KEYS = frozenset(("topicName", "frameName", "robotNamespace", "frame_name", "cameraName",
                        "camera_name", "imageTopicName", "cameraInfoTopicName", "output_type"))
_GZ_FRAME_KEYS = ("ignition_frame_id", "gz_frame_id", "frame_id")
"""gz-sensors' frame tags, weakest first: Fortress's, Garden's, SDF 1.10's ``<frame_id>``."""


ROS1_SENSOR_KEYS = frozenset(("frameName", "topicName", "robotNamespace", "bodyName",
                              "cameraName", "imageTopicName", "cameraInfoTopicName",
                              "gaussianNoise", "updateRateHZ"))
"""Parameters only gazebo_ros_pkgs' ROS 1 sensor plugins read (their names for the names
ROS 2's read otherwise)."""


_ROS1_NAMES = ROS1_SENSOR_KEYS | {"commandTopic", "odometryTopic"}
"""ROS 1 names read through :func:`ros1_param`: the sensor plugins', and the drives' topics."""


def ros1_param(plugin: Plugin, key: str) -> str | None:
    """``plugin``'s parameter ``key``, unless it is a ROS 1 name in a file for ROS 2.

    ROS 2's gazebo_plugins read none of ROS 1's names (``frameName``, ``cameraName``): in a
    file whose plugins are ROS 2's, the ROS 1 ones are left as Gazebo leaves them.
    """
    if plugin.ros2_file and key in _ROS1_NAMES:
        return None
    return param(plugin.params, key)


def is_ros_plugin(plugin: Plugin) -> bool:
    """Whether ``plugin`` is a Gazebo ROS wrapper: ``ros`` in its file name or ROS parameters."""
    words = set(re.split(r"[^a-z0-9]+", plugin.filename.lower()))
    return "ros" in words or any(key.startswith("ros/") or key in _ROS1_KEYS
                                 for key, _ in plugin.params)


def ros_plugin(sensor: Sensor) -> Plugin | None:
    """The sensor's Gazebo ROS plugin, the first of its plugins that is one; else None."""
    return next((p for p in sensor.plugins if is_ros_plugin(p)), None)



def gz_topic(sensor: Sensor) -> str | None:
    """The sensor's gz-transport ``<topic>``, absolute (``camera/image`` -> ``/camera/image``).

    None when the sensor has a ROS plugin (its topics are the plugin's) or no ``<topic>``.
    """
    text = (param(sensor.params, "topic") or "").strip()
    if not text or ros_plugin(sensor) is not None:
        return None
    return "/" + "/".join(part for part in text.split("/") if part)


def topic_origin(sensor: Sensor) -> str:
    """How the sensor's topic names were found, for a reader who must find them on a robot."""
    plugin = ros_plugin(sensor)
    if plugin is not None:
        return f"Gazebo ROS plugin {plugin.filename or plugin.name}"
    if gz_topic(sensor):
        return "gz <topic>, absolute; ros_gz_bridge keeps it"
    return "no ROS plugin, no <topic>"


def plugin_topic(plugin: Plugin, default: str, ros1: str = "topicName", within: str = "") -> str:
    """A Gazebo ROS plugin topic: remapped, then put in the plugin's namespace.

    A ROS 2 plugin's node resolves ``default`` as rcl does (:mod:`.ros_names`: its
    ``<ros><namespace>``, ``<ros><argument>`` and ``<ros><remapping>`` rules). A ROS 1 plugin
    (gazebo_ros_pkgs before ROS 2, as TurtleBot3's URDF still writes them) names its topic in
    ``ros1`` (``<topicName>``; under ``within``, a camera's name) and its namespace in
    ``<robotNamespace>``. The name has no leading ``/`` unless it, or the ``<ros><namespace>``
    it is put in, was written absolute (``/demo``: ``/demo/imu``).
    """
    node = PluginNode.of(plugin)
    topic = node.remapped(default)
    legacy = (ros1_param(plugin, ros1) or "").strip()
    if topic is None and legacy:
        topic = f"{within}/{legacy}" if within and not legacy.startswith("/") else legacy
        if topic.startswith("~/"):
            topic = f"{plugin.name}/{topic[2:]}"
        namespace = (param(plugin.params, "ros/namespace")
                     or ros1_param(plugin, "robotNamespace") or "").strip("/")
        full = f"{namespace}/{topic}" if namespace and not topic.startswith("/") else topic
        # roscpp cleans a name: '//' is one '/', a trailing '/' none (HSR's
        # '//hsrb/head_rgbd_sensor/...')
        return re.sub("/{2,}", "/", full).rstrip("/") or full
    written = default if topic is None else topic
    full = node.expand(written)
    # a topic under a namespace written absolute is absolute, as the model plugins' are
    rooted = (param(plugin.params, "ros/namespace") or "").strip().startswith("/")
    return full if written.startswith("/") or rooted else full[1:]


_SENSOR_FRAME_ID = frozenset(("libgazebo_ros_ray_sensor.so", "libgazebo_ros_camera.so",
                              "libgazebo_ros_imu_sensor.so", "libgazebo_ros_gps_sensor.so",
                              *VELODYNE_PLUGINS))
"""ROS 2 sensor plugins that stamp ``gazebo_ros::SensorFrameID`` (gazebo_plugins', and
velodyne_simulator's)."""
def _frame(sensor: Sensor) -> str | None:
    """The frame its messages are stamped with.

    gazebo_plugins' ROS 2 sensor plugins without ``<frame_name>`` stamp the link Gazebo
    carries the sensor on (``gazebo_ros::SensorFrameID``: the sensor's parent, after
    sdformat lumped fixed joints away), not the link the URDF names.
    """
    plugin = ros_plugin(sensor)
    named = next(filter(None, (ros1_param(plugin, key) for key in (
        "frame_name", "frameName", "frame_id"))), None) if plugin else None
    if named:
        return named
    if plugin is not None and plugin.filename in _SENSOR_FRAME_ID and (plugin.ros2_file or not any(
            key in ROS1_SENSOR_KEYS for key, _ in plugin.params)):
        return sensor.carrier
    gz_named = [param(sensor.params, key) for key in _GZ_FRAME_KEYS]
    return next((n for n in reversed(gz_named) if n), None) or sensor.reference


def lidar_spec(sensor: Sensor) -> LidarSpec:
    """The LIDAR view of a ``ray``/``gpu_ray``/``lidar``/``gpu_lidar`` sensor."""
    p = sensor.params
    root = "lidar" if any(k.startswith("lidar/") for k, _ in p) else "ray"
    plugin = ros_plugin(sensor)
    output = ray_output(plugin)
    topic = plugin_topic(plugin, "~/out") if plugin else gz_topic(sensor)
    near_m, far_m = _float(p, f"{root}/range/min"), _float(p, f"{root}/range/max")
    if plugin is not None and output is not None and output.velodyne:
        near_m, far_m = velodyne_band(plugin, near_m, far_m)
    return LidarSpec(
        samples=_samples(p, f"{root}/scan/horizontal/samples"),
        resolution=_float(p, f"{root}/scan/horizontal/resolution"),
        min_angle_rad=_float(p, f"{root}/scan/horizontal/min_angle"),
        max_angle_rad=_float(p, f"{root}/scan/horizontal/max_angle"),
        min_range_m=near_m,
        max_range_m=far_m,
        range_resolution_m=_float(p, f"{root}/range/resolution"),
        update_rate_hz=sensor.update_rate_hz,
        noise=_plus_plugin_noise(_noise(p, f"{root}/noise"), plugin),
        frame=_frame(sensor),
        topic=topic if output is not None else None,
        vertical_samples=_samples(p, f"{root}/scan/vertical/samples"),
        vertical_min_angle_rad=_float(p, f"{root}/scan/vertical/min_angle"),
        vertical_max_angle_rad=_float(p, f"{root}/scan/vertical/max_angle"),
        output=output if topic is not None else None,
    )


def imu_spec(sensor: Sensor) -> ImuSpec:
    """The IMU view of an ``imu`` sensor."""
    p = sensor.params

    plugin = ros_plugin(sensor)

    def axes(quantity: str) -> tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None]:
        x, y, z = (_plus_plugin_noise(_noise(p, f"imu/{quantity}/{axis}/noise"), plugin)
                   for axis in "xyz")
        return (x, y, z)

    return ImuSpec(
        update_rate_hz=sensor.update_rate_hz,
        angular_velocity_noise=axes("angular_velocity"),
        linear_acceleration_noise=axes("linear_acceleration"),
        frame=_frame(sensor),
        topic=plugin_topic(plugin, "~/out") if plugin else gz_topic(sensor),
    )


def camera_spec(sensor: Sensor) -> CameraSpec:
    """The camera view of a ``camera`` sensor."""
    p = sensor.params
    plugin = ros_plugin(sensor)
    image_topic, info_topic = _gz_camera_topics(sensor)
    depth = _gz_depth_topics(sensor)
    colour = not (depth and sensor.type in _GZ_DEPTH_ONLY)
    if plugin is not None:
        name = param(plugin.params, "camera_name") or sensor.name
        name = ros1_param(plugin, "cameraName") or name
        image_topic = plugin_topic(plugin, f"{name}/image_raw", "imageTopicName", name)
        info_topic = plugin_topic(plugin, f"{name}/camera_info", "cameraInfoTopicName", name)
        depth = _depth_topics(sensor, plugin, name)
    return CameraSpec(
        width_px=_int(p, "camera/image/width"),
        height_px=_int(p, "camera/image/height"),
        horizontal_fov_rad=_float(p, "camera/horizontal_fov"),
        image_format=param(p, "camera/image/format"),
        near_clip_m=_float(p, "camera/clip/near"),
        far_clip_m=_float(p, "camera/clip/far"),
        update_rate_hz=_throttled(sensor.update_rate_hz, plugin),
        noise=_noise(p, "camera/noise"),
        frame=(_optical_frame(sensor) if plugin is None else None) or _frame(sensor),
        image_topic=image_topic,
        info_topic=info_topic,
        depth_topics=depth,
        centred=plugin is None,
        colour=colour,
    )


def _throttled(rate_hz: float | None, plugin: Plugin | None) -> float | None:
    """A camera's rate under a ROS 1 plugin's ``<updateRate>``, which throttles it further.

    gazebo_ros_camera_utils (ROS 1) publishes a frame only once ``1/updateRate`` has passed
    since the last (a sensor without a rate updates every step); 0 or less throttles nothing.
    ROS 2's gazebo_ros_camera reads no ``<updateRate>``.
    """
    if plugin is None or plugin.for_ros2:
        return rate_hz
    throttle = parse_float(param(plugin.params, "updateRate"))
    if throttle is None or not throttle > 0 or not math.isfinite(throttle):
        return rate_hz
    return throttle if rate_hz is None or not rate_hz > 0 else min(rate_hz, throttle)


def _optical_frame(sensor: Sensor) -> str | None:
    """A gz camera's ``<optical_frame_id>``, its images' and camera_info's frame_id.

    gz-sensors' CameraSensor (Fortress on) stamps them so when it is given.
    """
    return (param(sensor.params, "camera/optical_frame_id") or "").strip() or None


_GZ_DEPTH_ONLY = ("depth_camera", "depth")
_GZ_RGBD = ("rgbd_camera", "rgbd")


def _gz_depth_topics(sensor: Sensor) -> tuple[tuple[str, str], ...]:
    """What a gz depth or RGBD camera publishes of depth (gz-sensors' DepthCameraSensor.cc,
    RgbdCameraSensor.cc): the depth image (32FC1) on ``TOPIC`` or ``TOPIC/depth_image``,
    and its points on ``TOPIC/points``; nothing for another camera, or one without a
    ``<topic>``.
    """  # noqa: D205
    topic = gz_topic(sensor)
    if topic is None or sensor.type not in (*_GZ_DEPTH_ONLY, *_GZ_RGBD):
        return ()
    image = topic if sensor.type in _GZ_DEPTH_ONLY else f"{topic}/depth_image"
    return ((image, "sensor_msgs/msg/Image"), (f"{topic}/points", "sensor_msgs/msg/PointCloud2"))


def _gz_camera_topics(sensor: Sensor) -> tuple[str | None, str | None]:
    """A gz camera's image and camera_info topics (None, None without a gz ``<topic>``).

    An ``rgbd_camera`` publishes ``TOPIC/image`` and ``TOPIC/camera_info``; the others their
    image on ``TOPIC`` and the info beside it, unless ``<camera_info_topic>`` names it.
    """
    topic = gz_topic(sensor)
    if topic is None:
        return None, None
    if sensor.type == "rgbd_camera":
        return f"{topic}/image", f"{topic}/camera_info"
    named = (param(sensor.params, "camera/camera_info_topic") or "").strip()
    parent = topic.rsplit("/", 1)[0]
    return topic, ("/" + named.lstrip("/") if named else f"{parent}/camera_info")
