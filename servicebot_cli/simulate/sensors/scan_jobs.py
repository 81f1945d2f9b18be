"""A ray sensor's scans of a piece as a job: what they depend on, the caster keeping the noise.

A piece's scans depend only on its poses (the base's path, the arm at each scan) and on the
range noise's generator, which carries on from piece to piece. :class:`ScanCaster` holds
one ray sensor's generator (a LIDAR's, a sonar's, a cliff sensor's) and everything fixed for
the run, so that it can cast the pieces' scans in another process
(:mod:`servicebot_cli.simulate.pose_work`); cast in order, in whichever process, they give
the same bits.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.sensors import LidarSpec
from servicebot_cli.simulate.body import Mounted
from servicebot_cli.simulate.sensors import lidar
from servicebot_cli.simulate.sensors.noise import Noise
from servicebot_cli.simulate.shape import RobotShape
from servicebot_cli.simulate.world.motion import Path2D
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class ScanJob:
    """The scans of one piece: at ``times_s`` along ``truth``.

    ``arm_q_rad`` (scans, J) and ``parts_to_base`` (scans, S, 4, 4) are the arm and the
    robot's parts at the tick boundary at or before each scan.
    """

    truth: Path2D
    times_s: FloatArray
    arm_q_rad: FloatArray
    parts_to_base: FloatArray


class ScanCaster:
    """Casts each piece's :class:`ScanJob`, in order: the range noise continues across them."""

    def __init__(self, mounted: Mounted[LidarSpec], shape: RobotShape, base_height_m: float,
                 solids: Sequence[Solid], meshes: Sequence[Mesh], noise_m: Noise,
                 period_s: float) -> None:
        self.mounted, self.shape, self.base_height_m = mounted, shape, base_height_m
        self.solids, self.meshes, self.noise_m, self.period_s = solids, meshes, noise_m, period_s
        self.rays = lidar.ray_directions(mounted.spec, mounted.transform_sensor_to_base)
        self.fixed_m: FloatArray | None = None  # the parts fixed on the base: cast once

    def __call__(self, job: ScanJob) -> lidar.Scans:
        """The job's scans: the world and the robot's own links (the arm where it is)."""
        spec, mount = self.mounted.spec, self.mounted.transform_sensor_to_base
        if self.fixed_m is None:
            self.fixed_m = lidar.fixed_ranges(self.shape, self.mounted.link, mount, self.rays)
        own = lidar.own_ranges(self.shape, self.mounted.link, mount, self.rays, job.arm_q_rad,
                               job.parts_to_base, self.fixed_m)
        return lidar.scan(spec, mount, self.base_height_m, job.truth, job.times_s,
                          self.solids, self.meshes, self.noise_m, own_m=own,
                          period_s=self.period_s)
