"""Every way a port can fail to work is one clear line and exit 4 (a real pty, no mocks)."""

from __future__ import annotations

import os
import stat
import subprocess
import sys

from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.framing import encode_frame
from tests.conftest import assert_one_line_error

ONE_SHOT = ("--linear", "0.01", "--duration-s", "0.5", "--connect-timeout-s", "0.5")


def test_missing_port_lists_the_ports_that_exist(run, tmp_path, fake_device):
    fake_device()  # at least one pseudo-terminal exists
    missing = tmp_path / "ttyUSB9"
    line = assert_one_line_error(run("drive", "--port", missing, *ONE_SHOT), 4,
                                 f"port {missing} does not exist", "serial ports here:",
                                 "pseudo-terminals: /dev/pts/", "servicebot emulate")
    assert "Traceback" not in line


def test_not_a_serial_port(run, tmp_path):
    plain = tmp_path / "notes.txt"
    plain.write_text("hello")
    assert_one_line_error(run("drive", "--port", plain, *ONE_SHOT), 4, "is not a serial port")
    assert_one_line_error(run("drive", "--port", "/dev/null", *ONE_SHOT), 4,
                          "/dev/null is not a serial port")


_AS_NOBODY = """
import os, sys
from servicebot_cli.cli import main
import importlib, json, pkgutil, serial.tools.list_ports, servicebot_cli.drive  # noqa
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.drive.motors import motor_map
for module in pkgutil.walk_packages(servicebot_cli.drive.__path__, "servicebot_cli.drive."):
    importlib.import_module(module.name)  # import while readable
import servicebot_cli.output.drive_text  # noqa
motor_map(load(RobotSource.bundled("real")))
if os.geteuid() == 0:  # root opens everything: drop to nobody for a real permission check
    os.setgroups([]); os.setgid(65534); os.setuid(65534)
main(sys.argv[1:], prog_name="servicebot")
"""


def test_permission_denied_says_how_to_join_the_group(fake_device):
    device = fake_device()
    os.chmod(device.path, 0 if os.geteuid() != 0 else stat.S_IRUSR | stat.S_IWUSR)
    result = subprocess.run([sys.executable, "-c", _AS_NOBODY, "drive", "--port", device.path,
                             *ONE_SHOT], capture_output=True, text=True, timeout=60, cwd="/")
    assert_one_line_error(result, 4, f"permission denied opening {device.path}",
                          "sudo usermod -aG", "log out and back in")


def test_busy_port(run, fake_device):
    import serial

    device = fake_device()
    holder = serial.Serial(device.path, 9600, exclusive=True)
    try:
        assert_one_line_error(run("drive", "--port", device.path, *ONE_SHOT), 4,
                              f"port {device.path} is busy", "close that program")
    finally:
        holder.close()


def test_no_answer_from_the_firmware(run, fake_device):
    device = fake_device()  # mute
    assert_one_line_error(run("drive", "--port", device.path, *ONE_SHOT), 4,
                          f"no answer from the firmware on {device.path} at 9600 baud within "
                          "0.5 s", "--baud")
    assert device.received.startswith(b"\xaa\x55\x00")  # it did ask: PING frames


def test_wrong_protocol_is_named(run, fake_device):
    device = fake_device(lambda data: b"$GPGGA,123519,4807.038,N,01131.000,E*47\r\n")
    assert_one_line_error(run("drive", "--port", device.path, *ONE_SHOT), 4,
                          f"{device.path} at 9600 baud answers, but not in the servicebot protocol",
                          "try --protocol arduino")


def test_garbage_with_crc_failures_is_a_wrong_protocol(run, fake_device):
    frame = bytearray(encode_frame(msg.encode_version(1, msg.Version(1, (1, 0), 500))))
    frame[-1] ^= 0xFF  # a device that frames like us but fails every CRC
    device = fake_device(lambda data: bytes(frame))
    line = assert_one_line_error(run("drive", "--port", device.path, *ONE_SHOT), 4,
                                 "answers, but not in the servicebot protocol")
    assert "rejected" in line and " 0 rejected" not in line


def test_another_protocol_version_is_refused(run, fake_device):
    def version_2(data):
        return encode_frame(msg.encode_version(data[3], msg.Version(2, (9, 0), 500)))

    device = fake_device(version_2)
    assert_one_line_error(run("drive", "--port", device.path, *ONE_SHOT), 4,
                          "speaks servicebot protocol v2", "update one of them")


def test_arduino_protocol_against_a_silent_board(run, fake_device):
    device = fake_device()
    assert_one_line_error(run("drive", "--port", device.path, "--protocol", "arduino",
                              "--ticks-per-rev", "3436", *ONE_SHOT), 4, "no answer")
    assert device.received.startswith(b"b\r")


def test_a_port_that_dies_before_any_answer_is_a_link_error_not_a_lost_link(run):
    """A device that fails on drive's first byte, before the firmware ever answered, ended
    with 'link lost' and exit 5, the code of a link lost mid-run; no link was ever had."""
    import select
    import threading
    import tty

    master, slave = os.openpty()
    tty.setraw(slave)
    port = os.ttyname(slave)

    def die_on_first_byte() -> None:
        select.select([master], [], [], 10)
        os.read(master, 100)
        os.close(master)

    board = threading.Thread(target=die_on_first_byte, daemon=True)
    board.start()
    try:
        result = run("drive", "--port", port, *ONE_SHOT)
    finally:
        board.join(10)
        os.close(slave)
    assert_one_line_error(result, 4, f"no link: reading {port} failed")


def test_waits_beyond_a_day_are_refused_before_any_port_is_opened(run):
    """--boot-time-s 1e10 passed the option check and overflowed the clock call (exit 3)."""
    for option in ("--boot-time-s", "--link-timeout-s", "--connect-timeout-s"):
        assert_one_line_error(run("drive", "--port", "/dev/null", option, "1e10", "--linear",
                                  "0.01", "--duration-s", "0.5"), 2,
                              f"Invalid value for '{option}': 1e10 is above the maximum 86400")


def test_a_watchdog_the_protocol_cannot_carry_is_refused():
    """emulate --watchdog-ms 65536 crashed at the first PING (a 16-bit field). A process
    with a timeout: an emulator that takes the value serves until it is stopped."""
    from tests.conftest import run_servicebot

    assert_one_line_error(run_servicebot("emulate", "--watchdog-ms", "65536", timeout=30), 2,
                          "'--watchdog-ms': 65536 is not in the range 1<=x<=65535")


def test_an_empty_port_is_said_as_given(run):
    """--port "$PORT" with PORT unset was taken as no port: 'port /dev/ttyUSB0 does not
    exist', a device the user never named."""
    assert_one_line_error(run("drive", "--port", "", "--linear", "0.01", "--duration-s", "0.5"),
                          2, "'--port': an empty path")
