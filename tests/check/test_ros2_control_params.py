"""Hardware parameters of real ros2_control blocks that are right as written."""

from __future__ import annotations

from tests.check.helpers import findings, fixture


def _sb510(run, tmp_path, port: str, baud_rate: str = "115200") -> list[str]:
    text = fixture("SB510").read_text().replace(
        '<param name="port">ttyUSB0</param>', f'<param name="port">{port}</param>').replace(
        '<param name="baud_rate">9601</param>', f'<param name="baud_rate">{baud_rate}</param>')
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB510")
    return [str(f["message"]) for f in findings(result.stdout)]


def test_a_numeric_port_is_a_network_port_not_a_serial_device(run, tmp_path):
    # ros2_kortex's KortexMultiInterfaceHardware: robot_ip, port 10000, port_realtime 10001
    assert _sb510(run, tmp_path, "10000") == []


def test_a_serial_device_without_its_directory_is_still_flagged(run, tmp_path):
    assert _sb510(run, tmp_path, "/dev/ttyUSB0") == []
    (message,) = _sb510(run, tmp_path, "ttyUSB0")
    assert "port 'ttyUSB0' is not a serial device path" in message


def test_a_dynamixel_bus_rate_above_1_mbaud_is_not_a_typo(run, tmp_path):
    # open_manipulator's OMY arms: baud_rate 6250000 (4000000 for the end unit)
    for rate in ("1000000", "4000000", "6250000", "10500000"):
        assert _sb510(run, tmp_path, "/dev/ttyUSB0", rate) == [], rate
    (message,) = _sb510(run, tmp_path, "/dev/ttyUSB0", "115201")
    assert "baud_rate '115201' is not a standard baud rate" in message


def test_digits_other_than_0_to_9_are_no_port_and_no_rate(run, tmp_path):
    """'²' and '٣' are digits to str.isdigit(); int() refuses the first (no internal error)."""
    (message,) = _sb510(run, tmp_path, "/dev/ttyUSB0", "²")
    assert "baud_rate '²' is not a standard baud rate" in message
    (message,) = _sb510(run, tmp_path, "٣")
    assert "port '٣' is not a serial device path" in message


def test_a_simulated_or_mock_component_opens_no_port(run, tmp_path):
    """ar4_ros_driver's Gazebo robot reuses its driver's macro with serial_port="None":
    gz_ros2_control's GazeboSimSystem and mock_components never read the parameter."""
    text = fixture("SB510").read_text()
    plugin = text.split("<plugin>")[1].split("</plugin>")[0]
    for simulated in ("gz_ros2_control/GazeboSimSystem", "mock_components/GenericSystem"):
        path = tmp_path / "robot.urdf"
        path.write_text(text.replace(plugin, simulated))
        result = run("check", path, "--format", "json", "--isolated", "--select", "SB510")
        assert findings(result.stdout) == [], simulated
    assert _sb510(run, tmp_path, "None")  # the real driver's would open it
