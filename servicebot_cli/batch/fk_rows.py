"""``fk --configs``: joint values per line in, poses per line out.

Each input line is one configuration: CSV columns or JSON keys named after joints (an
``ik`` result line, with its ``joints`` object or result columns, works too). A column that
states its unit (``NAME_deg``, ``NAME_rad``, ``NAME_m``, as ``ik --deg`` writes them) or a
line's ``angle_unit`` is read in that unit; bare names follow ``--deg`` (see
:mod:`~servicebot_cli.kinematics.joint_columns`). Results are
computed in chunks, so the conversion to roll-pitch-yaw and quaternions is vectorised, and
written as soon as a chunk is done; memory stays bounded by the chunk size.

Output rows::

    JSON Lines: {"line": 2, "poses": [{"frame": "...", "position_m": [...],
                 "rpy_rad": [...], "quaternion_xyzw": [...]}]}
    CSV:        line,x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad,qx,qy,qz,qw
                (each column prefixed with "FRAME." when several frames are asked for)
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.reading import Row
from servicebot_cli.batch.stream import RowKind
from servicebot_cli.common.errors import JointNotFound
from servicebot_cli.description.model import new_data
from servicebot_cli.kinematics.forward import configurations, frame_transforms, pose_table
from servicebot_cli.kinematics.frames import frame_ids, link_names
from servicebot_cli.kinematics.joint_columns import (
    ColumnUnits,
    angle_unit,
    joint_of,
    read_units,
)
from servicebot_cli.kinematics.json_types import JsonObject, JsonValue
from servicebot_cli.kinematics.mimics import Mimics
from servicebot_cli.kinematics.transforms import planar_matrix
from servicebot_cli.kinematics.user_joints import (
    angular,
    clamped_user_vector,
    number,
    row_pairs,
)

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]

CHUNK = 512
_LIMIT_SLACK = 1e-9  # as JointSpace.checked: a value this far outside a limit is on it
# Columns of an ik result that are not joints: fk input skips them as joints.
RESULT_COLUMNS = ("line", "angle_unit", "success", "position_error_m", "orientation_error_rad",
                  "iterations", "attempts", "solutions", "solve_time_s", "base_x_m", "base_y_m",
                  "base_yaw_rad", "base_yaw_deg", "hint")
BASE_COLUMNS = ("base_x_m", "base_y_m", "base_yaw_rad", "base_yaw_deg")
"""An ``ik --with-base`` result's base: where the robot stands for that line's poses."""
_NO_BASE = (math.nan, math.nan, math.nan)
_POSE_COLUMNS = ("x_m", "y_m", "z_m", "roll_{u}", "pitch_{u}", "yaw_{u}", "qx", "qy", "qz", "qw")


class FkBatch:
    """Poses of fixed frames for a stream of configurations.

    Attributes:
        clamped_values: Values ``--clamp`` moved onto a limit.
        clamped_lines: Lines that had such a value.
    """

    def __init__(self, robot: RobotDescription, frames: Sequence[str], relative_to: str, *,
                 deg: bool, clamp: bool, in_world: FloatArray | None = None) -> None:
        """Prepare for ``frames`` in ``relative_to``; angles in degrees with ``deg``.

        With ``in_world`` (``transform_root_to_world``, where the robot stands), poses are
        in the world instead.
        """
        known = link_names(robot)
        self.model = robot.model
        self.data = new_data(self.model, robot.display)
        self.space = robot.joint_space
        self.mimics = Mimics.of(robot.joints, self.space)
        self.frames = list(frames)
        *self.ids, self.reference = frame_ids(self.model, [*frames, relative_to], known)
        self.deg, self.clamp = deg, clamp
        self.in_world = in_world
        self.unit = "deg" if deg else "rad"
        self._columns = self._header()
        self.clamped_values = self.clamped_lines = 0
        self.header_units: ColumnUnits | None = None
        """A CSV header's joints and angle unit (None: each line says, as JSON lines do)."""
        self._line_units: dict[tuple[object, ...], ColumnUnits] = {}

    def columns(self) -> list[str]:
        """CSV header: ``line`` then the pose columns of each frame."""
        return list(self._columns)

    def _header(self) -> list[str]:
        names = [c.format(u=self.unit) for c in _POSE_COLUMNS]
        if len(self.frames) == 1:
            return ["line", *names]
        return ["line", *(f"{frame}.{n}" for frame in self.frames for n in names)]

    def check_header(self, columns: Sequence[str]) -> None:
        """Every CSV column must be a joint (or an ik result column), in units that agree.

        Raises:
            JointNotFound: The first column that is neither, with the nearest joint names.
            UnitConflict: Joint columns whose units disagree (see :func:`read_units`).
        """
        joints = [name for name in columns if name not in RESULT_COLUMNS]
        for name in joints:
            if joint_of(name, self.space)[0] not in self.space.names:
                raise JointNotFound.for_name(name, self.space.names)
        if "angle_unit" not in columns:  # else each line says its unit
            self.header_units = read_units(joints, self.space, deg=self.deg,
                                           declared=_yaw_unit(columns))

    def parse(self, row: Row) -> FloatArray:
        """The row's configuration, one value per joint [rad or m], then its base's pose.

        The base (``x``, ``y`` [m], ``yaw`` [rad]; NaN without one) is an ``ik --with-base``
        result's, where the robot stands for this line (over ``--base``).
        """
        values: Mapping[str, JsonValue] = row.values
        base = _row_base(values)
        joints = values.get("joints")
        named = joints if isinstance(joints, Mapping) else values  # an ik result line, or flat
        pairs = row_pairs(named, RESULT_COLUMNS)
        units = self.header_units if self.header_units is not None else \
            self.units_of(values, [name for name, _ in pairs])
        vector, clamped = clamped_user_vector(
            self.space, [(units.joint(name), value) for name, value in pairs], deg=units.deg,
            clamp=self.clamp, mimics=self.mimics)
        if clamped:
            self.clamped_values += len(clamped)
            self.clamped_lines += 1
        return np.concatenate((vector, base))

    def units_of(self, values: Mapping[str, JsonValue], names: Sequence[str]) -> ColumnUnits:
        """The joints and angle unit of a line whose joint keys are ``names``.

        Its ``angle_unit``, its columns' units and its base's yaw unit, which must agree.

        Raises:
            UnitConflict: An ``angle_unit`` other than ``deg`` or ``rad``, or units that
                disagree.
        """
        said = angle_unit(values["angle_unit"]) if "angle_unit" in values else None
        base = values.get("base")
        yaw = _yaw_unit(base, prefix="") if isinstance(base, Mapping) else _yaw_unit(values)
        key = (tuple(names), said, yaw)
        if key not in self._line_units:
            self._line_units[key] = read_units(names, self.space, deg=self.deg,
                                               line_unit=said, declared=yaw)
        return self._line_units[key]

    def results(self, items: Iterable[tuple[Row, FloatArray]],
                kind: RowKind) -> Iterator[JsonObject]:
        """One output row per input row, computed a chunk at a time."""
        iterator = iter(items)
        while chunk := list(itertools.islice(iterator, CHUNK)):
            poses = self.pose_table(np.stack([values for _, values in chunk]))
            for (row, _), values in zip(chunk, poses, strict=True):
                yield self.json_row(row.line, values) if kind == "jsonl" else \
                    self._csv_row(row.line, values)

    def chunk_vectors(self, given: FloatArray, joints: Sequence[int]) -> FloatArray | None:
        """Joint values of many lines at once, as :meth:`parse` reads one line.

        Args:
            given: Values in the header's units, shape (lines, len(joints)).
            joints: The joint-space index of each column.

        Returns:
            Shape (lines, joints of the space) [rad or m]; None when a value lies outside
            its limits without ``clamp`` (the per-line path then names it).
        """
        space = self.space
        values = np.zeros((given.shape[0], len(space.names)))
        values[:, joints] = given
        named = np.zeros(len(space.names), dtype=bool)
        named[list(joints)] = True
        if self.header_units is not None and self.header_units.deg:
            values = np.where(angular(space), np.radians(values), values)
        mimics = self.mimics
        for f, lead, k, c in zip(mimics.follower, mimics.leader, mimics.multiplier,
                                 mimics.offset, strict=True):
            if not named[f]:
                values[:, f] = k * values[:, lead] + c
        named[list(mimics.follower)] |= named[list(mimics.leader)]
        bounded = ~np.isnan(space.lower)
        inside = values.copy()
        inside[:, bounded] = np.clip(values[:, bounded], space.lower[bounded],
                                     space.upper[bounded])
        no_base = np.full((len(values), 3), math.nan)
        if self.clamp:
            moved = named & (np.abs(values - inside) > 1e-9)
            if mimics.follower and moved.any():
                return None  # clamped leader by leader, with its followers: line by line
            self.clamped_values += int(moved.sum())
            self.clamped_lines += int(moved.any(axis=1).sum())
            return np.hstack((np.where(named, inside, values), no_base))
        probe = np.where(named, values, inside)[:, bounded]
        low, high = space.lower[bounded] - _LIMIT_SLACK, space.upper[bounded] + _LIMIT_SLACK
        if not ((probe >= low) & (probe <= high)).all():
            return None
        return np.hstack((values, no_base))

    def pose_table(self, values: FloatArray) -> FloatArray:
        """Poses of the frames for many configurations (see :func:`pose_table`).

        Args:
            values: One value per joint [rad or m], then the base's ``x y yaw`` (NaN: none),
                shape (lines, joints of the space + 3).

        Returns:
            Shape (lines, frames, 10), angles in the user's unit, no ``-0.0``.
        """
        joints, base = values[:, :-3], values[:, -3:]
        matrices = frame_transforms(self.model, self.data, configurations(self.space, joints),
                                    self.ids, self.reference)
        if self.in_world is not None:
            matrices = np.matmul(self.in_world, matrices)
        placed = ~np.isnan(base[:, 0])
        if placed.any():  # each line's own base, where ik placed it
            bases = np.array([planar_matrix(x, y, yaw) for x, y, yaw in base[placed].tolist()])
            matrices[placed] = np.matmul(bases[:, None], matrices[placed])
        poses = pose_table(matrices) + 0.0
        if self.deg:
            poses[..., 3:6] = np.degrees(poses[..., 3:6])
        return poses

    def json_row(self, line: int, poses: FloatArray) -> JsonObject:
        """One JSON Lines result: the line and each frame's pose."""
        return self._json_row(line, poses)

    def _json_row(self, line: int, poses: FloatArray) -> JsonObject:
        table = poses.tolist()
        return {"line": line, "poses": [
            {"frame": frame, "position_m": p[0:3], f"rpy_{self.unit}": p[3:6],
             "quaternion_xyzw": p[6:10]}
            for frame, p in zip(self.frames, table, strict=True)
        ]}

    def _csv_row(self, line: int, poses: FloatArray) -> JsonObject:
        return dict(zip(self._columns, [line, *poses.ravel().tolist()], strict=True))


