"""A ray sensor's scans as the message its plugin names: LaserScan, PointCloud2, PointCloud, Range.

The ROS 2 ``gazebo_ros_ray_sensor`` converts each Gazebo scan (``gazebo_ros/conversions/
sensor_msgs.hpp``), stamped in the plugin's frame:

- *LaserScan*: one ring of ranges; with several vertical rings, the middle one (ring
  ``rings // 2``; ROS 1's laser plugins: every ring, :func:`laser_scan`). Its other
  fields are those servicebot has always written (``scan_time`` the scan period, no
  intensities).
- *PointCloud2*: every ring's rays with a finite range, in order, as points in the sensor
  frame, ``x = r cos(i) cos(a)``, ``y = r cos(i) sin(a)``, ``z = r sin(i)`` (azimuth ``a``
  from the horizontal ``min_angle``, inclination ``i`` from the vertical one), with fields
  ``x``, ``y``, ``z`` and ``intensity``, float32, 16 bytes a point; height 1, dense.
- *PointCloud2* of velodyne_simulator's plugin: the points column after column, with a
  ``ring`` and a ``time`` field (:func:`velodyne_cloud`).
- *PointCloud*: the same points, and one ``intensity`` channel.
- *Range*: the least range over every ray (float32's largest when none is less), the field
  of view the larger of the horizontal and vertical spans, and ``<radiation_type>``.

A kinematic world has no laser retro-reflectors: every ray's intensity is 0, raised to
``<min_intensity>`` as the plugin does. A cloud's size follows its points, so its messages
are grouped by size (:class:`~.byte_rows.Payloads`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.ray_output import LASER_SCAN, POINT_CLOUD, POINT_CLOUD2, RANGE
from servicebot_cli.description.sensors import LidarSpec
from servicebot_cli.simulate.bag import cdr
from servicebot_cli.simulate.bag.byte_rows import ByteRows, Payloads, SizeGroups
from servicebot_cli.simulate.sensors.lidar import Scans, vertical_angles

FloatArray = npt.NDArray[np.float64]
Serializer = Callable[[Scans, str], ByteRows | Payloads]
"""A ray sensor's scans of a piece and its frame to their messages' payloads."""
Fill = Callable[[npt.NDArray[np.bool_], int], Mapping[str, npt.NDArray[Any] | float]]
"""The fields of the messages of the scans a mask selects, each with this many points."""
FLOAT32, FLOAT32_MAX, UINT16 = 7, float(np.finfo(np.float32).max), 4
CLOUD_FIELDS = ("x", "y", "z", "intensity")
POINT_BYTES = 4 * len(CLOUD_FIELDS)


def unpublished_note(spec: LidarSpec) -> str | None:
    """Why the run cannot write ``spec``'s messages, as a stderr note; None when it can.

    LaserScan from any plugin; the other types as the ROS 2 ray sensor plugin converts them.
    """
    output = spec.output
    if output is None or output.message == LASER_SCAN or output.ray_sensor or output.velodyne:
        return None
    return (f"note: /{(spec.topic or '').lstrip('/')} ({output.message}) is not published: "
            "the simulator writes that type only as gazebo_ros_ray_sensor converts a scan")


def serializer_for(spec: LidarSpec) -> tuple[str, Serializer]:
    """The message type of ``spec``'s scans and the function that serializes a piece's."""
    message = spec.output.message if spec.output else LASER_SCAN
    if spec.output is not None and spec.output.velodyne:
        return message, velodyne_cloud
    serializers: dict[str, Serializer] = {
        POINT_CLOUD2: point_cloud2, POINT_CLOUD: point_cloud, RANGE: range_message}
    return message, serializers.get(message, laser_scan)


def laser_scan(scans: Scans, frame: str) -> ByteRows:
    """LaserScan of the middle ring (the only one of a level scan), or of every ring.

    The angles are the sensor's ``<min_angle>`` and ``<max_angle>`` and the step between
    its rays, as Gazebo's ``RaySensor`` gives them: one ray (cast straight ahead) keeps the
    configured angles, and its step divides by zero.

    ROS 1's ``gazebo_ros_laser`` and ``gazebo_ros_gpu_laser`` copy all of Gazebo's ranges,
    ring after ring, and its intensities (0 here), with ``scan_time`` 0.
    """
    spec, rings = scans.spec, len(vertical_angles(scans.spec))
    rays = len(scans.angles_rad) // rings
    every = spec.output is not None and spec.output.every_ring
    start = 0 if every else (rings // 2) * rays
    ranges = scans.ranges_m if every else scans.ranges_m[:, start:start + rays]
    layout = cdr.Layout()
    layout.header(frame)
    for name in ("angle_min", "angle_max", "angle_increment", "time_increment", "scan_time",
                 "range_min", "range_max"):
        layout.field(name, "<f4")
    layout.sequence("ranges", "<f4", ranges.shape[1])
    layout.sequence("intensities", "<f4", ranges.shape[1] if every else 0)
    low, high = spec.min_angle_rad or 0.0, spec.max_angle_rad or 0.0
    with np.errstate(divide="ignore", invalid="ignore"):  # one ray: Gazebo's 0/0 or x/0
        step = np.float64(high - low) / (rays - 1)
    return cdr.serialize(layout, scans.times_s, {
        "angle_min": low, "angle_max": high,
        "angle_increment": step, "time_increment": 0.0,
        "scan_time": 0.0 if every else scans.period_s,
        "range_min": spec.min_range_m or 0.0, "range_max": spec.max_range_m or np.inf,
        "ranges": ranges.astype(np.float32)})


def range_message(scans: Scans, frame: str) -> ByteRows:
    """Range: the least range over all rays, as the plugin's conversion takes it."""
    spec = scans.spec
    horizontal = (spec.max_angle_rad or 0.0) - (spec.min_angle_rad or 0.0)
    vertical = (spec.vertical_max_angle_rad or 0.0) - (spec.vertical_min_angle_rad or 0.0)
    least = np.where(np.isnan(scans.ranges_m), np.inf, scans.ranges_m).min(axis=1, initial=np.inf)
    layout = cdr.Layout()
    layout.header(frame)
    layout.constant("<B", spec.output.radiation_type if spec.output else 1)
    layout.constant("<f", max(horizontal, vertical))
    layout.constant("<f", spec.min_range_m or 0.0)
    layout.constant("<f", spec.max_range_m if spec.max_range_m is not None else np.inf)
    layout.field("range", "<f4")
    return cdr.serialize(layout, scans.times_s, {"range": np.minimum(least, FLOAT32_MAX)})


