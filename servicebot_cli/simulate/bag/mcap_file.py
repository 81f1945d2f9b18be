"""An MCAP file written in batches of messages, each batch's record headers built at once.

The format is https://mcap.dev/spec, laid out as the reference writer does it: magic, header,
schemas and channels, zstd chunks of about ``chunk_size`` bytes each followed by their message
indexes, data end, then a summary (schemas, channels, statistics, chunk indexes), summary
offsets, footer and magic. Readers (Foxglove, ``ros2 bag``, the ``mcap`` and ``rosbags``
libraries) seek through the indexes. The chunk being filled and at most
:data:`PENDING_BYTES` of full chunks waiting for the writing thread are held in memory; the
file's bytes do not depend on how the messages are split into batches.

Why not the ``mcap`` package's writer: it builds each message record in Python, about 4 us a
message; a three-minute run has 80 000 of them, half the simulator's time. Here payloads come
as :class:`~servicebot_cli.simulate.bag.byte_rows.Payloads`, rows of a few byte arrays (a
stream's messages have one size); the records of a batch (headers and payloads) are copied
into one byte array a block of rows at a time, with no Python object per message, and a chunk
is a slice of it. Full chunks
are joined, compressed, checksummed and written by one worker thread, in order, while the
caller goes on (zstd and zlib let go of the GIL); at most :data:`PENDING_BYTES` of records
wait for it (they are views on the batches' arrays, which live while a chunk of them waits).
"""

from __future__ import annotations

import itertools
import struct
import zlib
from collections.abc import Mapping, Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import BinaryIO, Protocol

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.bag.byte_rows import ByteRows, Payloads, after_prefixes

MAGIC = b"\x89MCAP0\r\n"
_HEADER, _FOOTER, _SCHEMA, _CHANNEL, _MESSAGE = 0x01, 0x02, 0x03, 0x04, 0x05
_CHUNK, _MESSAGE_INDEX, _CHUNK_INDEX, _STATISTICS = 0x06, 0x07, 0x08, 0x0B
_SUMMARY_OFFSET, _DATA_END = 0x0E, 0x0F

# A message record's fixed part: opcode, record length, channel, sequence, log and publish time.
_MESSAGE_HEAD = np.dtype([("opcode", "u1"), ("length", "<u8"), ("channel", "<u2"),
                          ("sequence", "<u4"), ("log_time", "<u8"), ("publish_time", "<u8")])
_INDEX_ENTRY = np.dtype([("log_time", "<u8"), ("offset", "<u8")])
PENDING_BYTES = 32 << 20
"""Record bytes of full chunks at most waiting for the writing thread: a few seconds of a run
without camera images, so the caller waits for none until the end."""


@dataclass(frozen=True)
class Channel:
    """A topic and the schema of its messages."""

    topic: str
    message_encoding: str
    schema_name: str
    schema_encoding: str
    schema_data: bytes
    metadata: Mapping[str, str] = field(default_factory=dict)


def _string(text: str) -> bytes:
    data = text.encode("utf-8")
    return struct.pack("<I", len(data)) + data


def _record(opcode: int, content: bytes) -> bytes:
    return struct.pack("<BQ", opcode, len(content)) + content


def _string_map(pairs: Mapping[str, str]) -> bytes:
    body = b"".join(_string(k) + _string(v) for k, v in sorted(pairs.items()))
    return struct.pack("<I", len(body)) + body


def _id_map(pairs: Mapping[int, int]) -> bytes:
    """A map<uint16, uint64>, as chunk indexes and statistics hold them."""
    body = b"".join(struct.pack("<HQ", k, v) for k, v in sorted(pairs.items()))
    return struct.pack("<I", len(body)) + body


class _Output:
    """The file, with its position and the running CRC of the data section."""

    def __init__(self, handle: BinaryIO) -> None:
        self.handle, self.position, self.crc = handle, 0, 0

    def write(self, data: bytes, *, data_section: bool = True) -> int:
        """Write ``data``; returns the offset it starts at."""
        start = self.position
        self.handle.write(data)
        self.position += len(data)
        if data_section:
            self.crc = zlib.crc32(data, self.crc)
        return start


