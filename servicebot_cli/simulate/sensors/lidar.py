"""The LIDAR: rays cast in 3D from the sensor's pose against the world, as Gazebo's ray sensor.

Rays leave the sensor frame at the scan angles (Gazebo spaces ``samples`` rays evenly from
``min_angle`` to ``max_angle``, both included; one ray goes straight ahead), in each ring of
``<vertical>`` samples (one level ring without), and are cast against the floor, every
obstacle and the robot's own links. Gazebo Classic's rays begin at ``min``
(``MultiRayShape``): the robot's own parts nearer than that (a bumper in front of an IR
sensor) are not seen; an obstacle nearer than that reads -inf. Returns at or
closer than ``min`` read -inf and those at or beyond ``max`` (or none) +inf, as REP 117 and
``sensor_msgs/LaserScan`` say; the others get the gaussian noise and are clamped into
``[min, max]``, as Gazebo Classic's ray sensors (``RaySensor.cc``, ``GpuRaySensor.cc``) and
gz-sensors' ``Lidar::ApplyNoise`` do. ``<range><resolution>`` is not applied: neither
quantises ranges (gz-sensors only reports ``RangeResolution()``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.sensors import LidarSpec
from servicebot_cli.simulate.sensors import noise
from servicebot_cli.simulate.shape import Part, RobotShape
from servicebot_cli.simulate.world import raycast
from servicebot_cli.simulate.world.motion import Path2D, pose_at
from servicebot_cli.simulate.world.robot_rays import cast_parts
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
RAYS_PER_BATCH = 32_768  # keeps each batch's temporaries in cache


@dataclass(frozen=True)
class Scans:
    """Scan data: ``ranges`` (scans, rays) [m] at ``times_s``, and sensor poses.

    A ray's azimuth is ``angles_rad`` and, with several rings, its inclination
    ``inclinations_rad`` (None: one level ring), both (rays,), ring after ring.
    """

    spec: LidarSpec
    times_s: FloatArray
    angles_rad: FloatArray
    ranges_m: FloatArray
    origin_m: FloatArray  # sensor position in the world per scan, (scans, 3)
    yaw_rad: FloatArray  # sensor heading in the world per scan
    period_s: float = 0.0  # between scans (0 for a run of one scan)
    inclinations_rad: FloatArray | None = None


MAX_RAYS = 1_000_000
"""The most rays a scan may cast (a 128-ring LIDAR of 2,048 columns casts 262,144)."""


def cast_problem(spec: LidarSpec) -> str | None:
    """Why the simulator cannot cast ``spec``'s rays; None when it can."""
    if not spec.samples or spec.samples < 1 or spec.min_angle_rad is None \
            or spec.max_angle_rad is None:
        return "it needs a whole <samples> of at least 1, <min_angle> and <max_angle>"
    rays = ray_count(spec)
    if rays > MAX_RAYS:
        return f"its {rays:,} rays a scan are more than the {MAX_RAYS:,} the simulator casts"
    angles = (spec.min_angle_rad, spec.max_angle_rad, spec.vertical_min_angle_rad or 0.0,
              spec.vertical_max_angle_rad or 0.0)
    if not all(math.isfinite(a) for a in angles):
        return "its <min_angle> and <max_angle> must be numbers"
    low, high = spec.min_range_m, spec.max_range_m
    if (low is not None and not math.isfinite(low)) or (high is not None and math.isnan(high)):
        return "its <range><min> must be a number, and its <max> a number or inf"
    noise = spec.noise
    if noise is not None and not all(math.isfinite(value) for value in (
            noise.mean, noise.stddev, noise.bias_mean, noise.bias_stddev)):
        return "its <noise> means and standard deviations must be numbers"
    return None


def ray_count(spec: LidarSpec) -> int:
    """Rays a scan casts: ``<samples>`` in each of its rings."""
    return (spec.samples or 0) * max(spec.vertical_samples or 1, 1)


