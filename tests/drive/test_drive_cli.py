"""drive's options, defaults and --dry-run, in process: nothing here opens a port."""

from __future__ import annotations

import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.drive.link_setup import serial_defaults
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.framing import Decoder
from tests.conftest import REAL_URDF, assert_one_line_error

ONE_SHOT = ("--linear", "0.02", "--duration-s", "1")


def frames_of(stdout):
    lines = [ln for ln in stdout.splitlines() if not ln.startswith("#")]
    return [(float(ln.split()[0]), Decoder().feed(bytes.fromhex(ln.split("  ")[2]))[0])
            for ln in lines]


def test_port_and_baud_come_from_the_real_urdf():
    assert serial_defaults(load(RobotSource.bundled("real"))) == ("/dev/ttyUSB0", 9600)
    assert serial_defaults(load(RobotSource.bundled("sim"))) == (None, None)


def test_the_descriptions_port_is_the_default(run, tmp_path):
    port = tmp_path / "ttyBOARD"
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(REAL_URDF.read_text().replace("/dev/ttyUSB0", str(port)))
    assert_one_line_error(run("drive", urdf, *ONE_SHOT), 4, f"port {port} does not exist")
    other = tmp_path / "ttyOTHER"
    assert_one_line_error(run("drive", urdf, "--port", other, *ONE_SHOT), 4, f"port {other}")


def test_the_descriptions_baud_is_the_default(run, tmp_path):
    urdf = tmp_path / "slow.urdf"
    urdf.write_text(REAL_URDF.read_text().replace(
        '<param name="baud_rate">9600</param>', '<param name="baud_rate">4800</param>'))
    assert_one_line_error(run("drive", urdf, "--dry-run", *ONE_SHOT), 2,
                          "20 Hz needs 640 bytes/s one way",
                          "4800 baud carries 480; at most 15.0 Hz")
    assert run("drive", urdf, "--dry-run", "--baud", "9600", *ONE_SHOT).exit_code == 0


def test_a_description_without_a_port_needs_one(run):
    assert_one_line_error(run("drive", "--robot", "sim", *ONE_SHOT), 2,
                          "names no serial port", "give --port")


def test_dry_run_prints_the_frames_without_a_port(run, real_motors):
    result = run("drive", "--dry-run", "--linear", "0.05", "--angular", "0.02",
                 "--duration-s", "1.5", "--arm", "arm_base_to_link1=0.4")
    assert result.exit_code == 0, result.stderr
    frames = frames_of(result.stdout)
    kinds = [msg.MsgType(f.type).name for _, f in frames]
    assert kinds[0] == "PING" and kinds[-1] == "STOP" and kinds.count("SET_ARM") == 1
    assert len(frames) == 1 + 30 + 1  # handshake, 1.5 s at 20 Hz, stop
    assert [f.seq for _, f in frames] == list(range(1, 33))
    wheels = [msg.decode_values(f) for _, f in frames if f.type == msg.MsgType.SET_WHEELS]
    assert all(abs(v) <= 0.5 for speeds in wheels for v in speeds)
    assert wheels[0][1] > wheels[0][0] > 0  # turning left: the right side is faster
    for before, after in zip(wheels, wheels[1:], strict=False):  # 1 rad/s^2 at 20 Hz
        assert all(abs(a - b) <= 0.1 + 1e-3 for a, b in zip(before, after, strict=True))
    arm = next(f for _, f in frames if f.type == msg.MsgType.SET_ARM)
    assert msg.decode_values(arm) == (0.4, 0.0, 0.0, 0.0)
    assert "SET_ARM seq=2 [+0.400 +0.000 +0.000 +0.000] rad" in result.stdout


def test_dry_run_of_the_arduino_protocol(run):
    result = run("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "3436",
                 "--linear", "0.05", "--duration-s", "1")
    assert result.exit_code == 0, result.stderr
    lines = [ln for ln in result.stdout.splitlines() if not ln.startswith("#")]
    assert "'b'" in lines[0] and "'m 9 9': left +0.499 rad/s" in result.stdout
    assert lines[-1].endswith("'m 0 0': left +0.000 rad/s, right +0.000 rad/s; 'e'")


@pytest.mark.parametrize(("args", "needles"), [
    (("--rate", "31"), ("Invalid value for --rate", "at most 30.0 Hz")),
    (("--rate", "2"), ("too slow to keep the firmware's watchdog fed",)),
    (("--rate", "abc"), ("'abc' is not a number",)),
    (("--angular", "inf"), ("not a finite number",)),
    (("--rate", "-1"), ("must be above 0",)),
])
def test_bad_numbers(run, args, needles):
    base = ("--linear", "0.02", "--duration-s", "1")
    assert_one_line_error(run("drive", "--dry-run", *base, *args), 2, *needles)


def test_a_link_timeout_shorter_than_two_periods_fails_before_the_port_opens(run, fake_device):
    device = fake_device()
    assert_one_line_error(run("drive", "--port", device.path, "--rate", "20",
                              "--link-timeout-s", "0.05", *ONE_SHOT), 2,
                          "Invalid value for --link-timeout-s", "shorter than two command periods")
    assert device.received == b""


