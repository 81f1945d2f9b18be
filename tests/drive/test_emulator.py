"""The emulated controller as a pure state machine: encoders, watchdog, CRC, arm, wire."""

from __future__ import annotations

import random

import pytest

from servicebot_cli.drive.emulator.arduino_firmware import ArduinoFirmware
from servicebot_cli.drive.emulator.firmware import BinaryFirmware, MotorModel
from servicebot_cli.drive.emulator.wire import FaultInjector, Faults, PacedQueue, byte_time_s
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.arduino import ArduinoConfig
from servicebot_cli.drive.protocols.binary import BinaryLink
from servicebot_cli.drive.protocols.framing import Decoder, Frame, encode_frame


@pytest.fixture
def firmware(real_motors):
    return BinaryFirmware(MotorModel(real_motors, 0.5))


def replies(data):
    return Decoder().feed(data)


def test_encoders_integrate_the_commanded_speeds_exactly(firmware, real_motors):
    host = BinaryLink(real_motors)
    firmware.receive(host.wheels([0.5, 0.5, -0.25, 0.25])[0], 1.0)
    firmware.receive(host.wheels([0.1, 0.1, 0.1, 0.1])[0], 1.4)
    firmware.receive(host.stop()[0], 1.6)
    firmware.model.advance(5.0)
    assert firmware.model.wheel_position_rad == pytest.approx(
        [0.5 * 0.4 + 0.02, 0.5 * 0.4 + 0.02, -0.1 + 0.02, 0.1 + 0.02])


def test_every_frame_gets_one_reply_with_its_seq(firmware, real_motors):
    host = BinaryLink(real_motors)
    frames = [host.hello(), host.wheels([0.1] * 4)[0], host.arm([0.2] * 4)[0], host.stop()[0]]
    got = replies(firmware.receive(b"".join(frames), 0.1))
    assert [f.seq for f in got] == [1, 2, 3, 4]
    assert [msg.MsgType(f.type).name for f in got] == ["VERSION", "TELEMETRY", "TELEMETRY",
                                                       "TELEMETRY"]
    assert msg.decode_telemetry(got[1]).faults & msg.Fault.RESET  # first telemetry after boot


def test_the_watchdog_stops_the_wheels_at_its_exact_deadline(firmware, real_motors):
    host = BinaryLink(real_motors)
    firmware.receive(host.wheels([0.4] * 4)[0], 10.0)
    firmware.model.advance(12.0)  # checked late: the stop still happened at 10.5
    assert firmware.model.wheel_velocity_rad_s == [0.0] * 4
    assert firmware.model.wheel_position_rad == pytest.approx([0.4 * 0.5] * 4)
    assert firmware.model.counters.watchdog_trips == 1
    reply = replies(firmware.receive(host.arm([0.0] * 4)[0], 12.1))[0]
    assert msg.decode_telemetry(reply).faults & msg.Fault.WATCHDOG


def test_only_motion_commands_feed_the_watchdog(firmware, real_motors):
    host = BinaryLink(real_motors)
    firmware.receive(host.wheels([0.4] * 4)[0], 0.0)
    for t in (0.2, 0.4, 0.6, 0.8):  # a host that only pings does not keep the robot driving
        firmware.receive(host.hello(), t)
    assert firmware.model.wheel_velocity_rad_s == [0.0] * 4
    firmware.receive(host.wheels([0.4] * 4)[0], 1.0)
    for t in (1.3, 1.6, 1.9):
        firmware.receive(host.wheels([0.4] * 4)[0], t)
    firmware.model.advance(2.2)
    assert firmware.model.wheel_velocity_rad_s == [0.4] * 4