def scan_angles(spec: LidarSpec) -> FloatArray:
    """Bearing of each ray in the sensor frame [rad].

    Raises:
        DescriptionError: :func:`cast_problem` has a problem with ``spec``.
    """
    problem = cast_problem(spec)
    if problem is not None:
        raise DescriptionError(f"the ray sensor on {spec.frame or 'its link'}: {problem}")
    # cast_problem found every one of them
    assert spec.samples and spec.min_angle_rad is not None and spec.max_angle_rad is not None
    if spec.samples == 1:  # Gazebo's MultiRayShape: one ray, straight ahead
        return np.zeros(1)
    return np.linspace(spec.min_angle_rad, spec.max_angle_rad, spec.samples)


def vertical_angles(spec: LidarSpec) -> FloatArray:
    """Each ring's inclination [rad]: ``<vertical>`` samples from min to max, else one, level.

    The rings are spaced as the scan's rays, both ends included (Gazebo's
    ``vertical_angle_step``, (max - min) / (samples - 1)).
    """
    count = spec.vertical_samples or 1
    if count <= 1:
        return np.zeros(1)
    return np.linspace(spec.vertical_min_angle_rad or 0.0, spec.vertical_max_angle_rad or 0.0,
                       count)


def ray_angles(spec: LidarSpec) -> tuple[FloatArray, FloatArray | None]:
    """Each ray's azimuth and inclination [rad], ring after ring as Gazebo orders its ranges.

    The inclination is None for one level ring (every ray's is 0).
    """
    azimuth, rings = scan_angles(spec), vertical_angles(spec)
    if len(rings) == 1:
        return azimuth, None
    return np.tile(azimuth, len(rings)), np.repeat(rings, len(azimuth))


def _local_directions(spec: LidarSpec) -> FloatArray:
    """Each ray's unit direction in the sensor frame, shape (3, R)."""
    azimuth, inclination = ray_angles(spec)
    if inclination is None:
        return np.vstack((np.cos(azimuth), np.sin(azimuth), np.zeros_like(azimuth)))
    flat = np.cos(inclination)
    return np.vstack((flat * np.cos(azimuth), flat * np.sin(azimuth), np.sin(inclination)))