def test_a_rate_close_to_the_limit_warns(run):
    result = run("drive", "--dry-run", "--rate", "25", *ONE_SHOT)
    assert result.exit_code == 0
    assert "warning: 25 Hz uses 83% of the 9600-baud link" in result.stderr


def test_modes_do_not_mix(run, tmp_path):
    script = tmp_path / "s.txt"
    script.write_text("stop 1\n")
    assert_one_line_error(run("drive", "--script", script, "--linear", "0.1"), 2, "not both")
    assert_one_line_error(run("drive", "--linear", "0.1"), 2, "--duration-s", "needed")


def test_teleop_needs_a_terminal(run):
    assert_one_line_error(run("drive", input=""), 2, "teleop needs a terminal on stdin",
                          "--script FILE")


def test_arm_targets_are_checked_against_the_urdf(run):
    assert_one_line_error(run("drive", "--dry-run", "--duration-s", "1", "--arm",
                              "arm_base_to_link1=1.6"), 2, "outside its limits [-1.57, 1.57]")
    assert_one_line_error(run("drive", "--dry-run", "--duration-s", "1", "--arm",
                              "arm_base_to_lnk1=0.1"), 2, "did you mean 'arm_base_to_link1'")


def test_a_log_in_a_missing_directory_fails_before_the_port_opens(run, tmp_path, fake_device):
    device = fake_device()
    log = tmp_path / "missing" / "run.csv"
    assert_one_line_error(run("drive", "--port", device.path, "--log", log, *ONE_SHOT), 2,
                          "directory", "does not exist")
    assert device.received == b""  # nothing was sent


def test_a_run_that_never_connected_leaves_no_log(run, tmp_path, fake_device):
    device = fake_device()
    log = tmp_path / "run.csv"
    result = run("drive", "--port", device.path, "--log", log, "--connect-timeout-s", "0.3",
                 *ONE_SHOT)
    assert result.exit_code == 4
    assert list(tmp_path.iterdir()) == []


def test_dry_run_as_json(run):
    import json

    result = run("drive", "--dry-run", "--format", "json", "--linear", "0.01", "--duration-s",
                 "0.1")
    assert result.exit_code == 0, result.stderr
    frames = json.loads(result.stdout)
    assert [f["meaning"].split()[0] for f in frames] == ["PING", "SET_WHEELS", "SET_WHEELS",
                                                        "STOP"]
    assert frames[1] == {"t_s": 0.0, "bytes_hex": "aa 55 08 02 10 32 00 32 00 32 00 32 00 35 34",
                         "meaning": "SET_WHEELS seq=2 [+0.050 +0.050 +0.050 +0.050] rad/s"}


def test_dry_run_needs_a_plan(run):
    assert_one_line_error(run("drive", "--dry-run"), 2, "--dry-run needs a plan")


def test_a_twist_too_large_for_a_float_is_scaled_with_a_warning_not_zeroed(run):
    result = run("drive", "--dry-run", "--linear", "1e308", "--duration-s", "0.5",
                 "--max-accel", "100")
    assert result.exit_code == 0, result.stderr
    assert "more rad/s than a float holds" in result.stderr and "scaled to 0.035 m/s" \
        in result.stderr
    assert "[+0.500 +0.500 +0.500 +0.500] rad/s" in result.stdout


def test_max_speed_caps_below_the_urdf_and_refuses_above_it(run):
    result = run("drive", "--dry-run", "--protocol", "arduino", "--ticks-per-rev", "3436",
                 "--max-speed", "0.2", "--linear", "1", "--duration-s", "0.5",
                 "--max-accel", "100")
    assert result.exit_code == 0, result.stderr
    assert "'m 3 3': left +0.166 rad/s" in result.stdout and "'m 9 9'" not in result.stdout
    result = run("drive", "--dry-run", "--max-speed", "0.6", "--linear", "1",
                 "--duration-s", "0.5")
    assert result.exit_code == 2 and "--max-speed" in result.stderr and \
        "above service_robot's wheel limit of 0.5 rad/s" in result.stderr


def test_deadman_is_for_teleop_only(run):
    result = run("drive", "--deadman-ms", "600", "--linear", "0.01", "--duration-s", "1")
    assert result.exit_code == 2 and "--deadman-ms is for teleop" in result.stderr


def test_a_baud_too_slow_for_any_rate_says_so(run):
    """At 1200 baud drive said 'at most 3.8 Hz', then refused 3.7 Hz as too slow for the
    watchdog: no rate works, and neither line said so. A rate of 1e300 printed its bytes a
    second in 300 digits."""
    assert_one_line_error(run("drive", "--baud", "1200", "--dry-run", "--linear", "0.01",
                              "--duration-s", "0.5"), 2,
                          "1200 baud carries 3.8 commands a second", "fewer than the 4 Hz")
    line = assert_one_line_error(run("drive", "--rate", "1e300", "--dry-run", "--linear",
                                     "0.01", "--duration-s", "0.5"), 2, "needs 3.2e+301 bytes/s")
    assert len(line) < 300
