"""The parts' transforms at a piece's arm configurations, each configuration composed once.

A piece's contact tests ask for the parts at the configurations the arm would reach; the
piece then needs them at the configurations it did reach, mostly the same ones. Rows already
composed are found by their bits (a hash of each row, then an exact comparison of the bits),
and a row equal to the one before it is composed once, so the transforms are the very bits
:meth:`~servicebot_cli.simulate.shape.RobotShape.transforms_to_base` makes for each row.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.shape import RobotShape, configuration_rows

FloatArray = npt.NDArray[np.float64]
UIntArray = npt.NDArray[np.uint64]
_MIX = np.uint64(0x9E3779B97F4A7C15)  # the golden ratio's odd multiplier (Fibonacci hashing)
_SHIFT = np.uint64(29)


class TransformMemo:
    """``shape.transforms_to_base`` with the rows made since :meth:`clear` remembered.

    Args:
        shape: The robot's parts and the joints that move them.
    """

    def __init__(self, shape: RobotShape) -> None:
        self.shape = shape
        self.clear()

    def clear(self) -> None:
        """Forget every row (a piece starts: memory stays flat)."""
        self._batches: list[tuple[UIntArray, FloatArray]] = []  # (bits, transforms) made
        self._sorted: UIntArray = np.zeros(0, dtype=np.uint64)  # the rows' keys, ascending
        self._order = np.zeros(0, dtype=np.int64)  # the row of each sorted key

    def __call__(self, q: FloatArray) -> FloatArray:
        """``transform_part_to_base`` of every part at each row of ``q`` (P, J): (P, S, 4, 4)."""
        q = np.ascontiguousarray(configuration_rows(q, len(self.shape.joints)))
        bits = q.view(np.uint64)
        if not self._batches:
            out, _ = self._make(q, bits)
            return out
        known_bits, known = self._known()
        keys = _row_keys(bits)
        at = np.minimum(np.searchsorted(self._sorted, keys), len(self._sorted) - 1)
        row = self._order[at]
        hit = (self._sorted[at] == keys) & np.all(known_bits[row] == bits, axis=1)
        out = known[row]  # a gather by row numbers: far faster than by a mask
        miss = np.flatnonzero(~hit)
        if len(miss):
            out[miss], _ = self._make(q[miss], bits[miss])
        return out

    def _make(self, q: FloatArray, bits: UIntArray) -> tuple[FloatArray, FloatArray]:
        """The rows ``q`` composed (a row equal to the one before it once), and those made."""
        new = np.ones(len(q), dtype=bool)
        new[1:] = np.any(bits[1:] != bits[:-1], axis=1)
        made = self.shape.transforms_to_base(q if new.all() else q[new])
        self._batches.append((bits[new], made))
        return (made if new.all() else made[np.cumsum(new) - 1]), made

    def _known(self) -> tuple[UIntArray, FloatArray]:
        """Every row made so far, in one array (the batches joined when a lookup needs it)."""
        if len(self._batches) > 1:
            self._batches = [(np.concatenate([b for b, _ in self._batches]),
                              np.concatenate([m for _, m in self._batches]))]
            self._sorted = np.zeros(0, dtype=np.uint64)
        bits, made = self._batches[0]
        if len(self._sorted) != len(bits):
            keys = _row_keys(bits)
            self._order = np.argsort(keys, kind="stable")
            self._sorted = keys[self._order]
        return bits, made


def _row_keys(bits: UIntArray) -> UIntArray:
    """A 64-bit hash of each row's bits, shape (P,)."""
    key = np.zeros(len(bits), dtype=np.uint64)
    for column in bits.T:
        key = (key ^ column) * _MIX
        key ^= key >> _SHIFT
    return key