def _row_base(values: Mapping[str, JsonValue]) -> tuple[float, float, float]:
    """An ``ik --with-base`` result line's base: ``x``, ``y`` [m], ``yaw`` [rad]; NaN without.

    Its JSON ``base`` object, or its CSV ``base_x_m``, ``base_y_m`` and ``base_yaw_rad`` (or
    ``base_yaw_deg``) columns.
    """
    base = values.get("base")
    if isinstance(base, Mapping):
        given = {f"base_{key}": value for key, value in base.items()}
    else:
        given = {key: values[key] for key in BASE_COLUMNS if key in values}
    if not given or all(value in ("", None) for value in given.values()):
        return _NO_BASE  # a line ik solved without a base, or no ik result
    yaw_key = "base_yaw_deg" if "base_yaw_deg" in given else "base_yaw_rad"
    x, y, yaw = (number(given.get(key), f"'{key}'")
                 for key in ("base_x_m", "base_y_m", yaw_key))
    return x, y, math.radians(yaw) if yaw_key.endswith("deg") else yaw


def _yaw_unit(keys: Iterable[str], prefix: str = "base_") -> tuple[tuple[str, str], ...]:
    """The angle unit an ik ``--with-base`` result's base yaw states: ``(what, unit)``, if any.

    ``keys`` are a CSV header or a flat JSON line's (``base_yaw_deg``), or, with ``prefix``
    "", a JSON ``base`` object's (``yaw_deg``).
    """
    return tuple((f"'{key}'" if prefix else f"base '{key}'", key.rpartition("_")[2])
                 for key in keys if key in (f"{prefix}yaw_deg", f"{prefix}yaw_rad"))
