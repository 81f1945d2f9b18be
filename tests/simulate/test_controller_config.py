"""diff_drive_controller as configured: the controllers file, its limiter, its covariances."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from servicebot_cli.simulate.controllers.limiter import AxisLimits, limited
from tests.simulate.helpers import body

GEOMETRY = body().geometry
V_LIMIT, A_LIMIT = 0.0308, 0.05  # robots/controllers.yaml
DT = 0.01


def test_the_ramp_starts_from_the_limited_command_so_nothing_creeps():
    target = np.r_[np.full(1000, 0.2), np.zeros(1000)]  # 0.2 m/s asked for 10 s, then 0
    v = limited(target, AxisLimits(-V_LIMIT, V_LIMIT, -A_LIMIT, A_LIMIT), DT)
    assert v.max() == pytest.approx(V_LIMIT)
    assert np.all(np.abs(np.diff(v)) <= A_LIMIT * DT + 1e-15)
    # stopped within v / a (0.62 s) of the command ending, not ramping down from 0.2 m/s
    stopped = np.flatnonzero(v[1000:] == 0.0)[0] * DT
    assert stopped == pytest.approx(V_LIMIT / A_LIMIT, abs=DT)
    # the ramps up and down cancel: the distance is what the limit gives over 10 s
    assert v.sum() * DT == pytest.approx(V_LIMIT * 10, abs=V_LIMIT * DT)


def test_jerk_limits_bound_the_change_of_acceleration():
    jerk = 0.5
    target = np.r_[np.full(300, 0.3), np.zeros(300)]
    v = limited(target, AxisLimits(max_acceleration=0.2, min_acceleration=-0.2,
                                   max_jerk=jerk, min_jerk=-jerk), DT)
    second = np.diff(np.r_[0.0, 0.0, v], 2)  # (v - v0) - (v0 - v1) per tick
    assert np.all(np.abs(second) <= 2 * jerk * DT**2 + 1e-15)
    assert np.all(np.abs(np.diff(v)) <= 0.2 * DT + 1e-15)
    # without look-ahead the jerk-limited ramp overshoots a little, as the controller's does
    assert 0.3 <= v[:300].max() < 0.33 and abs(v[299] - 0.3) < 0.01 and abs(v[-1]) < 0.02


def _summary(run, tmp_path, *args):
    result = run("simulate", "--headless", "--format", "json", *args)
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_a_quarter_turn_of_the_default_scenario_turns_what_the_limits_allow(run, tmp_path):
    scenario = tmp_path / "turn.yaml"
    scenario.write_text("duration_s: 20\ncmd_vel:\n  - {duration_s: 13.77, angular_rad_s: 0.5}\n")
    summary = _summary(run, tmp_path, "-s", scenario)
    # robots/controllers.yaml: 0.114 rad/s at most, 0.2 rad/s^2; the command lasts until the
    # 0.5 s timeout; ramps up and down cancel
    assert summary["final_pose"]["yaw_rad"] == pytest.approx(0.114 * (13.77 + 0.5), abs=2e-3)
    assert summary["controller"]["max_angular_velocity_rad_s"]["source"].endswith(
        "controllers.yaml")


def test_controllers_file_option_scenario_and_command_line_in_that_order(run, tmp_path):
    controllers = tmp_path / "mine.yaml"
    controllers.write_text("""\
controller_manager:
  ros__parameters:
    update_rate: 50
    base: {type: diff_drive_controller/DiffDriveController}
base:
  ros__parameters:
    publish_rate: 25.0
    cmd_vel_timeout: 0.25
    linear:
      x: {has_velocity_limits: true, max_velocity: 0.02, has_acceleration_limits: false}
    pose_covariance_diagonal: [1, 2, 3, 4, 5, 6]
