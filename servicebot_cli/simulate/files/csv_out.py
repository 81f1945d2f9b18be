"""One CSV file per stream, plus summary.json, in an output directory, written as the run goes.

Every file is written to a temporary first and renamed into place only once all are written,
so an error or a signal leaves no temporary file and no partial set of new files. Rows are
appended a piece of the run at a time. Numbers are written in the shortest form that reads
back to the same float, so files are exact and the same seed gives the same bytes. A run
that renders camera images also leaves its last frame as ``camera.png``.
"""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.files import OutputError, atomic_directory, atomic_output
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.simulate.bag.byte_rows import place_rows
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.files.png import png_bytes
from servicebot_cli.simulate.sensors.camera_image import Frame
from servicebot_cli.simulate.simulator import SimResult

if TYPE_CHECKING:
    from servicebot_cli.simulate.summary import Summary

Table = tuple[tuple[str, ...], str]
"""A CSV file's header fields and rows (text, one line each)."""


def _rows(columns: Sequence[npt.ArrayLike]) -> str:
    """CSV lines of the columns' numbers, each in numpy's shortest round-trip form.

    Each distinct number (bit pattern) is formatted once; the lines are then put together
    in one byte array, the cells of one text length at a time.
    """
    if not columns:
        return ""
    matrix = np.column_stack([np.asarray(c, dtype=float) for c in columns])
    if not matrix.size:
        return ""
    distinct, which = np.unique(np.ascontiguousarray(matrix).reshape(-1).view(np.int64),
                                return_inverse=True)
    text = _shortest_text(distinct.view(np.float64))
    table = np.frombuffer(text.tobytes(), dtype=np.uint8).reshape(len(text), -1)
    lengths = np.char.str_len(text).astype(np.uint8)[which.reshape(-1)]  # at most 24
    sizes = lengths + np.int64(1)  # each cell and its separator
    starts = np.cumsum(sizes) - sizes
    out = np.full(int(starts[-1] + sizes[-1]), ord(","), dtype=np.uint8)
    out[(starts + lengths).reshape(matrix.shape)[:, -1]] = ord("\n")
    order, counts = np.argsort(lengths, kind="stable"), np.bincount(lengths)
    ends, cell_text = np.cumsum(counts), which.reshape(-1)
    for length in np.flatnonzero(counts).tolist():  # each text length's cells in one copy
        cells = order[ends[length] - counts[length]:ends[length]]
        place_rows(out, starts[cells], table[cell_text[cells], :length])
    return out.tobytes().decode("ascii")


def _shortest_text(values: npt.NDArray[np.float64]) -> npt.NDArray[np.bytes_]:
    """Each number in numpy's shortest round-trip form (``str``), as ASCII bytes.

    orjson writes the same shortest digits (Ryu) about six times as fast as numpy, and in
    the same form for zero and for 1e-4 <= |x| < 1e16; numpy writes the others (exponents,
    NaN, infinities). A LIDAR's ranges are all distinct numbers: 648,000 in the default run.
    """
    import orjson

    size = np.abs(values)
    plain = (values == 0) | ((size >= 1e-4) & (size < 1e16))  # False for NaN and infinities
    fast = np.array(orjson.dumps(np.ascontiguousarray(values[plain]),
                                 option=orjson.OPT_SERIALIZE_NUMPY)[1:-1].split(b","),
                    dtype=np.bytes_) if plain.any() else np.zeros(0, dtype=np.bytes_)
    if plain.all():
        return fast
    slow = values[~plain].astype(str).astype(np.bytes_)
    out = np.zeros(len(values), dtype=np.result_type(fast, slow))
    out[plain], out[~plain] = fast, slow
    return out


def _table(header: Sequence[str], columns: Sequence[npt.ArrayLike]) -> Table:
    return tuple(header), _rows(columns)


def tables(result: SimResult) -> dict[str, Table]:
    """File name to the header and the rows of every stream for a piece of a run.

    Boundary rows (ground truth) are the piece's tick starts, and the run's end in its last
    piece.
    """
    truth, plan, odom, joints = result.truth, result.plan, result.odometry, result.joints
    end = len(truth.x_m) if result.last else len(truth.x_m) - 1
    ticks = np.arange(result.first_tick, result.first_tick + end) * truth.dt_s
    lin = np.append(truth.linear_m_s, 0.0)[:end]
    ang = np.append(truth.angular_rad_s, 0.0)[:end]
    starts = np.arange(result.first_tick, result.first_tick + plan.ticks) * plan.dt_s
    out = {
        "ground_truth.csv": _table(("time_s", "x_m", "y_m", "yaw_rad", "linear_m_s",
                                    "angular_rad_s"),
                                   (ticks, truth.x_m[:end], truth.y_m[:end],
                                    truth.yaw_rad[:end], lin, ang)),
        "cmd_vel.csv": _table(("time_s", "target_linear_m_s", "target_angular_rad_s",
                               "linear_m_s", "angular_rad_s", "left_wheel_rad_s",
                               "right_wheel_rad_s"),
                              (starts, plan.target_linear_m_s, plan.target_angular_rad_s,
                               plan.linear_m_s, plan.angular_rad_s, plan.left_rad_s,
                               plan.right_rad_s)),
        "odometry.csv": _table(("time_s", "x_m", "y_m", "yaw_rad", "linear_m_s",
                                "angular_rad_s"),
                               (odom.times_s, odom.x_m, odom.y_m, odom.yaw_rad, odom.linear_m_s,
                                odom.angular_rad_s)),
        "joint_states.csv": _table(
            ("time_s", *(f"{n}_rad" for n in joints.names), *(f"{n}_rad_s" for n in joints.names)),
            (joints.times_s, *joints.positions.T, *joints.velocities.T)),
        "collisions.csv": (("time_s", "obstacle", "link", "x_m", "y_m", "yaw_rad"), "".join(
            f"{c.time_s!r},{c.obstacle},{c.link},{c.x_m!r},{c.y_m!r},{c.yaw_rad!r}\n"
            for c in result.contacts)),
    }
    for name, scans in zip(scan_files(result.body), result.scans, strict=True):
        up = scans.inclinations_rad  # several rings: each ray's inclination too
        names = [f"range_m@{a:.6f}rad" for a in scans.angles_rad] if up is None else \
            [f"range_m@{a:.6f}rad@{e:.6f}rad" for a, e in zip(scans.angles_rad, up, strict=True)]
        out[name] = _table(("time_s", *names), (scans.times_s, *scans.ranges_m.T))
    if result.imu is not None:
        imu = result.imu
        out["imu.csv"] = _table(
            ("time_s", "qx", "qy", "qz", "qw", "wx_rad_s", "wy_rad_s", "wz_rad_s",
             "ax_m_s2", "ay_m_s2", "az_m_s2"),
            (imu.times_s, *imu.orientation_xyzw.T, *imu.angular_velocity_rad_s.T,
             *imu.linear_acceleration_m_s2.T))
    if result.camera is not None:
        cam, n = result.camera, len(result.camera_times_s)
        out["camera_info.csv"] = _table(
            ("time_s", "width_px", "height_px", "fx_px", "fy_px", "cx_px", "cy_px"),
            (result.camera_times_s, *(np.full(n, v) for v in (cam.width_px, cam.height_px,
                                                              cam.k[0], cam.k[4], cam.k[2],
                                                              cam.k[5]))))
    return out


