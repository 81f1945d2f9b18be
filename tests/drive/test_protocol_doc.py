"""docs/serial-protocol.md is the firmware author's contract: its numbers must be the code's."""

from __future__ import annotations

import re
import struct

from servicebot_cli.drive.link_setup import link_capacity_hz
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.arduino import ArduinoConfig
from servicebot_cli.drive.protocols.binary import BinaryLink
from servicebot_cli.drive.protocols.framing import (
    MAX_PAYLOAD,
    OVERHEAD,
    Decoder,
    Frame,
    encode_frame,
)
from tests.conftest import REPO

DOC = (REPO / "docs" / "serial-protocol.md").read_text()
FORMATS = {"PING": "", "STOP": "", "SET_WHEELS": "<4h", "SET_ARM": "<4h", "VERSION": "<BBBH",
           "TELEMETRY": "<4h4h4hB", "NACK": "<BB"}


def vectors():
    block = DOC.split("<!-- vectors: start -->")[1].split("<!-- vectors: end -->")[0]
    rows = re.findall(r"^\| (\w+) \| (\d+) \| ([^|]*) \| `([0-9a-f ]+)` \|$", block, re.M)
    assert len(rows) >= 8
    return rows


def test_every_vector_is_what_the_code_encodes_and_decodes():
    for name, seq, values, hex_bytes in vectors():
        wire = bytes.fromhex(hex_bytes)
        numbers = [int(v) for v in values.split()] if values.strip() != "-" else []
        fmt = FORMATS[name]
        payload = struct.pack(fmt, *numbers) if fmt else b""
        frame = Frame(int(seq), msg.MsgType[name], payload)
        assert encode_frame(frame) == wire, name
        assert Decoder().feed(wire) == [frame], name


def test_the_crc_check_value_in_the_doc():
    assert "`123456789` is **`0x29B1`**" in DOC


def test_frame_sizes_table_matches_the_code():
    for name, size in msg.PAYLOAD_SIZE.items():
        row = re.search(rf"^\| `0x{int(name):02X}` \| {name.name} \|.*\| (\d+) \| (\d+) \|$",
                        DOC, re.M)
        assert row, name.name
        assert (int(row.group(1)), int(row.group(2))) == (size, size + OVERHEAD), name.name
    assert "LEN | payload length in bytes, 0 to 32" in DOC and MAX_PAYLOAD == 32


def test_the_sizing_arithmetic(real_motors):
    link = BinaryLink(real_motors)
    assert (link.command_bytes, link.reply_bytes) == (15, 32)
    assert link_capacity_hz(link, 9600) == 30.0
    assert "| 15 | 300 B/s | **31 %** |" in DOC and "| 32 | 640 B/s | **67 %** |" in DOC
    assert "960 / 32 = **30 commands per second**" in DOC


def test_the_arduino_example_numbers(real_motors):
    config = ArduinoConfig(3436, 30.0)
    assert config.pid_interval_s == 0.033  # the firmware's integer 1000 / 30
    assert round(config.ticks_per_frame(0.5), 2) == 9.02
    assert config.max_ticks(real_motors.max_wheel_rad_s) == 9
    assert round(config.speed_rad_s(9), 3) == 0.499 and round(config.speed_rad_s(1), 3) == 0.055
    assert "0.5 rad/s is 9.02 ticks, sent as 9 (0.499 rad/s); one tick is 0.055 rad/s" in DOC
    coarse = ArduinoConfig(3400, 30.0)  # 9 ticks would be 0.504 rad/s at the real 33 ms
    assert coarse.max_ticks(0.5) == 8 and round(coarse.speed_rad_s(8), 3) == 0.448
    assert "With N = 3400, 9 ticks would be 0.504 rad/s: 8 is sent (0.448 rad/s)" in DOC


def test_the_watchdog_contract_is_stated_and_emulated(real_motors):
    from servicebot_cli.drive.emulator.firmware import BinaryFirmware, MotorModel

    assert "for 500 ms** (it may use a shorter timeout, never a longer one" in DOC
    firmware = BinaryFirmware(MotorModel(real_motors, 0.5))
    reply = firmware.receive(encode_frame(Frame(1, msg.MsgType.PING)), 0.0)
    assert msg.decode_version(Decoder().feed(reply)[0]).watchdog_ms == 500