def test_corrupted_frames_never_move_a_motor(firmware, real_motors):
    data = bytearray(BinaryLink(real_motors).wheels([0.5] * 4)[0])
    for bit in range(16, len(data) * 8):
        corrupted = bytearray(data)
        corrupted[bit // 8] ^= 1 << (bit % 8)
        assert firmware.receive(bytes(corrupted), 0.0) == b""
    firmware.model.advance(0.4)
    assert firmware.model.wheel_velocity_rad_s == [0.0] * 4
    assert firmware.model.wheel_position_rad == [0.0] * 4
    assert firmware.model.counters.commands == 0
    assert firmware.decoder.stats.crc_errors > 0


def test_unknown_types_and_wrong_lengths_are_refused(firmware):
    got = replies(firmware.receive(encode_frame(Frame(5, 0x42)) + encode_frame(
        Frame(6, msg.MsgType.SET_WHEELS, b"\x00\x00")), 0.0))
    assert [msg.decode_nack(f) for f in got] == [(0x42, msg.NackReason.UNKNOWN_TYPE),
                                                 (msg.MsgType.SET_WHEELS,
                                                  msg.NackReason.BAD_LENGTH)]
    assert firmware.model.wheel_velocity_rad_s == [0.0] * 4


def test_the_arm_moves_to_its_target_at_its_velocity_limit(real_motors):
    firmware = BinaryFirmware(MotorModel(real_motors, watchdog_s=10.0))
    host = BinaryLink(real_motors)
    firmware.receive(host.arm([1.0, -0.5, 0.0, 1.57])[0], 0.0)
    firmware.model.advance(0.25)
    assert firmware.model.arm_position_rad == pytest.approx([0.25, -0.25, 0.0, 0.25])
    firmware.model.advance(2.0)
    assert firmware.model.arm_position_rad == pytest.approx([1.0, -0.5, 0.0, 1.57])


def test_the_watchdog_also_holds_a_moving_arm(firmware, real_motors):
    firmware.receive(BinaryLink(real_motors).arm([1.0, 0.0, 0.0, 0.0])[0], 0.0)
    firmware.model.advance(3.0)
    assert firmware.model.arm_position_rad[0] == pytest.approx(0.5)  # 1 rad/s for 500 ms


def test_stop_holds_the_arm_where_it_is(firmware, real_motors):
    host = BinaryLink(real_motors)
    firmware.receive(host.arm([1.0, 0.0, 0.0, 0.0])[0], 0.0)
    firmware.receive(host.stop()[0], 0.5)
    firmware.model.advance(3.0)
    assert firmware.model.arm_position_rad[0] == pytest.approx(0.5)


def test_arduino_firmware_speaks_like_the_stock_one(real_motors):
    model = MotorModel(real_motors, 2.0)
    arduino = ArduinoFirmware(model, ArduinoConfig(3436, 30.0), 9600)
    assert arduino.receive(b"b\r", 0.0) == b" 9600\r\n"
    assert arduino.receive(b"m 9 -9\r", 0.0) == b"OK\r\n"
    assert arduino.receive(b"e\r", 1.0) == b"273 -273\r\n"  # 9 ticks per 33 ms, for 1 s
    assert arduino.receive(b"r\r", 1.0) == b"OK\r\n"
    assert arduino.receive(b"e\r", 1.0) == b"0 0\r\n"
    assert arduino.receive(b"u 20:12:0:50\r", 1.0) == b"OK\r\n"
    assert arduino.receive(b"s 3 90\r", 1.0) == b"Invalid Command\r\n"
    assert arduino.receive(b"m 50 50\r", 1.0) == b"OK\r\n"  # beyond the limit: clamped
    assert max(model.wheel_velocity_rad_s) <= 0.5
    assert arduino.receive(b"m 0", 1.0) + arduino.receive(b" 0\r", 1.0) == b"OK\r\n"
    assert model.wheel_velocity_rad_s == [0.0] * 4


def test_arduino_auto_stop(real_motors):
    model = MotorModel(real_motors, 2.0)
    arduino = ArduinoFirmware(model, ArduinoConfig(3436, 30.0), 9600)
    arduino.receive(b"m 5 5\r", 0.0)
    model.advance(2.5)
    assert model.wheel_velocity_rad_s == [0.0] * 4 and model.counters.watchdog_trips == 1


def test_paced_queue_releases_one_byte_per_byte_time():
    per_byte = byte_time_s(9600)
    assert per_byte == pytest.approx(1 / 960)
    queue = PacedQueue(per_byte)
    queue.push(b"x" * 96, 0.0)
    assert queue.pop(0.0) == b""
    assert len(queue.pop(0.05)) == 48  # 50 ms carry 48 bytes at 9600 baud
    assert len(queue.pop(0.1)) == 48
    assert queue.next_due_s() is None


def test_unpaced_queue_honours_ready_times():
    queue = PacedQueue()
    queue.push(b"ab", 0.2)
    assert queue.pop(0.1) == b"" and queue.pop(0.2) == b"ab"


def test_fault_injector_drops_and_corrupts_at_the_asked_rates():
    injector = FaultInjector(Faults(drop=0.1, corrupt=0.1), random.Random(3))
    data = bytes(20000)
    out = injector.apply(data)
    assert 1600 < injector.dropped < 2400 and 1400 < injector.corrupted < 2200
    assert len(out) == len(data) - injector.dropped
    assert sum(1 for b in out if b) == injector.corrupted
