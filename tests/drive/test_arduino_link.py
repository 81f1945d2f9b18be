"""ROSArduinoBridge replies on a noisy link: parsed defensively, re-aligned, checked."""

from __future__ import annotations

import random

import pytest
from hypothesis import given
from hypothesis import strategies as st

from servicebot_cli.drive.protocols.arduino import ArduinoConfig, ArduinoLink
from servicebot_cli.drive.protocols.arduino_replies import LineSplitter, classify
from servicebot_cli.drive.protocols.events import Ack, Hello, Reading, Refused


@pytest.fixture
def link(real_motors):
    return ArduinoLink(real_motors, ArduinoConfig(3436, 30.0))


@pytest.mark.parametrize("line", [b"--82", b"-+231", b"+5 3", b"12 3 4", b"1\xb2 3", b"O K",
                                  b"99999999999 1", b"-2147483649 0", b"\x00\xff"])
def test_garbled_lines_are_classified_never_raised(line):
    assert classify(line).kind == "garbled"


def test_good_lines(link):
    assert classify(b"OK").kind == "ok" and classify(b" 9600").values == (9600,)
    assert classify(b"-2147483648 2147483647").values == (-2**31, 2**31 - 1)
    assert classify(b"Invalid Command").kind == "refused"


@given(st.binary(max_size=200))
def test_any_bytes_are_events_or_counted_errors(data):
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.drive.motors import motor_map

    link = ArduinoLink(motor_map(load(RobotSource.bundled("real"))), ArduinoConfig(3436))
    for _ in range(3):
        link.wheels([0.1] * 4)
    events = link.feed(data, 1.0) + link.feed(b"\r\n", 2.0)
    assert all(isinstance(e, Ack | Reading | Refused | Hello) for e in events)


def test_a_lost_cr_or_lf_never_glues_two_replies():
    splitter = LineSplitter()
    assert splitter.feed(b"OK\r12 34\n5 6\r") == [b"OK", b"12 34", b"5 6"]


def test_replies_realign_after_a_lost_ok_and_an_invalid_command(link):
    tokens = [link.wheels([0.2] * 4)[1] for _ in range(4)]
    # 1: OK lost; 2: answered normally; 3: its `m` garbled into Invalid Command; 4: normal
    events = link.feed(b"10 10\r\nOK\r\n20 20\r\nInvalid Command\r\n30 30\r\n"
                       b"OK\r\n40 40\r\n", 1.0)
    acks = [e.token for e in events if isinstance(e, Ack)]
    readings = [e.ack for e in events if isinstance(e, Reading)]
    assert acks == [tokens[1], tokens[3]]
    assert readings == tokens
    assert any(isinstance(e, Refused) and "to m" in e.reason for e in events)


def test_an_encoder_jump_beyond_the_wheel_limit_is_rejected_and_counted(link):
    token = link.wheels([0.5] * 4)[1]
    link.feed(b"OK\r\n1000 1000\r\n", 1.0)
    link.wheels([0.5] * 4)
    before = link.errors
    # 50 ms later: at most 0.5 rad/s * 547 ticks/rad * 1.5 * (0.05 + 0.1) s + 2 = 63 ticks
    assert [e for e in link.feed(b"OK\r\n1080 1000\r\n", 1.05) if isinstance(e, Reading)] == []
    assert link.jumps == 1 and link.errors == before + 1
    link.wheels([0.5] * 4)
    good = [e for e in link.feed(b"OK\r\n1030 1030\r\n", 1.10) if isinstance(e, Reading)]
    assert len(good) == 1 and token < good[0].ack


def test_three_consistent_jumps_are_a_new_baseline_without_a_jump_in_travel(link):
    link.wheels([0.0] * 4)
    first = link.feed(b"OK\r\n5000 5000\r\n", 1.0)[-1]
    out = []
    for i, t in enumerate((1.05, 1.10, 1.15, 1.20)):
        link.wheels([0.0] * 4)
        out += [e for e in link.feed(f"OK\r\n{i} {i}\r\n".encode(), t) if isinstance(e, Reading)]
    assert len(out) == 1 and out[0].wheel_position_rad[0] == pytest.approx(
        first.wheel_position_rad[0] + 1 / link.config.ticks_per_rad)


