"""IK targets of many CSV lines at once: the targets :func:`row_target` reads, line by line.

A CSV header says once where each line's numbers are (:func:`target_layout`); a chunk of
lines then becomes targets with a few numpy operations (:func:`table_targets`) instead of a
dict and a conversion per cell. The targets are the same, bit for bit: quaternions through
:func:`~servicebot_cli.kinematics.rotations.matrices_from_quaternions`, roll-pitch-yaw
through :func:`~servicebot_cli.kinematics.rotations.matrix_from_rpy` one line at a time.
Whatever :func:`row_target` would refuse gives None, so the caller goes line by line and
the message names the line. Pure.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.rotations import AXES, matrices_from_quaternions, matrix_from_rpy
from servicebot_cli.kinematics.targets import MAX_POSITION_M, POSITION_KEYS, QUATERNION_KEYS

FloatArray = npt.NDArray[np.float64]

_RPY_KEYS = ((("roll_rad", "pitch_rad", "yaw_rad"), False),
             (("roll_deg", "pitch_deg", "yaw_deg"), True))
_PARTIAL = (*QUATERNION_KEYS, "roll", "pitch", "yaw", *(k for keys, _ in _RPY_KEYS for k in keys))
"""Keys of an orientation: one without the rest of its set goes the per-line path, refused."""


@dataclass(frozen=True)
class TargetLayout:
    """Where a CSV line's target numbers are.

    Attributes:
        columns: Indices of the position's three columns, then the orientation's (four for
            a quaternion, three for roll-pitch-yaw, none for a position alone).
        quaternion: The orientation is ``qx qy qz qw``.
        deg: Roll-pitch-yaw is in degrees.
    """

    columns: tuple[int, ...]
    quaternion: bool = False
    deg: bool = False


def target_layout(header: Sequence[str], frame: str, *, deg: bool) -> TargetLayout | None:
    """The layout :func:`row_target` reads from lines under ``header``; None: not a simple one.

    Not simple: a key given twice (with and without the ``FRAME.`` prefix), no position,
    or half an orientation (the per-line path then says which).
    """
    prefix = f"{frame}."
    keys = [name[len(prefix):] if name.startswith(prefix) else name for name in header]
    if len(set(keys)) != len(keys):
        return None
    index = {key: k for k, key in enumerate(keys)}
    position = next((p for p in POSITION_KEYS if all(k in index for k in p)), None)
    if position is None:
        return None
    where = [index[k] for k in position]
    if all(k in index for k in QUATERNION_KEYS):
        return TargetLayout((*where, *(index[k] for k in QUATERNION_KEYS)), quaternion=True)
    for rpy, in_deg in (*_RPY_KEYS, (("roll", "pitch", "yaw"), deg)):
        if all(k in index for k in rpy):
            return TargetLayout((*where, *(index[k] for k in rpy)), deg=in_deg)
    if any(k in index for k in _PARTIAL):
        return None
    return TargetLayout(tuple(where))


def table_targets(layout: TargetLayout, numbers: FloatArray,
                  axes: tuple[str, ...] | None) -> list[IkTarget] | None:
    """The targets of a chunk of lines, as :func:`row_target` makes each.

    Args:
        layout: Where the numbers came from.
        numbers: Finite values of ``layout.columns``, shape (lines, len(columns)).
        axes: ``--orientation-axes``; None: all three with an orientation, none without.

    Returns:
        One target per line; None when a line needs the per-line path (a position beyond
        :data:`MAX_POSITION_M`, a quaternion of zero length, axes without an orientation).
    """
    positions = np.array(numbers[:, :3], dtype=np.float64)
    if (np.abs(positions) > MAX_POSITION_M).any():
        return None
    rotations: FloatArray | list[FloatArray] | None = None
    if layout.quaternion:
        rotations = matrices_from_quaternions(numbers[:, 3:7])
        if rotations is None:
            return None
    elif len(layout.columns) == 6:
        angles = np.array(numbers[:, 3:6], dtype=np.float64)
        if layout.deg:
            angles = np.radians(angles)
        rotations = [matrix_from_rpy(row) for row in angles]
    chosen = (AXES if rotations is not None else ()) if axes is None else axes
    if chosen and rotations is None:
        return None
    if rotations is None:
        return [IkTarget(p, None, chosen) for p in positions]
    return [IkTarget(p, r, chosen) for p, r in zip(positions, rotations, strict=True)]
