"""The bulk MCAP writer, read back by the reference implementation (the ``mcap`` package)."""

from __future__ import annotations

import io
import zlib

import numpy as np
import pytest
from mcap.reader import make_reader
from mcap.stream_reader import StreamReader

from servicebot_cli.simulate.bag.mcap_file import MAGIC, Channel, write_mcap

CHANNELS = [
    Channel("/a", "cdr", "pkg/A", "ros2msg", b"int32 x", {"k": "v"}),
    Channel("/b", "cdr", "pkg/B", "ros2msg", b"float64 y"),
    Channel("/c", "cdr", "pkg/A", "ros2msg", b"int32 x"),  # shares /a's schema
    Channel("/quiet", "cdr", "pkg/B", "ros2msg", b"float64 y"),  # no messages
]


def _write(channel_ids, times, payloads, chunk_size=1 << 20) -> bytes:
    buffer = io.BytesIO()
    sequences = np.zeros(len(payloads), dtype=np.uint32)
    for channel in set(channel_ids):
        mine = np.flatnonzero(np.asarray(channel_ids) == channel)
        sequences[mine] = np.arange(len(mine))
    write_mcap(buffer, CHANNELS, np.asarray(channel_ids, dtype=np.uint16), sequences,
               np.asarray(times, dtype=np.uint64), payloads, profile="ros2", library="test",
               chunk_size=chunk_size)
    return buffer.getvalue()


@pytest.mark.parametrize("chunk_size", [64, 1000, 1 << 20])
def test_messages_schemas_and_indexes_read_back(chunk_size):
    rng = np.random.default_rng(4)
    n = 500
    channel_ids = rng.integers(0, 3, n).tolist()
    times = np.cumsum(rng.integers(0, 3, n)).tolist()  # repeated stamps included
    payloads = [bytes(rng.integers(0, 256, rng.integers(0, 40), dtype=np.uint8)) for _ in range(n)]
    data = _write(channel_ids, times, payloads, chunk_size)
    assert data.startswith(MAGIC) and data.endswith(MAGIC)
    reader = make_reader(io.BytesIO(data))
    summary = reader.get_summary()
    assert summary.statistics.message_count == n
    assert summary.statistics.channel_message_counts == {
        i: channel_ids.count(i) for i in range(len(CHANNELS))}
    assert len(summary.schemas) == 2 and len(summary.channels) == 4
    assert summary.channels[0].metadata == {"k": "v"}
    assert (len(summary.chunk_indexes) == 1) == (chunk_size == 1 << 20)
    read = [(ch.topic, sch.name, m.log_time, m.sequence, m.data)
            for sch, ch, m in reader.iter_messages()]
    expected = [(CHANNELS[c].topic, CHANNELS[c].schema_name, t, None, p)
                for c, t, p in zip(channel_ids, times, payloads, strict=True)]
    assert [r[:3] + r[4:] for r in read] == [e[:3] + e[4:] for e in expected]
    only_b = [m.data for _, _, m in reader.iter_messages(topics=["/b"])]
    assert only_b == [p for c, p in zip(channel_ids, payloads, strict=True) if c == 1]


def test_every_crc_validates():
    data = _write([0, 1, 2, 0], [1, 2, 3, 4], [b"x", b"yy", b"", b"zzz"], chunk_size=20)
    records = list(StreamReader(io.BytesIO(data), validate_crcs=True).records)
    footer = records[-1]
    assert type(footer).__name__ == "Footer"
    # The footer's CRC covers the summary, its offsets and the footer up to the CRC field.
    assert footer.summary_crc == zlib.crc32(data[footer.summary_start:-len(MAGIC) - 4])
    # A chunk whose CRC does not match its records is refused by the reference reader.
    first_chunk = make_reader(io.BytesIO(data)).get_summary().chunk_indexes[0]
    crc_at = first_chunk.chunk_start_offset + 1 + 8 + 8 + 8 + 8  # opcode, length, 3 x u64
    broken = bytearray(data)
    broken[crc_at] ^= 0x01
    with pytest.raises(Exception, match="(?i)crc"):
        list(StreamReader(io.BytesIO(bytes(broken)), validate_crcs=True).records)


def test_no_messages_is_a_valid_file():
    data = _write([], [], [])
    summary = make_reader(io.BytesIO(data)).get_summary()
    assert summary.statistics.message_count == 0 and len(summary.channels) == 4


def test_messages_added_in_batches_give_the_same_file():
    from servicebot_cli.simulate.bag.mcap_file import McapWriter

    rng = np.random.default_rng(9)
    n = 400
    channel_ids = rng.integers(0, 3, n)
    times = np.cumsum(rng.integers(0, 3, n)).astype(np.uint64)
    payloads = [bytes(rng.integers(0, 256, rng.integers(0, 60), dtype=np.uint8))
                for _ in range(n)]
    whole = _write(channel_ids.tolist(), times.tolist(), payloads, chunk_size=500)
    sequences = np.zeros(n, dtype=np.uint32)
    for channel in range(3):
        mine = np.flatnonzero(channel_ids == channel)
        sequences[mine] = np.arange(len(mine))
    buffer = io.BytesIO()
    writer = McapWriter(buffer, CHANNELS, profile="ros2", library="test", chunk_size=500)
    cuts = [0, 0, 1, 17, 17, 150, 151, 399, n]  # empty batches, single messages, long ones
    for a, b in zip(cuts, cuts[1:], strict=False):
        writer.add(channel_ids[a:b].astype(np.uint16), sequences[a:b], times[a:b],
                   payloads[a:b])
    writer.finish()
    assert buffer.getvalue() == whole
    assert len(make_reader(io.BytesIO(whole)).get_summary().chunk_indexes) > 3


def test_payloads_as_rows_in_any_order_give_the_same_file():
    from servicebot_cli.simulate.bag.byte_rows import Payloads

    rng = np.random.default_rng(11)
    n = 300
    channel_ids = rng.integers(0, 3, n).tolist()
    times = np.cumsum(rng.integers(0, 3, n)).tolist()
    widths = [0, 5, 40]  # an empty payload, short and long ones
    blocks = [rng.integers(0, 256, (n, w), dtype=np.uint8) for w in widths]
    block = rng.integers(0, 3, n)
    row = rng.permutation(n)  # rows taken out of order, some never
    payloads = [bytes(blocks[b][r]) for b, r in zip(block, row, strict=True)]
    as_bytes = _write(channel_ids, times, payloads, chunk_size=700)
    buffer = io.BytesIO()
    sequences = np.zeros(n, dtype=np.uint32)
    for channel in set(channel_ids):
        mine = np.flatnonzero(np.asarray(channel_ids) == channel)
        sequences[mine] = np.arange(len(mine))
    write_mcap(buffer, CHANNELS, np.asarray(channel_ids, dtype=np.uint16), sequences,
               np.asarray(times, dtype=np.uint64), Payloads(blocks, block, row),
               profile="ros2", library="test", chunk_size=700)
    assert buffer.getvalue() == as_bytes
    read = [m.data for _, _, m in make_reader(io.BytesIO(as_bytes)).iter_messages()]
    assert read == payloads