def _points(scans: Scans) -> tuple[FloatArray, npt.NDArray[np.bool_]]:
    """Each ray's point in the sensor frame, (scans, rays, 3), and which ones are finite.

    The inclination is the ring's; a single ring's is the vertical ``min_angle`` (default 0),
    as the conversion takes it.
    """
    spec, r = scans.spec, scans.ranges_m
    azimuth = scans.angles_rad
    inclination = scans.inclinations_rad if scans.inclinations_rad is not None else \
        np.full_like(azimuth, spec.vertical_min_angle_rad or 0.0)
    flat = np.cos(inclination)
    points = np.stack((r * flat * np.cos(azimuth), r * flat * np.sin(azimuth),
                       r * np.sin(inclination)), axis=-1)
    return points, np.isfinite(r)


def _intensity(scans: Scans) -> float:
    """Every point's intensity: Gazebo's 0, floored at ``<min_intensity>``."""
    return max(0.0, scans.spec.output.min_intensity if scans.spec.output else 0.0)


def point_cloud2(scans: Scans, frame: str) -> Payloads:
    """PointCloud2 of every finite ray, x, y, z and intensity as float32."""
    points, finite = _points(scans)
    cloud = np.concatenate((points, np.full(points.shape[:2] + (1,), _intensity(scans))),
                           axis=-1).astype("<f4")
    fields = tuple((name, 4 * index, FLOAT32) for index, name in enumerate(CLOUD_FIELDS))
    return _by_size(scans.times_s, finite, _cloud2_layout(frame, fields, POINT_BYTES),
                    lambda keep, count: {
                        "data": cloud[keep].reshape(-1, len(CLOUD_FIELDS) * count).view(np.uint8)})


