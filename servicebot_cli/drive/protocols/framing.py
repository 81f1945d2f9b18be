"""Framing of the servicebot serial protocol: frames, their CRC, and a byte-fed decoder.

A frame on the wire (multi-byte fields little-endian, see ``docs/serial-protocol.md``)::

    offset  size  field
    0       2     SYNC     0xAA 0x55
    2       1     LEN      payload length, 0..MAX_PAYLOAD
    3       1     SEQ      sequence number; a reply carries the SEQ of the command it answers
    4       1     TYPE     message type (messages.py)
    5       LEN   PAYLOAD
    5+LEN   2     CRC      CRC-16/CCITT-FALSE of LEN, SEQ, TYPE and PAYLOAD, low byte first

Pure: bytes in, frames out. The decoder may be fed any chunking of the byte stream and finds
frames again after garbage, lost bytes or corrupted bytes.
"""

from __future__ import annotations

from dataclasses import dataclass

SYNC = b"\xaa\x55"
HEADER_SIZE = 5  # SYNC, LEN, SEQ, TYPE
CRC_SIZE = 2
OVERHEAD = HEADER_SIZE + CRC_SIZE
MAX_PAYLOAD = 32  # a LEN above this is not a frame: resynchronise at once


def _crc_table() -> tuple[int, ...]:
    table = []
    for byte in range(256):
        crc = byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) if crc & 0x8000 else (crc << 1)
        table.append(crc & 0xFFFF)
    return tuple(table)


_CRC_TABLE = _crc_table()


def crc16_ccitt_false(data: bytes, crc: int = 0xFFFF) -> int:
    """CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no XOR out.

    ``crc16_ccitt_false(b"123456789") == 0x29B1`` (the catalogue's check value).
    """
    for byte in data:
        crc = ((crc << 8) & 0xFFFF) ^ _CRC_TABLE[((crc >> 8) ^ byte) & 0xFF]
    return crc


@dataclass(frozen=True)
class Frame:
    """One frame's content.

    Attributes:
        seq: Sequence number, 0..255.
        type: Message type, 0..255.
        payload: Payload bytes, at most :data:`MAX_PAYLOAD`.
    """

    seq: int
    type: int
    payload: bytes = b""


def encode_frame(frame: Frame) -> bytes:
    """The bytes of ``frame`` on the wire.

    Raises:
        ValueError: A field out of its byte range or a payload over :data:`MAX_PAYLOAD`
            (a bug in the caller, never user input).
    """
    if not (0 <= frame.seq <= 255 and 0 <= frame.type <= 255):
        raise ValueError(f"seq and type are bytes, got seq={frame.seq} type={frame.type}")
    if len(frame.payload) > MAX_PAYLOAD:
        raise ValueError(f"payload of {len(frame.payload)} bytes is over {MAX_PAYLOAD}")
    body = bytes((len(frame.payload), frame.seq, frame.type)) + frame.payload
    crc = crc16_ccitt_false(body)
    return SYNC + body + bytes((crc & 0xFF, crc >> 8))


@dataclass
class DecoderStats:
    """What the decoder has seen since it was made.

    Attributes:
        frames: Frames delivered.
        crc_errors: Candidate frames whose CRC did not match.
        bad_length: Candidate frames whose LEN was over the maximum.
        discarded_bytes: Bytes dropped while hunting for a frame (garbage, bad candidates).
    """

    frames: int = 0
    crc_errors: int = 0
    bad_length: int = 0
    discarded_bytes: int = 0

    @property
    def errors(self) -> int:
        """Candidate frames rejected, for any reason."""
        return self.crc_errors + self.bad_length


class Decoder:
    """Turns a byte stream, fed in any chunks, into frames.

    It looks for SYNC, checks LEN, waits for the whole frame and checks its CRC. A rejected
    candidate costs one byte: the search restarts just after its first SYNC byte, so a real
    frame hidden inside garbage is still found.
    """

    def __init__(self, max_payload: int = MAX_PAYLOAD) -> None:
        self._buffer = bytearray()
        self._max_payload = max_payload
        self.stats = DecoderStats()

    def feed(self, data: bytes) -> list[Frame]:
        """Add ``data``; return every frame it completes, in order."""
        self._buffer += data
        frames: list[Frame] = []
        while True:
            frame, complete = self._next()
            if frame is not None:
                frames.append(frame)
            elif complete:
                return frames

    def _next(self) -> tuple[Frame | None, bool]:
        """One step: ``(frame, False)``, ``(None, False)`` to go on, ``(None, True)`` when done."""
        buffer = self._buffer
        start = buffer.find(SYNC)
        if start < 0:  # keep a last 0xAA: it may be the first half of SYNC
            self._discard(len(buffer) - (1 if buffer[-1:] == SYNC[:1] else 0))
            return None, True
        self._discard(start)
        if len(buffer) < HEADER_SIZE:
            return None, True
        length = buffer[2]
        if length > self._max_payload:
            self.stats.bad_length += 1
            self._discard(1)
            return None, False
        end = HEADER_SIZE + length + CRC_SIZE
        if len(buffer) < end:
            return None, True
        crc = buffer[end - 2] | (buffer[end - 1] << 8)
        if crc16_ccitt_false(bytes(buffer[2:end - 2])) != crc:
            self.stats.crc_errors += 1
            self._discard(1)
            return None, False
        frame = Frame(buffer[3], buffer[4], bytes(buffer[HEADER_SIZE:end - 2]))
        del buffer[:end]
        self.stats.frames += 1
        return frame, False

    def _discard(self, count: int) -> None:
        if count > 0:
            del self._buffer[:count]
            self.stats.discarded_bytes += count

    @property
    def pending(self) -> int:
        """Bytes held while waiting for the rest of a frame."""
        return len(self._buffer)