def scan(spec: LidarSpec, transform_sensor_to_base: FloatArray, base_height_m: float,
         path: Path2D, times_s: FloatArray, solids: Sequence[Solid], meshes: Sequence[raycast.Mesh],
         noise_m: noise.Noise, own_m: FloatArray | None = None, period_s: float = 0.0) -> Scans:
    """The scans at ``times_s`` along ``path``; ``own_m`` (scans, rays) are ranges to the robot.

    ``noise_m`` is the range noise of the run (its bias drawn once).
    """
    angles, inclinations = ray_angles(spec)
    x, y, yaw = pose_at(path, times_s)
    local_dirs = transform_sensor_to_base[:3, :3] @ _local_directions(spec)  # (3, R), base
    offset = transform_sensor_to_base[:3, 3]
    c, s = np.cos(yaw), np.sin(yaw)
    origins = np.column_stack((x + c * offset[0] - s * offset[1],
                               y + s * offset[0] + c * offset[1],
                               np.full_like(x, base_height_m + offset[2])))
    true = np.empty((len(times_s), len(angles)))
    bearings = np.arctan2(local_dirs[1], local_dirs[0])  # of each ray on the base
    per_batch = max(1, RAYS_PER_BATCH // len(angles))
    for start in range(0, len(times_s), per_batch):
        stop = min(start + per_batch, len(times_s))
        cb, sb = c[start:stop, None], s[start:stop, None]
        dirs = np.stack((cb * local_dirs[0] - sb * local_dirs[1],
                         sb * local_dirs[0] + cb * local_dirs[1],
                         np.broadcast_to(local_dirs[2], cb.shape[:1] + local_dirs[2].shape)),
                        axis=-1).reshape(-1, 3)
        o = np.repeat(origins[start:stop], len(angles), axis=0)
        fans = raycast.Fans(yaw[start:stop], bearings)  # each scan's rays leave one point
        true[start:stop] = raycast.cast(o, dirs, solids, meshes=meshes,
                                        fans=fans).reshape(stop - start, -1)
        if own_m is not None:
            np.minimum(true[start:stop], own_m[start:stop], out=true[start:stop])
    sensor_yaw = yaw + np.arctan2(transform_sensor_to_base[1, 0], transform_sensor_to_base[0, 0])
    return Scans(spec, times_s, angles, readings(true, spec, noise_m), origins, sensor_yaw,
                 period_s, inclinations)


def ray_directions(spec: LidarSpec, transform_sensor_to_base: FloatArray) -> FloatArray:
    """Each ray's unit direction in the base frame, shape (R, 3)."""
    return np.asarray(_local_directions(spec).T @ transform_sensor_to_base[:3, :3].T,
                      dtype=np.float64)


def ray_start_m(spec: LidarSpec) -> float:
    """Where the rays begin, from the sensor [m]: at ``<range><min>``, as Gazebo's do."""
    return max(spec.min_range_m or 0.0, 0.0)


def fixed_ranges(shape: RobotShape, sensor_link: str, transform_sensor_to_base: FloatArray,
                 directions: FloatArray, start_m: float = 0.0) -> FloatArray:
    """Distance along each ray to the parts fixed on the base, shape (R,).

    The same for every scan: a run casts them once. The sensor's own link is left out; the
    rays begin ``start_m`` from the sensor (:func:`ray_start_m`).
    """
    origin = np.broadcast_to(transform_sensor_to_base[:3, 3], directions.shape)
    return fixed_ranges_from(shape, sensor_link, origin, directions,
                             np.full(len(directions), start_m))


def fixed_ranges_from(shape: RobotShape, sensor_link: str, origins_m: FloatArray,
                      directions: FloatArray, starts_m: FloatArray) -> FloatArray:
    """Distance along each ray to the parts fixed on the base, but ``sensor_link``'s, (R,).

    ``origins_m`` and ``directions`` (R, 3) are in the base frame: the rays of one sensor,
    or of several whose links hold no part (cast together, one call for them all). Each ray
    begins ``starts_m`` (R,) along its direction: nearer parts are not seen.
    """
    fixed = shape.fixed() & np.array([p.link != sensor_link for p in shape.parts], dtype=bool)
    if not fixed.any():
        return np.full(len(directions), np.inf)
    placed = shape.transforms_to_base(np.zeros((1, len(shape.joints))))
    ranges: FloatArray = _cast_beyond([p for p, f in zip(shape.parts, fixed, strict=True) if f],
                                      placed[:, fixed], origins_m, directions, starts_m)[0]
    return ranges


def _cast_beyond(parts: list[Part], placed: FloatArray, origins_m: FloatArray,
                 directions: FloatArray, starts_m: FloatArray | float) -> FloatArray:
    """:func:`cast_parts`, the rays beginning ``starts_m`` (R,) along their directions.

    A ray that meets nothing nearer than its start is the ray cast from the sensor (the same
    bits); one that does is cast again from its start, and that hit is its distance.
    """
    hits: FloatArray = cast_parts(parts, placed, origins_m, directions)
    starts = np.broadcast_to(np.asarray(starts_m, dtype=np.float64), (len(directions),))
    near = np.flatnonzero((hits < starts).any(axis=0))
    if len(near):
        origins = np.broadcast_to(origins_m, directions.shape)[near]
        begun = origins + starts[near, None] * directions[near]
        again = cast_parts(parts, placed, begun, directions[near]) + starts[near]
        hits[:, near] = np.where(hits[:, near] < starts[near], again, hits[:, near])
    return hits


def own_ranges(shape: RobotShape, sensor_link: str, transform_sensor_to_base: FloatArray,
               directions: FloatArray, q: FloatArray,
               parts_to_base: FloatArray | None = None,
               fixed_m: FloatArray | None = None, start_m: float = 0.0) -> FloatArray:
    """Distance along each ray to the robot's own links, per scan, shape (scans, R).

    The sensor's own link is left out (Gazebo's ray sensor ignores the link it is on), and
    the rays begin ``start_m`` from the sensor (:func:`ray_start_m`). Parts
    fixed on the base are cast once (``fixed_m``: :func:`fixed_ranges`, when the caller
    keeps it); the arm's once per distinct arm configuration, those of a batch of
    configurations whose sphere never reaches a level scan's plane not at all.

    Args:
        shape: The robot's parts.
        sensor_link: The link the sensor is on.
        transform_sensor_to_base: The sensor's pose on the base, (4, 4).
        directions: Ray directions in the base frame, shape (R, 3).
        q: The moving joints' positions at each scan, shape (scans, J).
        parts_to_base: ``shape.transforms_to_base(q)`` when the caller has it already.
        fixed_m: :func:`fixed_ranges` of these rays, when the caller has it already.
        start_m: Where the rays begin [m].
    """
    keep = np.array([p.link != sensor_link for p in shape.parts], dtype=bool)
    moving = ~shape.fixed() & keep
    origin = np.broadcast_to(transform_sensor_to_base[:3, 3], directions.shape)
    parts = shape.parts
    if fixed_m is None:
        fixed_m = fixed_ranges(shape, sensor_link, transform_sensor_to_base, directions,
                               start_m)
    out = np.empty((len(q), len(directions)))
    out[:] = fixed_m
    if moving.any() and len(q):
        distinct, first, index = np.unique(q, axis=0, return_index=True, return_inverse=True)
        moved = [p for p, m in zip(parts, moving, strict=True) if m]
        hits = np.full((len(distinct), len(directions)), np.inf)
        per_batch = max(1, raycast_batch() // max(1, len(directions) * len(moved)))
        for start in range(0, len(distinct), per_batch):
            placed = (parts_to_base[first[start:start + per_batch]] if parts_to_base is not None
                      else shape.transforms_to_base(distinct[start:start + per_batch]))[:, moving]
            seen = _may_be_seen(moved, placed, transform_sensor_to_base[:3, 3], directions)
            if seen.any():  # the parts no ray can reach are left out; a batch of none, too
                rows = slice(start, start + len(placed))
                hits[rows] = _cast_beyond([p for p, k in zip(moved, seen, strict=True) if k],
                                          placed[:, seen], origin, directions, start_m)
        np.minimum(out, hits[index.ravel()], out=out)
    return out


def _may_be_seen(parts: list[Part], placed: FloatArray, origin_m: FloatArray,
                 directions: FloatArray) -> npt.NDArray[np.bool_]:
    """Per part: may a ray meet its bounding sphere in one of the configurations ``placed``?

    Level rays stay in the sensor's horizontal plane: a sphere wholly above or below it
    (with a margin above the ray caster's own) is never met. Other rays: every part may be.
    """
    if not np.all(directions[:, 2] == 0.0):
        return np.ones(len(parts), dtype=bool)
    radius = np.array([p.radius_m for p in parts])
    height = np.abs(placed[:, :, 2, 3] - origin_m[2])  # (configurations, parts)
    return np.asarray((height <= radius * (1 + 1e-5) + 1e-6).any(axis=0))


def raycast_batch() -> int:
    """Rays cast per batch against the robot's parts."""
    return RAYS_PER_BATCH


def readings(true_m: FloatArray, spec: LidarSpec, noise_m: noise.Noise) -> FloatArray:
    """What the sensor reports for true ranges: +-inf outside ``(min, max)``, else noisy.

    A true range at or beyond ``max`` is +inf, at or within ``min`` -inf; any other gets the
    noise, then is clamped into ``[min, max]``. The noise is drawn for every ray, so the
    seeded stream does not depend on what the rays meet.
    """
    low = spec.min_range_m if spec.min_range_m is not None else 0.0
    high = spec.max_range_m if spec.max_range_m is not None else np.inf
    noisy = noise_m.add(true_m)
    with np.errstate(invalid="ignore"):
        values = np.clip(noisy, low, high)
    values = np.where(true_m >= high, np.inf, values)
    return np.where(true_m <= low, -np.inf, values)
