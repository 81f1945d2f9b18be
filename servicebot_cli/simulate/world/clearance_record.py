"""The clearance record of a run: the closest the robot has come to an obstacle so far.

Each piece's poses are measured against the record of the pieces before it
(:func:`~servicebot_cli.simulate.world.clearance.closest` with ``below``), so the record of
the pieces in order is that of the whole run in one piece.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.world.clearance import Closest, closest
from servicebot_cli.simulate.world.contacts import Placed, Tester
from servicebot_cli.simulate.world.motion import Path2D

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
NO_CLEARANCE = Closest(float("inf"), -1, -1, -1)
"""The record before any pose: no obstacle measured."""


class ClearanceRecord:
    """The least part-obstacle distance over the pieces measured so far.

    Args:
        tester: The robot's parts and the world's obstacles.
        base_height_m: Height of the base's origin above the floor.
    """

    def __init__(self, tester: Tester, base_height_m: float) -> None:
        self.tester, self.base_height_m = tester, base_height_m
        self.record = NO_CLEARANCE

    def advance(self, first: int, truth: Path2D, arm_q: FloatArray,
                parts: FloatArray) -> Closest:
        """The record after the piece whose first tick is ``first``.

        ``truth`` and ``arm_q`` (n+1, J) are the piece's poses at its tick boundaries, and
        ``parts`` the parts' ``transform_part_to_base`` there, shape (n+1, S, 4, 4). A pose
        held for ticks is measured once: met again later it measures no less than at its
        first tick, which wins ties.
        """
        lo = 0 if first == 0 else 1  # the piece's first boundary ended the piece before
        rows = np.column_stack((truth.x_m[lo:], truth.y_m[lo:], truth.yaw_rad[lo:], arm_q[lo:]))
        new = np.ones(len(rows), dtype=bool)
        new[1:] = np.any(rows[1:] != rows[:-1], axis=1)
        index = np.flatnonzero(new) + lo  # the first tick of each held pose, in time order
        at: slice | IntArray = slice(lo, None) if new.all() else index  # a view if all
        found = closest(self.tester, Placed(parts[at], truth.x_m[at], truth.y_m[at],
                                            truth.yaw_rad[at], self.base_height_m),
                        below=self.record.distance_m)
        if found.index >= 0:
            self.record = Closest(found.distance_m, first + int(index[found.index]),
                                  found.obstacle, found.part)
        return self.record
