"""``--log FILE.csv``: one row per telemetry reply, written atomically.

Rows stream into a temporary file beside FILE.csv, which replaces FILE.csv when the run
ends, however it ends (Ctrl-C, SIGTERM, a lost link): the record of a run that went wrong
is the one most worth keeping. A run that never got a reply leaves nothing behind.
"""

from __future__ import annotations

import contextlib
import csv
from collections.abc import Iterator
from pathlib import Path
from typing import IO

from servicebot_cli.common.files import atomic_output
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols.events import Reading


def header(motors: MotorMap, has_arm: bool) -> list[str]:
    """Column names; each carries its unit."""
    wheels = motors.wheel_joints
    columns = ["t_s", "ack", "faults"]
    columns += [f"{w}_cmd_rad_s" for w in wheels]
    columns += [f"{w}_pos_rad" for w in wheels]
    columns += [f"{w}_vel_rad_s" for w in wheels]
    if has_arm:
        columns += [f"{j}_pos_rad" for j in motors.arm_joints]
    return columns


class TelemetryCsv:
    """Writes telemetry rows to an open text file."""

    def __init__(self, handle: IO[str], motors: MotorMap, has_arm: bool) -> None:
        self._writer = csv.writer(handle, lineterminator="\n")
        self._writer.writerow(header(motors, has_arm))
        self._has_arm = has_arm
        self.rows = 0

    def row(self, t_s: float, reading: Reading, commanded_rad_s: tuple[float, ...]) -> None:
        """One row for ``reading``, received ``t_s`` after the start."""
        values = [f"{t_s:.4f}", "" if reading.ack is None else reading.ack,
                  "|".join(reading.faults)]
        values += [f"{v:.6g}" for v in commanded_rad_s]
        values += [f"{v:.6g}" for v in reading.wheel_position_rad]
        values += [f"{v:.6g}" for v in reading.wheel_velocity_rad_s]
        if self._has_arm:
            values += [f"{v:.6g}" for v in reading.arm_position_rad or ()]
        self._writer.writerow(values)
        self.rows += 1


class _Discard(Exception):
    """Leave nothing behind: the run never got a reply."""


@contextlib.contextmanager
def telemetry_csv(path: Path, motors: MotorMap, has_arm: bool) -> Iterator[TelemetryCsv]:
    """A CSV log at ``path``, kept on every exit once it holds a row, else not written.

    Raises:
        OutputError: The file cannot be written (missing directory, permission).
    """
    failure: BaseException | None = None
    try:
        with atomic_output(path) as handle:
            log = TelemetryCsv(handle, motors, has_arm)
            try:
                yield log
            except BaseException as exc:  # keep the rows: close the file, then re-raise
                failure = exc
            if not log.rows:
                raise _Discard
    except _Discard:
        pass
    if failure is not None:
        raise failure
