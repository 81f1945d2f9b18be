"""Messages as rows of byte arrays, and rows copied into one byte array, many at once.

A stream's serialized messages all have one size, so they are the rows of one byte array.
Rows of several such arrays are interleaved into one array without a Python object per
message: all of one array's rows go to their places in one numpy assignment, through a view of
the target whose row ``k`` is the ``width`` bytes from byte ``k`` on.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

ByteRows = npt.NDArray[np.uint8]
"""Messages of one size, one row each: shape (messages, message size)."""
IntArray = npt.NDArray[np.int64]


@dataclass(frozen=True)
class Payloads:
    """Serialized messages, in order, as rows of a few byte arrays.

    Message ``i`` is ``blocks[block[i]][row[i]]``.

    Attributes:
        blocks: Byte arrays, each of shape (messages, message size).
        block: The block of each message.
        row: The row of each message in its block.
    """

    blocks: Sequence[ByteRows]
    block: IntArray
    row: IntArray

    def __len__(self) -> int:
        return len(self.block)

    def part(self, start: int, stop: int) -> Payloads:
        """Messages ``start`` to ``stop`` (excluded), on the same blocks."""
        return Payloads(self.blocks, self.block[start:stop], self.row[start:stop])

    def sizes(self) -> IntArray:
        """Bytes of each message."""
        widths = np.array([b.shape[1] for b in self.blocks], dtype=np.int64)
        return widths[self.block] if len(widths) else np.zeros(0, dtype=np.int64)

    @classmethod
    def of(cls, payloads: Sequence[bytes]) -> Payloads:
        """``payloads`` as rows: one block per distinct size."""
        groups = SizeGroups.of(np.fromiter(map(len, payloads), dtype=np.int64,
                                           count=len(payloads)))
        blocks = []
        for size, mine in zip(groups.sizes, groups.members, strict=True):
            data = b"".join([payloads[k] for k in mine.tolist()])
            blocks.append(np.frombuffer(data, dtype=np.uint8).reshape(len(mine), size))
        return cls(blocks, groups.block, groups.row)


@dataclass(frozen=True)
class SizeGroups:
    """Messages grouped by size, as :class:`Payloads` keeps them.

    Attributes:
        sizes: The distinct sizes, ascending.
        members: The messages of each size, in order.
        block: Each message's group (an index into ``sizes``).
        row: Each message's row within its group.
    """

    sizes: list[int]
    members: list[IntArray]
    block: IntArray
    row: IntArray

    @classmethod
    def of(cls, sizes_each: IntArray) -> SizeGroups:
        """The groups of messages of sizes ``sizes_each``."""
        sizes, block = np.unique(sizes_each, return_inverse=True)
        row = np.zeros(len(sizes_each), dtype=np.int64)
        members = []
        for index in range(len(sizes)):
            mine = np.flatnonzero(block == index)
            row[mine] = np.arange(len(mine))
            members.append(mine)
        return cls(sizes.tolist(), members, block.reshape(-1).astype(np.int64), row)


def after_prefixes(prefixes: ByteRows, payloads: Payloads, offsets: IntArray) -> ByteRows:
    """Each message's prefix row (``prefixes[i]``) then its payload, end to end, in one array.

    Message ``i`` starts at ``offsets[i]``; ``offsets[-1]`` is the total.
    """
    flat = np.empty(int(offsets[-1]), dtype=np.uint8)
    starts, width = offsets[:-1], prefixes.shape[1]
    place_rows(flat, starts, prefixes)
    for index, block in enumerate(payloads.blocks):
        mine = np.flatnonzero(payloads.block == index)
        if len(mine) and block.shape[1]:
            rows = payloads.row[mine]
            in_order = len(rows) == len(block) and bool(np.all(np.diff(rows) == 1)) \
                and rows[0] == 0
            place_rows(flat, starts[mine] + width, block if in_order else block[rows])
    return flat


def place_rows(flat: ByteRows, starts: IntArray, rows: ByteRows) -> None:
    """Copy row ``i`` of ``rows`` to ``flat[starts[i]:starts[i] + width]``.

    The places must not overlap (nor run past the end of ``flat``).
    """
    width = rows.shape[1]
    if not width or not len(rows):
        return
    # each row one element of ``width`` bytes: numpy copies it whole, not byte by byte
    row = np.dtype((np.void, width))
    windows = np.ndarray((len(flat) - width + 1,), dtype=row, buffer=flat, strides=(1,))
    windows[starts] = np.ascontiguousarray(rows).view(row).reshape(-1)
