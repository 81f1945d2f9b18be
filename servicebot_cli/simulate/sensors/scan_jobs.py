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
                 period_s: float, fixed_m: FloatArray | None = None) -> None:
        self.mounted, self.shape, self.base_height_m = mounted, shape, base_height_m
        self.solids, self.meshes, self.noise_m, self.period_s = solids, meshes, noise_m, period_s
        self.rays = lidar.ray_directions(mounted.spec, mounted.transform_sensor_to_base)
        self.fixed_m = fixed_m  # the parts fixed on the base: cast once (None: not yet)

    def __call__(self, job: ScanJob) -> lidar.Scans:
        """The job's scans: the world and the robot's own links (the arm where it is)."""
        spec, mount = self.mounted.spec, self.mounted.transform_sensor_to_base
        start_m = lidar.ray_start_m(spec)
        if self.fixed_m is None:
            self.fixed_m = lidar.fixed_ranges(self.shape, self.mounted.link, mount, self.rays,
                                              start_m)
        own = lidar.own_ranges(self.shape, self.mounted.link, mount, self.rays, job.arm_q_rad,
                               job.parts_to_base, self.fixed_m, start_m)
        return lidar.scan(spec, mount, self.base_height_m, job.truth, job.times_s,
                          self.solids, self.meshes, self.noise_m, own_m=own,
                          period_s=self.period_s)


def fixed_ranges_of(mounted: Sequence[Mounted[LidarSpec]],
                    shape: RobotShape) -> list[FloatArray | None]:
    """Each ray sensor's :func:`~.lidar.fixed_ranges`, those on links without parts together.

    A TurtleBot 4's eleven IR and cliff sensors sit on links with no collision shape: their
    rays are cast against the base's fixed parts in one call. A sensor alone in its group
    (the LIDAR of most robots) gets None: its caster casts them on its first job, as ever.
    """
    holding = {p.link for p in shape.parts}
    bare = [i for i, m in enumerate(mounted) if m.link not in holding]
    out: list[FloatArray | None] = [None] * len(mounted)
    if len(bare) < 2:
        return out
    rays = [lidar.ray_directions(mounted[i].spec, mounted[i].transform_sensor_to_base)
            for i in bare]
    origins = [np.broadcast_to(mounted[i].transform_sensor_to_base[:3, 3], r.shape)
               for i, r in zip(bare, rays, strict=True)]
    starts = [np.full(len(r), lidar.ray_start_m(mounted[i].spec))
              for i, r in zip(bare, rays, strict=True)]
    together = lidar.fixed_ranges_from(shape, "", np.concatenate(origins), np.concatenate(rays),
                                       np.concatenate(starts))
    for i, part in zip(bare, np.split(together, np.cumsum([len(r) for r in rays])[:-1]),
                       strict=True):
        out[i] = part
    return out