class McapWriter:
    """Writes one MCAP file; messages are added in batches, in log time order.

    Args:
        handle: A binary file open for writing, at its start.
        channels: The channels; a message's channel id is its index here.
        profile: The MCAP profile (``ros2``).
        library: What wrote the file.
        chunk_size: Uncompressed bytes per chunk, roughly: a chunk ends before the message
            whose record starts past the next multiple of ``chunk_size`` (counted from the
            first record).
    """

    def __init__(self, handle: BinaryIO, channels: Sequence[Channel], *, profile: str,
                 library: str, chunk_size: int = 1 << 20) -> None:
        import zstandard

        self.out, self.chunk_size, self.channels = _Output(handle), chunk_size, channels
        # level 1: what rosbag2's MCAP storage (the mcap C++ writer's Default) uses
        self.compressor = zstandard.ZstdCompressor(level=1)
        self.out.write(MAGIC)
        self.out.write(_record(_HEADER, _string(profile) + _string(library)))
        self.schemas, self.channel_records = _schemas_and_channels(channels)
        self.out.write(b"".join(self.schemas) + b"".join(self.channel_records))
        self.written = 0  # record bytes added so far
        self.open_chunk = -1  # written // chunk_size of the chunk being filled
        self.heads: list[np.ndarray] = []  # the chunk being filled: record headers,
        self.records: list[ByteRows] = []  # its records, end to end, and their offsets
        self.offsets: list[npt.NDArray[np.int64]] = []
        self.chunk_indexes: list[bytes] = []
        self.pending: list[tuple[Future[bytes], int]] = []  # chunks given to the thread, in
        # file order, with their record bytes
        self.thread: ThreadPoolExecutor | None = None
        self.counts = np.zeros(len(channels), dtype=np.int64)
        self.first_time = self.last_time = 0

    def add(self, channel_ids: npt.NDArray[np.integer], sequences: npt.NDArray[np.integer],
            log_times_ns: npt.NDArray[np.integer],
            payloads: Payloads | Sequence[bytes]) -> None:
        """Add messages after those added before (``log_times_ns`` non-decreasing).

        Args:
            channel_ids: Channel of each message (its index in ``channels``).
            sequences: Sequence number of each message within its channel.
            log_times_ns: Time of each message [ns]; also its publish time.
            payloads: Serialized messages.
        """
        if not isinstance(payloads, Payloads):
            payloads = Payloads.of(payloads)
        if not len(payloads):
            return
        heads = np.zeros(len(payloads), dtype=_MESSAGE_HEAD)
        sizes = payloads.sizes()
        heads["opcode"], heads["length"] = _MESSAGE, 22 + sizes
        heads["channel"], heads["sequence"] = channel_ids, sequences
        heads["log_time"] = heads["publish_time"] = log_times_ns
        offsets = np.concatenate(([0], np.cumsum(_MESSAGE_HEAD.itemsize + sizes)))
        records = after_prefixes(heads.view(np.uint8).reshape(len(heads), -1), payloads,
                                 offsets)
        starts = self.written + offsets
        groups = starts[:-1] // self.chunk_size
        bounds = [0, *(np.flatnonzero(np.diff(groups)) + 1).tolist(), len(payloads)]
        for a, b in itertools.pairwise(bounds):
            if groups[a] != self.open_chunk:
                self._write_open_chunk()
                self.open_chunk = int(groups[a])
            self.heads.append(heads[a:b])
            self.records.append(records[offsets[a]:offsets[b]])
            self.offsets.append(starts[a:b])
        self.written = int(starts[-1])
        if not self.counts.any():
            self.first_time = int(log_times_ns[0])
        self.last_time = int(log_times_ns[-1])
        self.counts += np.bincount(np.asarray(channel_ids, dtype=np.int64),
                                   minlength=len(self.channels))

    def _write_open_chunk(self) -> None:
        """Give the chunk being filled to the writing thread (after the ones before it)."""
        if not self.records:
            return
        offsets = np.concatenate(self.offsets)
        if self.thread is None:
            self.thread = ThreadPoolExecutor(1, thread_name_prefix="mcap-chunks")
        size = sum(len(part) for part in self.records)
        while self.pending and sum(n for _, n in self.pending) + size > PENDING_BYTES:
            self.chunk_indexes.append(self.pending.pop(0)[0].result())
        self.pending.append((self.thread.submit(
            _write_chunk, self.out, np.concatenate(self.heads), self.records,
            offsets - offsets[0], self.compressor), size))
        self.heads, self.records, self.offsets = [], [], []

    def close(self) -> None:
        """Stop the writing thread: chunks not begun are dropped (for a run ended early)."""
        if self.thread is not None:
            self.thread.shutdown(cancel_futures=True)
            self.thread = None
        self.pending = []

    def _written_chunks(self) -> None:
        """Wait for the writing thread to write every chunk given to it; raise its error."""
        try:
            for future, _ in self.pending:
                self.chunk_indexes.append(future.result())
        finally:
            self.pending = []
            if self.thread is not None:
                self.thread.shutdown()
                self.thread = None

    def finish(self) -> None:
        """Write the last chunk, the data end, the summary and the footer."""
        self._write_open_chunk()
        self._written_chunks()
        out, total = self.out, int(self.counts.sum())
        out.write(_record(_DATA_END, struct.pack("<I", out.crc)))
        statistics = _record(_STATISTICS, struct.pack(
            "<QHIIII", total, len(self.schemas), len(self.channels), 0, 0,
            len(self.chunk_indexes))
            + struct.pack("<QQ", self.first_time, self.last_time)
            + _id_map({i: int(n) for i, n in enumerate(self.counts)}))
        _write_summary(out, [(_SCHEMA, self.schemas), (_CHANNEL, self.channel_records),
                             (_STATISTICS, [statistics]), (_CHUNK_INDEX, self.chunk_indexes)])


