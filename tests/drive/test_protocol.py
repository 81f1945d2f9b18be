"""Framing: CRC, round trips at every chunking, resynchronisation, corruption."""

from __future__ import annotations

import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.framing import (
    MAX_PAYLOAD,
    OVERHEAD,
    SYNC,
    Decoder,
    Frame,
    crc16_ccitt_false,
    encode_frame,
)

FRAMES = [
    Frame(1, msg.MsgType.PING),
    Frame(2, msg.MsgType.SET_WHEELS, bytes(range(8))),
    Frame(255, msg.MsgType.TELEMETRY, bytes(range(25))),
    Frame(0, msg.MsgType.STOP),
    Frame(7, 0x42, SYNC * 16),  # a payload full of SYNC bytes must not confuse the decoder
    Frame(9, msg.MsgType.NACK, b"\xaa\xaa"),
]
STREAM = b"".join(encode_frame(f) for f in FRAMES)


def test_crc_check_value():
    assert crc16_ccitt_false(b"123456789") == 0x29B1
    assert crc16_ccitt_false(b"") == 0xFFFF


def test_frame_layout():
    data = encode_frame(Frame(3, 0x10, b"\x01\x02"))
    assert data[:2] == SYNC and data[2:5] == bytes([2, 3, 0x10]) and data[5:7] == b"\x01\x02"
    crc = crc16_ccitt_false(data[2:-2])
    assert data[-2:] == bytes([crc & 0xFF, crc >> 8]) and len(data) == OVERHEAD + 2


def test_every_chunking_of_the_stream_gives_the_same_frames():
    for size in range(1, len(STREAM) + 1):
        decoder = Decoder()
        got = []
        for i in range(0, len(STREAM), size):
            got += decoder.feed(STREAM[i:i + size])
        assert got == FRAMES, f"chunks of {size}"
        assert decoder.stats.errors == 0 and decoder.pending == 0


def test_every_split_point_of_every_frame():
    for frame in FRAMES:
        data = encode_frame(frame)
        for cut in range(len(data) + 1):
            decoder = Decoder()
            assert decoder.feed(data[:cut]) + decoder.feed(data[cut:]) == [frame]


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(1, 40), min_size=1, max_size=60), st.randoms(use_true_random=False))
def test_random_chunkings_round_trip(sizes, rng):
    stream = STREAM * 3
    decoder, got, i, k = Decoder(), [], 0, 0
    while i < len(stream):
        size = sizes[k % len(sizes)]
        got += decoder.feed(stream[i:i + size])
        i, k = i + size, k + 1
    assert got == FRAMES * 3


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=200), st.integers(1, 17))
def test_resynchronises_after_any_garbage(garbage, chunk):
    """Whatever garbage comes first, the frames after it are found (garbage that happens to
    hold a valid frame may add frames before them, never lose them)."""
    stream = garbage + STREAM
    decoder, got = Decoder(), []
    for i in range(0, len(stream), chunk):
        got += decoder.feed(stream[i:i + chunk])
    assert got[-len(FRAMES):] == FRAMES


def test_resync_inside_a_truncated_frame():
    truncated = encode_frame(FRAMES[2])[:-9]  # a frame cut short by lost bytes
    decoder = Decoder()
    assert decoder.feed(truncated + STREAM) == FRAMES
    assert decoder.stats.crc_errors >= 1


def test_oversized_length_is_rejected_at_once():
    decoder = Decoder()
    bogus = SYNC + bytes([MAX_PAYLOAD + 1, 0, 0])
    assert decoder.feed(bogus + STREAM) == FRAMES
    assert decoder.stats.bad_length == 1


def test_every_single_bit_flip_is_caught():
    for frame in FRAMES:
        data = bytearray(encode_frame(frame))
        for bit in range(16, len(data) * 8):  # the SYNC bytes are not protected, only located
            flipped = bytearray(data)
            flipped[bit // 8] ^= 1 << (bit % 8)
            assert Decoder().feed(bytes(flipped)) == [], f"bit {bit} of {frame}"


def test_random_multi_bit_corruption_is_caught():
    rng = random.Random(7)
    data = encode_frame(FRAMES[1])
    caught = 0
    for _ in range(5000):
        corrupted = bytearray(data)
        for _ in range(rng.randint(2, 4)):
            bit = rng.randrange(16, len(data) * 8)
            corrupted[bit // 8] ^= 1 << (bit % 8)
        if bytes(corrupted) == data:
            continue
        assert Decoder().feed(bytes(corrupted)) == []
        caught += 1
    assert caught > 4000


def test_encode_refuses_what_no_frame_can_hold():
    with pytest.raises(ValueError):
        encode_frame(Frame(256, 1))
    with pytest.raises(ValueError):
        encode_frame(Frame(1, 1, bytes(MAX_PAYLOAD + 1)))


def test_message_payload_round_trips():
    telemetry = msg.Telemetry((1.0, -1.0, 32.767, -32.768), (0.5, -0.5, 0.25, 0.0),
                              (0.3, -1.57, 1.57, 0.0), msg.Fault.WATCHDOG | msg.Fault.RESET)
    frame = Decoder().feed(encode_frame(msg.encode_telemetry(9, telemetry)))[0]
    assert frame.seq == 9 and msg.decode_telemetry(frame) == telemetry
    version = msg.Version(1, (2, 3), 500)
    assert msg.decode_version(msg.encode_version(1, version)) == version
    nack = msg.encode_nack(4, 0x42, msg.NackReason.UNKNOWN_TYPE)
    assert msg.decode_nack(nack) == (0x42, msg.NackReason.UNKNOWN_TYPE)


def test_wheel_positions_wrap_and_the_host_unwraps(real_motors):
    from servicebot_cli.drive.protocols.binary import BinaryLink

    link = BinaryLink(real_motors)
    positions = [30.0 + 0.5 * k for k in range(12)]  # crosses +32.768 rad
    unwrapped = []
    for k, p in enumerate(positions):
        telemetry = msg.Telemetry((p, -p, p, -p), (0.5,) * 4, (0.0,) * 4, msg.Fault(0))
        frame = encode_frame(msg.encode_telemetry(k, telemetry))
        (reading,) = link.feed(frame, 0.0)
        unwrapped.append(reading.wheel_position_rad)
    for p, got in zip(positions, unwrapped, strict=True):
        assert got == pytest.approx((p, -p, p, -p), abs=1e-3)


def test_a_wrong_payload_size_is_a_protocol_error():
    with pytest.raises(msg.ProtocolError, match="needs 8 payload bytes"):
        msg.decode_values(Frame(1, msg.MsgType.SET_WHEELS, b"\x00"))
    with pytest.raises(msg.ProtocolError, match="unknown message type"):
        msg.decode_values(Frame(1, 0x42, b""))