def scan_files(body: SimRobot) -> list[str]:
    """The CSV file of each of ``body``'s ray sensors, in order.

    The first (the LIDAR) writes ``scan.csv``; each other ``scan_TOPIC.csv``, its topic's
    name with ``/`` as ``_`` (``/ir_intensity_left`` -> ``scan_ir_intensity_left.csv``), cut
    at 100 characters (a file name holds 255 bytes), numbered ``_2``, ``_3``... where two
    would share one name.
    """
    out: list[str] = []
    for index, mounted in enumerate(body.ray_sensors):
        slug = re.sub(r"[^A-Za-z0-9_.-]+", "_", (mounted.spec.topic or "").strip("/"))[:100]
        stem = "scan" if index == 0 else f"scan_{slug}"
        name, count = f"{stem}.csv", 1
        while name in out:
            count += 1
            name = f"{stem}_{count}.csv"
        out.append(name)
    return out


_RUN_FILE = re.compile(r"(?:(?:ground_truth|cmd_vel|odometry|joint_states|imu|camera_info|"
                       r"collisions|scan(?:_.+)?)(?:_\d+)?\.csv)|summary\.json|camera\.png")
"""The names of the files a run writes in ``--out``."""


def _remove(paths: list[Path]) -> None:
    for path in paths:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()


class CsvWriter:
    """Writes a run's CSV files and ``summary.json`` into ``directory``, piece by piece.

    A missing directory is built under a temporary name beside it and renamed into place;
    in an existing one, every file is written to a temporary first. Either way the files
    are put in place when ``stack`` closes after :meth:`finish`, and an interrupted run
    leaves no temporary and no partial set of files.

    Raises:
        OutputError: The directory cannot be created or written.
    """

    def __init__(self, directory: str | Path, stack: contextlib.ExitStack) -> None:
        path = Path(directory)
        if os.path.exists(path) and not os.path.isdir(path):
            raise OutputError(f"{path}: exists and is not a directory; give a directory for "
                              "--out")
        self.stack = stack
        if os.path.exists(path):
            self.folder, self.in_place = path, False
        else:
            self.folder, self.in_place = stack.enter_context(atomic_directory(path)), True
        self.files: dict[str, IO[Any]] = {}
        self.last_frame: Frame | None = None

    def _open(self, name: str, mode: str = "w") -> IO[Any]:
        if self.in_place and mode == "wb":  # inside the directory being built
            return self.stack.enter_context((self.folder / name).open("wb"))
        if self.in_place:
            return self.stack.enter_context((self.folder / name).open(
                "w", encoding="utf-8", newline="\n"))
        return self.stack.enter_context(atomic_output(self.folder / name, mode))

    def add(self, piece: SimResult) -> None:
        """Append the rows of a piece of the run (the first opens the files)."""
        for name, (header, rows) in tables(piece).items():
            if name not in self.files:
                self.files[name] = self._open(name)
                self.files[name].write(",".join(header) + "\n")
            self.files[name].write(rows)
        if piece.frames:
            self.last_frame = piece.frames[-1]

    def finish(self, summary: Summary) -> None:
        """Write ``summary.json`` and ``camera.png``; in place when the stack closes.

        In an existing directory, a run's file this run does not write (an earlier run's
        ``scan_rear_scan.csv``, ``camera.png``) is removed as the new ones go in: the
        directory holds one run, whose ``summary.json`` it is. Other files stay.
        """
        self._open("summary.json").write(dumps(summary))
        if self.last_frame is not None:
            self._open("camera.png", "wb").write(png_bytes(self.last_frame.rgb))
        if not self.in_place:
            written = {*self.files, "summary.json", "camera.png" if self.last_frame else ""}
            stale = [entry for entry in self.folder.iterdir() if entry.is_file()
                     and _RUN_FILE.fullmatch(entry.name) and entry.name not in written]
            self.stack.callback(_remove, stale)