def write_mcap(handle: BinaryIO, channels: Sequence[Channel],
               channel_ids: npt.NDArray[np.integer], sequences: npt.NDArray[np.integer],
               log_times_ns: npt.NDArray[np.integer], payloads: Payloads | Sequence[bytes], *,
               profile: str, library: str, chunk_size: int = 1 << 20) -> None:
    """Write one MCAP file of ``payloads``, which must be in ``log_times_ns`` order.

    The arguments are those of :class:`McapWriter` and :meth:`McapWriter.add`.
    """
    writer = McapWriter(handle, channels, profile=profile, library=library,
                        chunk_size=chunk_size)
    writer.add(channel_ids, sequences, log_times_ns, payloads)
    writer.finish()


def _schemas_and_channels(channels: Sequence[Channel]) -> tuple[list[bytes], list[bytes]]:
    """Schema records (one per distinct schema; ids from 1) and channel records (ids from 0)."""
    schema_ids: dict[tuple[str, str, bytes], int] = {}
    schemas, records = [], []
    for channel_id, channel in enumerate(channels):
        key = (channel.schema_name, channel.schema_encoding, channel.schema_data)
        if key not in schema_ids:
            schema_ids[key] = len(schema_ids) + 1  # 0 means "no schema"
            schemas.append(_record(_SCHEMA, struct.pack("<H", schema_ids[key])
                                   + _string(channel.schema_name)
                                   + _string(channel.schema_encoding)
                                   + struct.pack("<I", len(channel.schema_data))
                                   + channel.schema_data))
        records.append(_record(_CHANNEL, struct.pack("<HH", channel_id, schema_ids[key])
                               + _string(channel.topic) + _string(channel.message_encoding)
                               + _string_map(channel.metadata)))
    return schemas, records


class Compressor(Protocol):
    """A chunk compressor (``zstandard.ZstdCompressor``)."""

    def compress(self, data: memoryview) -> bytes:
        """``data`` compressed, as one frame."""
        ...


def _write_chunk(out: _Output, heads: np.ndarray, parts: Sequence[ByteRows],
                 offsets: npt.NDArray[np.int64], compressor: Compressor) -> bytes:
    """Write one chunk (its records in ``parts``) and its message indexes; returns its index."""
    records = (parts[0] if len(parts) == 1 else np.concatenate(parts)).data
    compressed = compressor.compress(records)
    first, last = int(heads["log_time"][0]), int(heads["log_time"][-1])
    chunk = _record(_CHUNK, struct.pack("<QQQI", first, last, len(records), zlib.crc32(records))
                    + _string("zstd") + struct.pack("<Q", len(compressed)) + compressed)
    chunk_start = out.write(chunk)
    index_offsets = {}
    for channel in np.flatnonzero(np.bincount(heads["channel"])).tolist():
        mine = heads["channel"] == channel
        entries = np.empty(int(mine.sum()), dtype=_INDEX_ENTRY)
        entries["log_time"], entries["offset"] = heads["log_time"][mine], offsets[mine]
        index_offsets[channel] = out.write(_record(
            _MESSAGE_INDEX, struct.pack("<HI", channel, entries.nbytes) + entries.tobytes()))
    index_length = out.position - chunk_start - len(chunk)
    return _record(_CHUNK_INDEX, struct.pack("<QQQQ", first, last, chunk_start, len(chunk))
                   + _id_map(index_offsets) + struct.pack("<Q", index_length) + _string("zstd")
                   + struct.pack("<QQ", len(compressed), len(records)))


def _write_summary(out: _Output, groups: list[tuple[int, list[bytes]]]) -> None:
    """The summary section, its offsets, the footer with the summary CRC, and the magic."""
    summary_start = position = out.position
    parts, offsets = [], []
    for opcode, records in groups:
        data = b"".join(records)
        offsets.append(_record(_SUMMARY_OFFSET, struct.pack("<BQQ", opcode, position, len(data))))
        parts.append(data)
        position += len(data)
    summary = b"".join(parts) + b"".join(offsets)
    # The footer's CRC covers the summary, the offsets and the footer up to the CRC itself.
    footer_head = struct.pack("<BQQQ", _FOOTER, 20, summary_start, position)
    crc = zlib.crc32(footer_head, zlib.crc32(summary))
    out.write(summary + footer_head + struct.pack("<I", crc) + MAGIC, data_section=False)