""")
    scenario = tmp_path / "s.yaml"
    scenario.write_text("duration_s: 4\ncontroller: {cmd_vel_timeout_s: 0.75}\n"
                        "cmd_vel:\n  - {duration_s: 2, linear_m_s: 0.5}\n")
    summary = _summary(run, tmp_path, "-s", scenario, "--controllers", controllers,
                       "--wheel-separation-multiplier", "1.1", "--bag", tmp_path / "bag")
    c = summary["controller"]
    assert c["update_rate_hz"] == {"value": 50.0, "source": str(controllers)}
    assert c["max_linear_velocity_m_s"] == {"value": 0.02, "source": str(controllers)}
    assert c["max_linear_acceleration_m_s2"]["value"] is None  # switched off in the file
    assert c["cmd_vel_timeout_s"] == {"value": 0.75, "source": "scenario"}
    assert c["wheel_separation_multiplier"] == {"value": 1.1, "source": "command line"}
    assert c["saturation"]["source"] == "default"
    # 0.02 m/s from the first tick, for 2 s + the 0.75 s timeout
    assert summary["distance_m"] == pytest.approx(0.02 * 2.75, abs=0.02 * 0.02)  # one tick
    assert summary["messages"]["/base/odom"] == 4 * 25  # the controller's ~/odom

    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader(tmp_path / "bag") as reader:
        odom = [store.deserialize_cdr(raw, c.msgtype) for c, _, raw in reader.messages()
                if c.topic == "/base/odom"]
    assert np.diag(odom[-1].pose.covariance.reshape(6, 6)).tolist() == [1, 2, 3, 4, 5, 6]
    assert not odom[-1].twist.covariance.any()  # the file sets none: zero
    assert len(odom) == 100  # publish_rate 25 Hz from the file, for 4 s


_CONTROLLERS = Path(__file__).resolve().parents[2] / "robots" / "controllers.yaml"


def _robot_naming(tmp_path, *files: str) -> Path:
    """The bundled robot, its ros2_control plugin naming ``files`` as its parameters."""
    text = (_CONTROLLERS.parent / "service_robot.urdf.xml").read_text()
    named = "".join(f"<parameters>{name}</parameters>" for name in files)
    robot = tmp_path / "robot.urdf"
    robot.write_text(text.replace("<parameters>controllers.yaml</parameters>", named, 1))
    return robot


@pytest.mark.parametrize("case", ["nothing else", "another named file", "beside"])
def test_a_missing_parameter_file_is_noted_with_what_is_read_instead(run, tmp_path, case):
    """Gazebo's controller manager would not start; the run says so, and what it used."""
    missing = "/nonexistent/ws/install/share/demo/config/controllers.yaml"
    files = [missing, str(_CONTROLLERS)] if case == "another named file" else [missing]
    robot = _robot_naming(tmp_path, *files)
    if case == "beside":
        (tmp_path / "controllers.yaml").write_bytes(_CONTROLLERS.read_bytes())
    result = run("simulate", "--headless", "--format", "json", "--duration-s", "1", robot)
    assert result.exit_code == 0, result.stderr
    notes = [line for line in result.stderr.splitlines() if missing in line]
    assert len(notes) == 1, result.stderr
    expected = {"nothing else": "no controller publishes odometry or joint states; give the "
                                "file with --controllers FILE",
                "another named file": f"{_CONTROLLERS} is read without it",
                "beside": f"{tmp_path / 'controllers.yaml'} is read instead"}[case]
    assert notes[0] == (f"note: the ros2_control plugin's parameter file {missing} does not "
                        f"exist (the controller manager would not start in Gazebo); {expected}")
    messages = json.loads(result.stdout)["messages"]
    assert ("/joint_states" in messages) is (case != "nothing else")


def test_no_note_when_controllers_are_given(run, tmp_path):
    robot = _robot_naming(tmp_path, "/nonexistent/controllers.yaml")
    result = run("simulate", "--headless", "--duration-s", "1", "--controllers", _CONTROLLERS,
                 robot)
    assert result.exit_code == 0, result.stderr
    assert "nonexistent" not in result.stderr


_MANAGER_ONLY = ("controller_manager:\n  ros__parameters:\n    update_rate: {rate}\n"
                 "    base: {{type: diff_drive_controller/DiffDriveController}}\n")


@pytest.mark.parametrize("rate", ["0", "-10"])
def test_a_control_rate_of_zero_or_less_is_refused_in_one_line(run, tmp_path, rate):
    """update_rate 0 stopped the run with an internal error (a division by zero)."""
    controllers = tmp_path / "c.yaml"
    controllers.write_text(_MANAGER_ONLY.format(rate=rate))
    result = run("simulate", "--headless", "--duration-s", "1", "--controllers", controllers)
    assert result.exit_code == 2
    assert f"controller_manager.update_rate: must be above 0, got {rate}" in result.stderr


@pytest.mark.parametrize("rate", ["100000000", "99999999999999999999999"])
def test_a_control_rate_beyond_the_physics_step_runs_once_a_step(run, tmp_path, rate):
    """1e8 Hz ran for minutes (a tick per 10 ns); 1e23 Hz stopped with an internal error.
    gazebo_ros2_control runs the controllers once a physics step (1 ms) at most."""
    controllers = tmp_path / "c.yaml"
    controllers.write_text(_MANAGER_ONLY.format(rate=rate))
    result = run("simulate", "--headless", "--duration-s", "1", "--format", "json",
                 "--controllers", controllers)
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["controller"]["update_rate_hz"]["value"] == 1000.0
    assert "gazebo_ros2_control runs the controllers once a step (1000 Hz)" in result.stderr
