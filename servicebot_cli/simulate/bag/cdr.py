"""ROS 2 messages as CDR bytes, many at once, from numpy arrays.

A stream's messages share one layout: the same frame names, the same number of rays, joints
or transforms. :class:`Layout` computes that layout once (little-endian CDR with its 4-byte
encapsulation header, each primitive aligned to its size counted from the end of the header)
as a numpy structured type; a stream is then filled column by column, and its messages are
the rows of one byte array.
"""

from __future__ import annotations

import struct
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

_HEADER = b"\x00\x01\x00\x00"  # CDR little endian, no options
_HEADER_SIZE = len(_HEADER)


class Layout:
    """A fixed CDR layout: named numeric fields and constant bytes (strings, lengths)."""

    def __init__(self) -> None:
        self.offset = _HEADER_SIZE
        self.fields: dict[str, tuple[str, int, tuple[int, ...]]] = {}
        self.constants: list[tuple[int, bytes]] = [(0, _HEADER)]

    def _align(self, size: int) -> None:
        self.offset += -(self.offset - _HEADER_SIZE) % size

    def field(self, name: str, fmt: str, count: int = 1) -> None:
        """A primitive (``<f8``, ``<f4``, ``<i4``, ``<u4``, ``u1``) or fixed array of them."""
        size = np.dtype(fmt).itemsize
        self._align(size)
        self.fields[name] = (fmt, self.offset, (count,) if count > 1 else ())
        self.offset += size * count

    def constant(self, fmt: str, value: int | float) -> None:
        """A primitive whose value is the same in every message."""
        self._align(struct.calcsize(fmt))
        self._put(struct.pack(fmt, value))

    def _put(self, data: bytes) -> None:
        self.constants.append((self.offset, data))
        self.offset += len(data)

    def string(self, text: str) -> None:
        """A constant string: length (with the NUL) then UTF-8 bytes and NUL."""
        data = text.encode() + b"\x00"
        self.constant("<I", len(data))
        self._put(data)

    def strings(self, texts: Sequence[str]) -> None:
        """A constant ``string[]``."""
        self.constant("<I", len(texts))
        for text in texts:
            self.string(text)

    def sequence(self, name: str, fmt: str, count: int) -> None:
        """A ``T[]`` whose length ``count`` is the same in every message."""
        self.constant("<I", count)
        if count:
            self.field(name, fmt, count)
            fmt, offset, _ = self.fields[name]
            self.fields[name] = (fmt, offset, (count,))  # one element too: a (1,) array per row

    def header(self, frame_id: str) -> None:
        """A ``std_msgs/Header``: fields ``sec`` and ``nanosec``, constant ``frame_id``."""
        self.field("sec", "<i4")
        self.field("nanosec", "<u4")
        self.string(frame_id)

    def dtype(self) -> np.dtype:
        """The structured type of one message."""
        names = list(self.fields)
        return np.dtype({
            "names": names,
            "formats": [(self.fields[n][0], self.fields[n][2]) if self.fields[n][2]
                        else self.fields[n][0] for n in names],
            "offsets": [self.fields[n][1] for n in names],
            "itemsize": self.offset,
        })

    def records(self, count: int) -> npt.NDArray[np.void]:
        """``count`` messages with every constant in place and numeric fields zero."""
        template = bytearray(self.offset)
        for offset, data in self.constants:
            template[offset:offset + len(data)] = data
        # A view on one writable buffer: copying a structured array would drop the bytes
        # between fields, where the constants live.
        return np.frombuffer(bytearray(bytes(template) * count), dtype=self.dtype())


def set_stamps(records: npt.NDArray[np.void], times_s: npt.NDArray[np.float64]) -> None:
    """Fill ``sec``/``nanosec`` from times [s] (``builtin_interfaces/Time``)."""
    nanoseconds = stamps_ns(times_s)
    records["sec"] = nanoseconds // 1_000_000_000
    records["nanosec"] = nanoseconds % 1_000_000_000


def stamps_ns(times_s: npt.NDArray[np.float64]) -> npt.NDArray[np.int64]:
    """Times [s] as integer nanoseconds, rounded (so 0.1 s is exactly 100000000 ns)."""
    return np.round(np.asarray(times_s) * 1e9).astype(np.int64)


def rows(records: npt.NDArray[np.void]) -> npt.NDArray[np.uint8]:
    """The messages' bytes, one row per message: shape (messages, message size).

    A view on ``records`` (their bytes between fields included), not a copy.
    """
    return records.view(np.uint8).reshape(len(records), records.dtype.itemsize)


def serialize(layout: Layout, times_s: npt.NDArray[np.float64],
              fill: Mapping[str, npt.NDArray[Any] | float]) -> npt.NDArray[np.uint8]:
    """Messages of ``layout`` stamped ``times_s`` [s], each field of ``fill`` set: their rows."""
    records = layout.records(len(times_s))
    set_stamps(records, times_s)
    with np.errstate(over="ignore"):  # a float32 field beyond its range is +-inf, as in C++
        for name, values in fill.items():
            records[name] = values
    return rows(records)
