"""inspect A --diff B: what differs, exit 0 when equal and 1 when not."""

from __future__ import annotations

import json

from tests.conftest import REAL_URDF, SIM_URDF, XACRO_SOURCE, assert_one_line_error

GAZEBO_ONLY = {"sensor lidar", "sensor pi_camera", "sensor imu",
               "gazebo plugin gazebo_ros2_control (model)",
               "gazebo plugin lidar_plugin (sensor lidar)",
               "gazebo plugin camera_plugin (sensor pi_camera)",
               "gazebo plugin imu_plugin (sensor imu)", "gazebo base_link",
               "gazebo front_left_wheel", "gazebo front_right_wheel", "gazebo rear_left_wheel",
               "gazebo rear_right_wheel"}
WHEELS = ("front_left_wheel_joint", "front_right_wheel_joint", "rear_left_wheel_joint",
          "rear_right_wheel_joint")


def _diff_json(run, *args) -> tuple[int, dict]:
    result = run("inspect", *args, "--format", "json")
    return result.exit_code, json.loads(result.stdout)


def _check_sim_against_real(document: dict) -> None:
    assert document["equal"] is False
    found = {(d["element"], d["field"]): d for d in document["differences"]}
    for wheel in WHEELS:
        velocity = found[(f"joint {wheel}", "limits.velocity")]
        assert (velocity["a"], velocity["b"], velocity["unit"]) == (0.44, 0.5, "rad/s")
        command = found[(f"ros2_control ServiceRobotSystem joint {wheel}", "command.velocity.max")]
        assert (command["a"], command["b"]) == (0.44, 0.5)
    plugin = found[("ros2_control ServiceRobotSystem", "plugin")]
    assert (plugin["a"], plugin["b"]) == ("gazebo_ros2_control/GazeboSystem",
                                          "robot_control/SimpleHardwareInterface")
    port = found[("ros2_control ServiceRobotSystem", "params.port")]
    baud = found[("ros2_control ServiceRobotSystem", "params.baud_rate")]
    assert (port["change"], port["b"], baud["b"]) == ("added", "/dev/ttyUSB0", 9600)
    removed = {d["element"] for d in document["differences"] if d["change"] == "removed"}
    assert removed == GAZEBO_ONLY
    assert len(document["differences"]) == 4 + 8 + 3 + len(GAZEBO_ONLY)


def test_sim_against_real(run):
    code, document = _diff_json(run, SIM_URDF, "--diff", REAL_URDF)
    assert code == 1
    assert document["schema"] == "servicebot.inspect.diff/1"
    assert (document["a"], document["b"]) == (str(SIM_URDF), str(REAL_URDF))
    _check_sim_against_real(document)


def test_one_xacro_with_two_argument_sets(run):
    code, document = _diff_json(run, XACRO_SOURCE, "hardware:=sim", "--diff", XACRO_SOURCE,
                                "hardware:=real")
    assert code == 1
    assert document["a"].endswith("hardware:=sim") and document["b"].endswith("hardware:=real")
    _check_sim_against_real(document)


def test_bundled_shortcuts(run):
    code, document = _diff_json(run, "--diff", "--robot", "real")
    assert code == 1 and document["a"].endswith("robots/service_robot.urdf.xml")
    assert document["b"].endswith("robots/service_robot_real.urdf.xml")
    code, document = _diff_json(run, "--diff", REAL_URDF)
    assert code == 1 and document["a"].endswith("robots/service_robot.urdf.xml")


def test_equal_descriptions_exit_0(run):
    result = run("inspect", SIM_URDF, "--diff", XACRO_SOURCE)  # the xacro expands to the URDF
    assert result.exit_code == 0, result.stderr
    assert result.stdout.splitlines()[-1] == "no differences"
    code, document = _diff_json(run, REAL_URDF, "--diff", "--robot", "real")
    assert (code, document["equal"], document["differences"]) == (0, True, [])


def test_text_form_is_grouped_and_fits(run):
    result = run("inspect", SIM_URDF, "--diff", REAL_URDF)
    assert result.exit_code == 1
    lines = result.stdout.splitlines()
    assert max(map(len, lines)) <= 100 and "\x1b[" not in result.stdout
    at = lines.index("joint front_left_wheel_joint")
    assert lines[at + 1] == "  ~ limits velocity [rad/s]: 0.44 -> 0.5"
    at = lines.index("ros2_control ServiceRobotSystem")
    assert lines[at + 2:at + 4] == ["  + params port: /dev/ttyUSB0", "  + params baud_rate: 9600"]
    assert lines[lines.index("sensor lidar") + 1] == "  - only in A"
    assert lines[-1] == "27 differences: 13 changed, 12 only in A, 2 only in B"


def test_small_changes_are_found(run, tmp_path):
    changed = tmp_path / "changed.urdf"
    text = SIM_URDF.read_text()
    text = text.replace('<mass value="2.0"/>', '<mass value="2.5"/>')
    text = text.replace('lower="-1.57" upper="1.57" velocity="1.0"/>\n  </joint>\n  <link '
                        'name="arm_link2">', 'lower="-1.0" upper="1.57" velocity="1.0"/>\n'
                        '  </joint>\n  <link name="arm_link2">', 1)
    text = text.replace("<update_rate>10</update_rate>", "<update_rate>5.0</update_rate>")
    text = text.replace("0.241666667", "0.2416666670")  # same number, written differently
    changed.write_text(text)
    code, document = _diff_json(run, SIM_URDF, "--diff", changed)
    found = {(d["element"], d["field"]): (d["a"], d["b"]) for d in document["differences"]}
    assert code == 1 and found == {
        ("link arm_base_link", "mass_kg"): (2.0, 2.5),
        ("joint arm_base_to_link1", "limits.lower"): (-1.57, -1.0),
        ("sensor lidar", "update_rate_hz"): (10.0, 5.0),
        ("sensor lidar", "lidar.update_rate_hz"): (10.0, 5.0),
    }


def test_markdown_form(run):
    result = run("inspect", SIM_URDF, "--diff", REAL_URDF, "--format", "markdown")
    assert result.exit_code == 1
    row = "| joint front_left_wheel_joint | limits velocity [rad/s] | 0.44 | 0.5 |"
    assert row in result.stdout
    assert "| sensor lidar | (whole element) | present | (none) |" in result.stdout


def test_diff_usage_errors(run, tmp_path):
    assert_one_line_error(run("inspect", "--diff"), 2, "compares two descriptions, got 0")
    assert_one_line_error(run("inspect", SIM_URDF, REAL_URDF, SIM_URDF, "--diff"), 2, "got 3")
    assert_one_line_error(run("inspect", "--diff", REAL_URDF, "--section", "links"), 2,
                          "drop --section")
    assert_one_line_error(run("inspect", "--diff", REAL_URDF, "--format", "dot"), 2,
                          "draws the kinematic tree only")
    assert_one_line_error(run("inspect", "hardware:=real", XACRO_SOURCE, "--diff"), 2,
                          "comes before any FILE")
    assert_one_line_error(run("inspect", "--diff", tmp_path / "nope.urdf"), 2, "no such file")
    assert_one_line_error(run("inspect", SIM_URDF, "--diff", XACRO_SOURCE, "hardware:=mars"), 2,
                          "hardware:=mars is unknown")
