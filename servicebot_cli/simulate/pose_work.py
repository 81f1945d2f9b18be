"""What a piece computes from its poses alone: ray sensors' scans, self contact, clearance.

Once a piece's ground truth is known (the base's path, the arm at each tick boundary),
these three depend on nothing else of it, and each carries its state from piece to piece
(each ray sensor's noise generator, the self-contact events under way, the clearance
record).
The parts are placed once per piece for all three.
:class:`PoseWork` holds that state and everything fixed for the run, so the pieces' jobs
can be done in another process (:mod:`servicebot_cli.common.forked`) while the simulator
goes on: done in order, in whichever process, they give the same bits.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.self_contact import SelfContact, SelfContactWatch
from servicebot_cli.simulate.sensors import lidar
from servicebot_cli.simulate.sensors.scan_jobs import ScanCaster, ScanJob
from servicebot_cli.simulate.shape import RobotShape
from servicebot_cli.simulate.shape_memo import TransformMemo
from servicebot_cli.simulate.world.clearance import Closest
from servicebot_cli.simulate.world.clearance_record import ClearanceRecord
from servicebot_cli.simulate.world.motion import Path2D

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class PoseJob:
    """A piece's poses: ``truth`` and ``arm_q_rad`` (n+1, J) at its tick boundaries.

    ``scan_times_s`` are the piece's scans, one array per ray sensor (none without).
    """

    first_tick: int
    truth: Path2D
    arm_q_rad: FloatArray
    scan_times_s: tuple[FloatArray, ...]


@dataclass(frozen=True, eq=False)
class FromPoses:
    """What a piece's poses give.

    Attributes:
        scans: The piece's scans, one per ray sensor (none without).
        self_contacts: The self contacts that began in the piece.
        closest: The clearance record over the piece and the pieces before it.
    """

    scans: tuple[lidar.Scans, ...]
    self_contacts: list[SelfContact]
    closest: Closest


class PoseWork:
    """Does each piece's :class:`PoseJob`, in order, carrying the state between them.

    Args:
        shape: The robot's parts and the joints that move them.
        casters: Each ray sensor's scans (none without).
        self_contacts: The arm's self-contact watch, None without an arm.
        clearance: The clearance record.
    """

    def __init__(self, shape: RobotShape, casters: tuple[ScanCaster, ...],
                 self_contacts: SelfContactWatch | None, clearance: ClearanceRecord) -> None:
        self.shape, self.casters, self.self_contacts = shape, casters, self_contacts
        self.clearance = clearance
        self.transforms = TransformMemo(shape)

    def prepare(self) -> None:
        """Make the Coal objects the clearance will measure with, before the first job."""
        tester = self.clearance.tester
        if tester.world:
            for obstacle in tester.world:
                _ = obstacle.geometry, obstacle.transform
            _ = tester.geometries

    def __call__(self, job: PoseJob) -> FromPoses:
        """The piece's scans, its self contacts and the clearance record.

        The parts are placed at each of the piece's arm configurations once (a
        configuration held for ticks once), with the bits
        :meth:`~servicebot_cli.simulate.shape.RobotShape.transforms_to_base` gives it.
        """
        self.transforms.clear()
        parts = self.transforms(job.arm_q_rad)  # (n+1, S, 4, 4) at the tick boundaries
        jobs: dict[bytes, ScanJob] = {}  # sensors at one rate share their job
        scans = tuple(caster(jobs.get(times_s.tobytes()) or jobs.setdefault(
                          times_s.tobytes(), _scan_job(job, times_s, parts)))
                      for caster, times_s in zip(self.casters, job.scan_times_s, strict=True))
        contacts = self.self_contacts.advance(job.first_tick, job.arm_q_rad, parts) \
            if self.self_contacts else []
        return FromPoses(scans, contacts, self.clearance.advance(job.first_tick, job.truth,
                                                                 job.arm_q_rad, parts))


def _scan_job(job: PoseJob, times_s: FloatArray, parts: FloatArray) -> ScanJob:
    """The scans at ``times_s`` of ``job``'s piece, the robot as at each one's tick start.

    ``parts`` (n+1, S, 4, 4) are the robot's parts at the piece's tick boundaries.
    """
    boundary = job.truth.tick_index(times_s, boundaries=True)  # the scan's tick's start
    return ScanJob(job.truth, times_s, job.arm_q_rad[boundary], parts[boundary])
