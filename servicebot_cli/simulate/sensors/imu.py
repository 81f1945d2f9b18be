r"""The IMU: angular velocity, specific force and orientation at the sensor, with Gazebo noise.

For a base moving on the floor at forward speed :math:`v`, yaw rate :math:`\omega`, and their
rates :math:`\dot v`, :math:`\dot\omega`, a point at :math:`r = (r_x, r_y)` on the base
accelerates, in the base frame, by

.. math:: a_x = \dot v - \omega^2 r_x - \dot\omega r_y, \quad
          a_y = v\omega + \dot\omega r_x - \omega^2 r_y

and an accelerometer reads :math:`a + (0, 0, g)` (specific force: +g upward at rest).
Rates of change are taken per control tick, where the commands change. The orientation is
the sensor frame's in the world, as Gazebo reports it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.sensors import ImuSpec, NoiseSpec
from servicebot_cli.kinematics.rotations import quaternion_from_matrix
from servicebot_cli.simulate.bag import quaternions as rotations
from servicebot_cli.simulate.sensors import noise
from servicebot_cli.simulate.world.motion import Path2D, pose_at

FloatArray = npt.NDArray[np.float64]
GRAVITY_M_S2 = 9.8  # Gazebo's default world


@dataclass(frozen=True)
class ImuSamples:
    """Imu messages and the per-axis noise variances they report.

    Quaternions (N, 4) xyzw, angular velocity (N, 3) [rad/s], linear acceleration (N, 3)
    [m/s^2].
    """

    spec: ImuSpec
    times_s: FloatArray
    orientation_xyzw: FloatArray
    angular_velocity_rad_s: FloatArray
    linear_acceleration_m_s2: FloatArray
    angular_velocity_variance: tuple[float, float, float]
    linear_acceleration_variance: tuple[float, float, float]


def axis_noises(spec: ImuSpec, rng: np.random.Generator, count: int) -> list[noise.Noise]:
    """The noise of each axis for a run of ``count`` samples, in the order of ``measure``.

    Angular velocity then linear acceleration, axis by axis, each drawn for the whole run
    before the next (so a run gives the same numbers in pieces).
    """
    specs = [axis_spec for axis in range(3) for axis_spec in (
        spec.angular_velocity_noise[axis], spec.linear_acceleration_noise[axis])]
    return noise.one_after_another(specs, rng, count)


def measure(spec: ImuSpec, transform_sensor_to_base: FloatArray, path: Path2D,
            times_s: FloatArray, noises: list[noise.Noise],
            before: tuple[float, float] = (0.0, 0.0)) -> ImuSamples:
    """IMU samples at ``times_s`` along ``path``, with ``noises`` (from :func:`axis_noises`).

    ``before`` is the twist (v [m/s], omega [rad/s]) of the tick before ``path``'s first.
    """
    k = path.tick_index(times_s)
    v, w = path.linear_m_s[k], path.angular_rad_s[k]
    previous_v = np.concatenate(([before[0]], path.linear_m_s[:-1]))[k]
    previous_w = np.concatenate(([before[1]], path.angular_rad_s[:-1]))[k]
    dv, dw = (v - previous_v) / path.dt_s, (w - previous_w) / path.dt_s
    rx, ry = transform_sensor_to_base[0, 3], transform_sensor_to_base[1, 3]
    accel_base = np.column_stack((dv - w * w * rx - dw * ry, v * w + dw * rx - w * w * ry,
                                  np.full_like(v, GRAVITY_M_S2)))
    rate_base = np.column_stack((np.zeros_like(w), np.zeros_like(w), w))
    to_sensor = transform_sensor_to_base[:3, :3]  # rows: sensor axes in the base frame
    accel = accel_base @ to_sensor
    rate = rate_base @ to_sensor
    for axis in range(3):
        rate[:, axis] = noises[2 * axis].add(rate[:, axis])
        accel[:, axis] = noises[2 * axis + 1].add(accel[:, axis])
    _, _, yaw = pose_at(path, times_s)
    orientation = rotations.multiply(rotations.yaw(yaw), quaternion_from_matrix(to_sensor))
    return ImuSamples(
        spec, times_s, orientation, rate, accel,
        _variances(spec.angular_velocity_noise), _variances(spec.linear_acceleration_noise),
    )


def _variances(axes: tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None]
               ) -> tuple[float, float, float]:
    """The covariance diagonal a message reports for per-axis noise [unit^2]."""
    x, y, z = axes
    return noise.variance(x), noise.variance(y), noise.variance(z)
