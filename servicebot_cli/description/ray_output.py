"""What a ray sensor publishes on ROS: the message type its Gazebo ROS plugin names.

gazebo_ros_pkgs' ROS 2 ``gazebo_ros_ray_sensor`` (``gazebo_plugins/src/
gazebo_ros_ray_sensor.cpp``) publishes on ``~/out`` the ``<output_type>`` it is given:
``sensor_msgs/LaserScan``, ``sensor_msgs/PointCloud``, ``sensor_msgs/PointCloud2`` or
``sensor_msgs/Range``; without one, PointCloud2. Any other type, an empty
``<output_type/>`` too, is an error: the plugin publishes nothing. For Range,
``<radiation_type>`` is ``ultrasound`` or ``infrared`` (the default when absent); any other,
or an empty one, is an error too, and nothing is published. ``<min_intensity>`` (default 0)
floors the intensities of scans and clouds.

gazebo_ros_pkgs' ROS 1 plugins publish one type each: ``gazebo_ros_laser`` and
``gazebo_ros_gpu_laser`` LaserScan, ``gazebo_ros_block_laser`` PointCloud, ``gazebo_ros_range``
Range; the two laser plugins copy every vertical ring's ranges into their LaserScan.
velodyne_simulator's ``gazebo_ros_velodyne_laser`` (and its GPU twin) publish PointCloud2
with a ``ring`` and a ``time`` field (``GazeboRosVelodyneLaser.cpp``), keeping the points
strictly between ``max(<min_range>, ray min)`` and ``min(<max_range>, ray max)`` and not
below ``<min_intensity>`` (:func:`velodyne_band`). Another ROS plugin publishes its
``<output_type>`` when it names one, else LaserScan. gz-sim's lidars publish LaserScan on
their ``<topic>`` (ros_gz_bridge keeps the type).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from servicebot_cli.description.elements import parse_float
from servicebot_cli.description.extensions import Plugin, param

LASER_SCAN = "sensor_msgs/msg/LaserScan"
POINT_CLOUD = "sensor_msgs/msg/PointCloud"
POINT_CLOUD2 = "sensor_msgs/msg/PointCloud2"
RANGE = "sensor_msgs/msg/Range"
ULTRASOUND, INFRARED = 0, 1
"""``sensor_msgs/Range``'s ``radiation_type`` values."""

_ROS2_TYPES = {"sensor_msgs/LaserScan": LASER_SCAN, "sensor_msgs/PointCloud": POINT_CLOUD,
               "sensor_msgs/PointCloud2": POINT_CLOUD2, "sensor_msgs/Range": RANGE}
_ROS1_TYPES = (("gazebo_ros_block_laser", POINT_CLOUD), ("gazebo_ros_range", RANGE),
               ("gazebo_ros_laser", LASER_SCAN), ("gazebo_ros_gpu_laser", LASER_SCAN))
_ROS1_LASERS = ("gazebo_ros_laser", "gazebo_ros_gpu_laser")
_RADIATION = {"infrared": INFRARED, "ultrasound": ULTRASOUND}
VELODYNE_PLUGINS = ("libgazebo_ros_velodyne_laser.so", "libgazebo_ros_velodyne_gpu_laser.so")


@dataclass(frozen=True)
class RayOutput:
    """A ray sensor's ROS output.

    Attributes:
        message: Its type, ROS 2 spelling (``sensor_msgs/msg/PointCloud2``).
        ray_sensor: Whether the ROS 2 ``gazebo_ros_ray_sensor`` publishes it, converting the
            scan as its ``gazebo_ros/conversions/sensor_msgs.hpp`` does.
        radiation_type: Range's :data:`ULTRASOUND` or :data:`INFRARED`.
        min_intensity: The floor of the published intensities.
        every_ring: Whether a LaserScan holds every vertical ring's ranges, ring after ring
            (ROS 1 ``gazebo_ros_laser`` and ``gazebo_ros_gpu_laser`` copy the whole Gazebo
            scan), not only the middle ring (ROS 2's conversion, ros_gz_bridge).
        velodyne: Whether velodyne_simulator's plugin publishes it: a PointCloud2 of
            ``x y z intensity ring time``, column after column, and no point whose intensity
            is below ``min_intensity``.
    """

    message: str
    ray_sensor: bool = False
    radiation_type: int = INFRARED
    min_intensity: float = 0.0
    every_ring: bool = False
    velodyne: bool = False


def ray_output(plugin: Plugin | None) -> RayOutput | None:
    """What ``plugin`` (None: gz-sim's ``<topic>``) publishes; None when it publishes nothing."""
    if plugin is None:
        return RayOutput(LASER_SCAN)
    written = (param(plugin.params, "output_type") or "").strip()
    if plugin.filename in VELODYNE_PLUGINS:
        floor = parse_float(param(plugin.params, "min_intensity"))
        return RayOutput(POINT_CLOUD2, min_intensity=-math.inf if floor is None else floor,
                         velodyne=True)
    if "gazebo_ros_ray_sensor" not in plugin.filename:
        own = next((kind for name, kind in _ROS1_TYPES if name in plugin.filename), None)
        return RayOutput(own or _ros2_spelling(written or "sensor_msgs/LaserScan"),
                         every_ring=any(name in plugin.filename for name in _ROS1_LASERS))
    given, kind = (param(plugin.params, key) for key in ("output_type", "radiation_type"))
    message = POINT_CLOUD2 if given is None else _ROS2_TYPES.get(written)  # empty: invalid
    radiation = INFRARED if kind is None else _RADIATION.get(kind.strip())
    if message is None or (message == RANGE and radiation is None):
        return None
    floor = parse_float(param(plugin.params, "min_intensity"))
    return RayOutput(message, True, INFRARED if radiation is None else radiation,
                     0.0 if floor is None else floor)


def velodyne_band(plugin: Plugin, near_m: float | None, far_m: float | None
                  ) -> tuple[float | None, float | None]:
    """The ranges a Velodyne plugin keeps: its ``<min_range>``/``<max_range>`` within the ray's.

    The plugin's own default to 0 and infinity; a value written that is no number is 0, as
    sdformat's ``Get<double>`` leaves it (``<max_range>abc`` keeps no point).
    """
    low, high = (_sdf_double(param(plugin.params, key)) for key in ("min_range", "max_range"))
    if low is not None and math.isfinite(low):
        near_m = low if near_m is None else max(near_m, low)
    if high is not None and not math.isnan(high):
        far_m = high if far_m is None else min(far_m, high)
    return near_m, far_m


def _sdf_double(text: str | None) -> float | None:
    """A plugin's number as sdformat reads it: None where not written, 0 where no number."""
    if text is None:
        return None
    value = parse_float(text)
    return 0.0 if value is None or math.isnan(value) and "nan" not in text.lower() else value


def _ros2_spelling(name: str) -> str:
    """``sensor_msgs/LaserScan`` in the ROS 2 spelling ``sensor_msgs/msg/LaserScan``."""
    package, _, rest = name.partition("/")
    return name if not rest or rest.startswith("msg/") else f"{package}/msg/{rest}"
