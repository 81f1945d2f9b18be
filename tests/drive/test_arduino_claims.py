"""What a ROSArduinoBridge board says of itself is checked, and what it can carry bounded.

The 'b' reply named a baud the link does not run at (a firmware built for 57600 on a 9600
link, or a byte of ' 9600' lost on the way) and was printed as fact; 'm' speeds beyond an
AVR int (atoi, 16 bits) were sent, where the board wraps them to another speed.
"""

from __future__ import annotations

from tests.drive.conftest import finish, servicebot

ARDUINO = ("--protocol", "arduino", "--ticks-per-rev", "3436")


def test_a_firmware_baud_other_than_the_links_is_a_warning(emulator):
    emu = emulator(*ARDUINO, "--baud", "57600")
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, *ARDUINO, "--baud", "9600",
                                        "--linear", "0.02", "--duration-s", "0.5"))
    assert code == 0, stderr
    assert "warning: the firmware says it runs at 57600 baud, the port at 9600" in stderr


def test_the_same_baud_says_nothing(emulator):
    emu = emulator(*ARDUINO, "--baud", "9600")
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, *ARDUINO, "--baud", "9600",
                                        "--linear", "0.02", "--duration-s", "0.5"))
    assert code == 0 and "warning" not in stderr, stderr


def test_speeds_beyond_an_avr_int_are_refused(run):
    result = run("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "1e9",
                 "--linear", "0.02", "--duration-s", "0.1")
    assert result.exit_code == 2
    assert "ticks a PID frame: ROSArduinoBridge reads 'm' with atoi into an int, at most " \
        "32767" in result.output
    fine = run("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "3436",
               "--linear", "0.02", "--duration-s", "0.1")
    assert fine.exit_code == 0, fine.output


def test_a_log_that_is_the_port_is_refused_before_anything_is_sent(emulator):
    """--log /dev/pts/N passed the suffix check (a device) and wrote the CSV into the port:
    1041 bytes of text to the motor controller."""
    emu = emulator()
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, "--linear", "0.02",
                                        "--duration-s", "0.3", "--log", emu.path))
    assert code == 2, stderr
    assert "is the serial port" in stderr and "the log's rows would go to the motor" in stderr
    assert emu.state()["counters"]["first_command"] is None
