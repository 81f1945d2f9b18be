"""A PNG file of an rgb8 image, with zlib alone (no imaging library to import).

8-bit truecolour, no interlace, every row with filter type 0 (PNG specification, ISO/IEC
15948): a signature, then IHDR, one IDAT with the zlib-compressed rows, and IEND, each
chunk with its length and CRC-32.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np
import numpy.typing as npt

_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_bytes(rgb: npt.NDArray[np.uint8]) -> bytes:
    """The PNG file of ``rgb``, shape (rows, columns, 3), row 0 at the top."""
    rows, columns, channels = rgb.shape
    if channels != 3:
        raise ValueError(f"expected 3 channels, got {channels}")
    raw = np.zeros((rows, 1 + 3 * columns), dtype=np.uint8)  # a filter byte 0 starts a row
    raw[:, 1:] = np.ascontiguousarray(rgb, dtype=np.uint8).reshape(rows, -1)
    header = struct.pack(">IIBBBBB", columns, rows, 8, 2, 0, 0, 0)  # 8-bit RGB
    return _SIGNATURE + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(
        raw.tobytes(), 9)) + _chunk(b"IEND", b"")


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data \
        + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