def test_a_stop_is_confirmed_by_counts_that_stop_changing(link):
    stop_tokens = set()
    counts = [100, 104, 108, 108, 109, 108, 108]  # `m 0 0` garbled once, then still
    for i, c in enumerate(counts):
        stop_tokens.add(link.stop()[1])
        link.feed(f"OK\r\n{c} {c}\r\n".encode(), 1.0 + 0.05 * i)
        if i < 5:
            assert not link.still(stop_tokens, 1.0 + 0.05 * i)
    assert link.still(stop_tokens, 1.3)


def test_an_ok_alone_never_confirms_a_stop(link):
    token = link.stop()[1]
    link.feed(b"OK\r\n", 1.0)
    assert not link.still({token}, 5.0)


def test_the_real_pid_interval_keeps_every_command_within_the_limit():
    for n in range(100, 20000, 7):
        config = ArduinoConfig(n, 30.0)
        assert config.speed_rad_s(config.max_ticks(0.5)) <= 0.5


def test_random_noise_never_raises(link):
    rng = random.Random(4)
    clean = b"".join(b"OK\r\n%d %d\r\n" % (i * 9, -i * 9) for i in range(200))
    for _ in range(50):
        noisy = bytearray(clean)
        for _ in range(20):
            i = rng.randrange(len(noisy))
            noisy[i] ^= 1 << rng.randrange(8)
        for _ in range(200):
            link.wheels([0.1] * 4)
        link.feed(bytes(noisy), 1.0)
    assert link.errors > 0


def _arduino_board(refuse_all: bool):
    """A ROSArduinoBridge-like responder: `b` answers its baud, the rest as asked."""
    buffer = bytearray()

    def respond(data: bytes) -> bytes:
        buffer.extend(data)
        out = b""
        while b"\r" in buffer:
            line, _, rest = bytes(buffer).partition(b"\r")
            buffer[:] = rest
            if line.strip() == b"b":
                out += b" 9600\r\n"
            elif line.strip():
                out += b"Invalid Command\r\n" if refuse_all else b"OK\r\n"
        return out

    return respond


def test_a_board_built_without_its_base_controller_fails_in_one_line(fake_device, tmp_path):
    from tests.drive.conftest import finish, servicebot

    device = fake_device(_arduino_board(refuse_all=True))
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", device.path, "--protocol", "arduino", "--ticks-per-rev", "3436",
        "--linear", "0.02", "--duration-s", "3", "--format", "json"))
    assert code == 4, stderr
    errors = [line for line in stderr.splitlines() if line.startswith("Error:")]
    assert len(errors) == 1 and "rebuild ROSArduinoBridge with USE_BASE" in errors[0]
    assert "AUTO_STOP_INTERVAL" in errors[0]  # the stop could not be confirmed either
    assert stderr.count("drive: firmware answered") == 1  # one refusal is logged, not 84
    import json

    assert json.loads(stdout)["outcome"] == "link_error"


def test_forgetting_protocol_arduino_gets_a_protocol_hint(fake_device):
    from tests.drive.conftest import finish, servicebot

    device = fake_device(_arduino_board(refuse_all=False))
    code, _, stderr = finish(servicebot("drive", "--port", device.path, "--linear", "0.02",
                                        "--duration-s", "1", "--connect-timeout-s", "0.6"))
    assert code == 4, stderr
    assert "speaks the ROSArduinoBridge protocol, not the servicebot protocol: give " \
        "--protocol arduino --ticks-per-rev N" in stderr


def test_a_board_that_says_ok_but_whose_encoders_never_settle_is_unconfirmed(fake_device):
    """`OK` to everything, counts that keep growing: drive must not claim the stop."""
    from tests.drive.conftest import finish, servicebot

    count = [0]
    ok = _arduino_board(refuse_all=False)

    def respond(data: bytes) -> bytes:
        out = ok(data)
        lines = out.split(b"\r\n")
        fixed = []
        for line, sent in zip(lines, data.split(b"\r"), strict=False):
            if sent.strip() == b"e":
                count[0] += 5
                line = b"%d %d" % (count[0], count[0])
            fixed.append(line)
        return b"\r\n".join(fixed + lines[len(fixed):])

    device = fake_device(respond)
    code, _, stderr = finish(servicebot(
        "drive", "--port", device.path, "--protocol", "arduino", "--ticks-per-rev", "3436",
        "--linear", "0.02", "--duration-s", "0.5"))
    assert code == 4, stderr
    assert "Error: stop not confirmed:" in stderr and "encoder counts that stop changing" \
        in stderr and "AUTO_STOP_INTERVAL" in stderr
    assert "motors stopped" not in stderr
