r"""A base that gz-sim's DiffDrive system drives runs gz-math's speed limiter, not ROS's.

gz-sim ``src/systems/diff_drive/DiffDrive.cc`` (main, gz-sim8 and ign-gazebo6 alike) calls
``SetMin*`` only for a ``<min_*>`` tag it finds, and gz-math ``src/SpeedLimiter.cc`` starts
every bound at +-infinity: a minimum left out is unbounded, not the maximum mirrored as
diff_drive_controller does. gz-math's ``LimitJerk`` also clamps the jerk itself,
:math:`v = v_0 + (v_0 - v_1) + \mathrm{clamp}(\ldots, j_{min} \Delta t^2, j_{max} \Delta t^2)`,
without ros2_controllers' factor 2. Leo Rover's real description, read back from the bag.
"""

from __future__ import annotations

import json

import pytest

from servicebot_cli.simulate.controllers.limiter import AxisLimits, limited
from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import LEO, bag_messages, edited

SCENARIO = """\
duration_s: 3
initial_pose: {x_m: 0, y_m: 0, yaw_rad: 0}
cmd_vel:
  - {duration_s: 1, linear_m_s: 0.3}
"""
"""0.3 m/s (the wheels' 6 rad/s allow it) for 1 s, then nothing: the command holds."""
STOP = SCENARIO + "  - {duration_s: 2, linear_m_s: 0.0}\n"
"""The same, told to stop at 1 s."""
MIN_ACCEL = "<min_linear_acceleration>-2.5</min_linear_acceleration>"


def _final_x_m(robot, tmp_path) -> float:
    scenario = tmp_path / "stop.yaml"
    scenario.write_text(STOP)
    odometry = bag_messages(robot, tmp_path, "-s", str(scenario), duration_s="3")["/odom"]
    return float(odometry[-1].pose.pose.position.x)


def test_without_a_minimum_acceleration_the_gz_base_stops_at_once(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(LEO, tmp_path, (MIN_ACCEL, ""), file="macros.xacro")
    # 0.12 s ramp up at 2.5 m/s^2 (0.018 m lost), then no braking limit: 0.3 - 0.018
    assert _final_x_m(robot, tmp_path) == pytest.approx(0.282, abs=0.005)
    summary = run_servicebot("simulate", robot, "--headless", "--duration-s", "1",
                             "--format", "json", env=NO_ROS)
    assert summary.returncode == 0, summary.stderr
    controller = json.loads(summary.stdout)["controller"]
    assert controller["min_linear_acceleration_m_s2"] == {"value": None, "source": "default"}
    assert controller["min_angular_acceleration_rad_s2"]["value"] == -3.0


def test_with_its_minimum_acceleration_the_gz_base_brakes_as_slowly(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(LEO, tmp_path, ("<odom_topic>", "<odom_topic>"), file="macros.xacro")
    assert _final_x_m(robot, tmp_path) == pytest.approx(0.3, abs=0.005)  # 0.018 m back


def test_a_gz_jerk_bound_is_j_dt2(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(LEO, tmp_path, (MIN_ACCEL, ""), (
        "<max_linear_acceleration>2.5</max_linear_acceleration>",
        "<max_linear_jerk>1</max_linear_jerk><min_linear_jerk>-1</min_linear_jerk>"),
        file="macros.xacro")
    scenario = tmp_path / "go.yaml"
    scenario.write_text(SCENARIO)
    odometry = bag_messages(robot, tmp_path, "-s", str(scenario), duration_s="1")["/odom"]
    at = next(m for m in odometry if m.header.stamp.nanosec == 250_000_000)
    # the acceleration grows by j dt a tick: v = j t^2 / 2 (ros2_controllers': j t^2)
    assert at.twist.twist.linear.x == pytest.approx(0.25**2 / 2, rel=0.1)


def test_the_gz_limiter_pins_gz_maths_formulas():
    dt_s, target = 0.01, pytest.importorskip("numpy").full(3, 1.0)
    gz = AxisLimits.gz(-float("inf"), float("inf"), -float("inf"), float("inf"),
                       -float("inf"), 2.0)
    # LimitJerk: accPrev + clamp(jerk) dt, over dt again: 2 dt^2, 2 (2 dt^2), 2 (3 dt^2)
    assert list(limited(target, gz, dt_s)) == pytest.approx([2e-4, 6e-4, 12e-4])
    assert AxisLimits.of("gz-math", 0, 1, -1, 1, -1, 1).min_acceleration == -1
    assert AxisLimits.of("gz-math", -float("inf"), 1, -float("inf"), 1, -float("inf"),
                         1).min_velocity == -float("inf")