def _cloud2_layout(frame: str, fields: tuple[tuple[str, int, int], ...],
                   point_bytes: int) -> Callable[[int], cdr.Layout]:
    """The layout of a dense, one-row PointCloud2 of ``count`` points of ``fields``.

    Each field: its name, offset and PointField datatype, one value.
    """
    def layout(count: int) -> cdr.Layout:
        out = cdr.Layout()
        out.header(frame)
        out.constant("<I", 1)  # height: one unordered row
        out.constant("<I", count)  # width
        out.constant("<I", len(fields))
        for name, offset, kind in fields:
            out.string(name)
            out.constant("<I", offset)
            out.constant("<B", kind)
            out.constant("<I", 1)  # count
        out.constant("<B", 0)  # is_bigendian
        out.constant("<I", point_bytes)  # point_step
        out.constant("<I", point_bytes * count)  # row_step
        out.sequence("data", "u1", point_bytes * count)
        out.constant("<B", 1)  # is_dense
        return out

    return layout


def velodyne_cloud(scans: Scans, frame: str) -> Payloads:
    """PointCloud2 as velodyne_simulator's plugin publishes it.

    Column after column, each column's rings in order: ``x y z intensity`` float32,
    ``ring`` uint16, ``time`` float32 (0), 22 bytes a point; only rays within the range
    band (the spec's, already narrowed to the plugin's) and not below ``<min_intensity>``
    (every intensity here is 0).
    """
    points, finite = _points(scans)
    rings = len(vertical_angles(scans.spec))
    columns = points.shape[1] // rings
    points = points.reshape(len(points), rings, columns, 3).transpose(0, 2, 1, 3)
    kept = finite.reshape(len(finite), rings, columns).transpose(0, 2, 1).reshape(len(finite), -1)
    if scans.spec.output is not None and scans.spec.output.min_intensity > 0.0:
        kept = np.zeros_like(kept)
    record = np.dtype([("xyz", "<f4", 3), ("intensity", "<f4"), ("ring", "<u2"),
                       ("time", "<f4")])
    cloud = np.zeros(kept.shape, record)
    cloud["xyz"] = points.reshape(len(points), -1, 3)
    cloud["ring"] = np.tile(np.arange(rings, dtype=np.uint16), columns)
    fields = (("x", 0, FLOAT32), ("y", 4, FLOAT32), ("z", 8, FLOAT32),
              ("intensity", 12, FLOAT32), ("ring", 16, UINT16), ("time", 18, FLOAT32))
    return _by_size(scans.times_s, kept, _cloud2_layout(frame, fields, record.itemsize),
                    lambda keep, count: {
                        "data": cloud[keep].view(np.uint8).reshape(-1, record.itemsize * count)})


def point_cloud(scans: Scans, frame: str) -> Payloads:
    """PointCloud of every finite ray, and its ``intensity`` channel."""
    points, finite = _points(scans)

    def layout(count: int) -> cdr.Layout:
        out = cdr.Layout()
        out.header(frame)
        out.constant("<I", count)
        if count:
            out.field("points", "<f4", 3 * count)
        out.constant("<I", 1)  # one channel
        out.string("intensity")
        out.sequence("values", "<f4", count)
        return out

    return _by_size(scans.times_s, finite, layout, lambda keep, count: {
        "points": points[keep].reshape(-1, 3 * count), "values": _intensity(scans)})


def _by_size(times_s: FloatArray, finite: npt.NDArray[np.bool_],
             layout: Callable[[int], cdr.Layout], fill: Fill) -> Payloads:
    """Each scan's message, those of one point count serialized together.

    ``layout(count)`` is the layout of a message of ``count`` points, ``fill(keep, count)``
    its fields' values for the scans ``keep`` selects (rows of ``finite``).
    """
    groups = SizeGroups.of(finite.sum(axis=1))
    blocks = []
    for count, mine in zip(groups.sizes, groups.members, strict=True):
        keep = np.zeros_like(finite)
        keep[mine] = finite[mine]
        values = fill(keep, count) if count else {}
        blocks.append(cdr.serialize(layout(count), times_s[mine], values))
    return Payloads(blocks, groups.block, groups.row)
