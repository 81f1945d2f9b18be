"""Gazebo Classic's diff-drive plugin: odometry from the world or the wheels, wheels that ramp.

gazebo_ros_pkgs' ``gazebo_ros_diff_drive.cpp`` (ROS 2: ``<odometry_source>``, default 1 =
WORLD; ROS 1: ``<odometrySource>``, default ``world``) publishes the model's world pose and
velocity unless told ``encoder``; ``<max_wheel_acceleration>`` (ROS 1
``<wheelAcceleration>``) ramps each wheel's surface speed. Real descriptions (Nav2's sam_bot,
TurtleBot3), each edited one tag at a time, read back from the bag by rosbags.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate.body import sim_robot
from tests.simulate.plugin_robots import (
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
)

INTO_A_WALL = """\
duration_s: 6
initial_pose: {x_m: 0.5, y_m: -0.3, yaw_rad: 0.4}
cmd_vel:
  - {start_s: 0, duration_s: 6, linear_m_s: 0.3}
world:
  walls: [{from_m: [1.8, -3], to_m: [1.8, 3], thickness_m: 0.1, height_m: 1.0}]
"""
SAM_BOT_SOURCE = ("<publish_odom>true</publish_odom>",
                  "<publish_odom>true</publish_odom><odometry_source>0</odometry_source>")
TB3_SOURCE = ("<odometrySource>world</odometrySource>",
              "<odometrySource>encoder</odometrySource>")


def _into_a_wall(robot: Path, tmp_path: Path) -> tuple[list, list[dict[str, str]]]:
    """The odometry messages and the ground truth rows of a drive into a wall."""
    scenario = tmp_path / "wall.yaml"
    scenario.write_text(INTO_A_WALL)
    out = tmp_path / "out"
    messages = bag_messages(robot, tmp_path, "-s", scenario, "--out", out, duration_s="6")
    with (out / "ground_truth.csv").open() as f:
        truth = list(csv.DictReader(f))
    assert (out / "collisions.csv").read_text().count("\n") > 1  # it did reach the wall
    odometry = next(m for topic, m in messages.items() if topic.endswith("odom"))
    return odometry, truth


def test_sam_bots_default_odometry_is_its_true_pose_in_the_world(tmp_path):
    pytest.importorskip("rosbags")
    odometry, truth = _into_a_wall(SAM_BOT, tmp_path)
    first, last = odometry[0].pose.pose.position, odometry[-1].pose.pose.position
    assert (first.x, first.y) == (0.5, -0.3)  # the start pose, not zero
    assert (last.x, last.y) == (float(truth[-1]["x_m"]), float(truth[-1]["y_m"]))
    height = sim_robot(load(RobotSource.of(SAM_BOT))).base_height_m
    assert last.z == pytest.approx(height) and height > 0  # the model origin's height
    assert odometry[-1].twist.twist.linear.x == 0.0  # stopped at the wall
    moving = odometry[100].twist.twist
    assert moving.linear.x == pytest.approx(0.3, abs=1e-6)
    assert abs(moving.linear.y) < 1e-7  # the plugin's float heading leaves a trace at most


def test_sam_bot_with_odometry_source_encoder_integrates_its_wheels(tmp_path):
    pytest.importorskip("rosbags")
    odometry, truth = _into_a_wall(edited(SAM_BOT, tmp_path, SAM_BOT_SOURCE), tmp_path)
    first, last = odometry[0].pose.pose.position, odometry[-1].pose.pose.position
    assert (first.x, first.y, first.z) == (0.0, 0.0, 0.0)
    travelled = ((float(truth[-1]["x_m"]) - 0.5) ** 2 + (float(truth[-1]["y_m"]) + 0.3) ** 2)
    assert last.x > travelled**0.5 + 0.5  # the wheels turned on at the wall


@pytest.mark.parametrize("source", ["2", "-1"])
def test_sam_bot_with_another_odometry_source_never_updates_its_odometry(tmp_path, source):
    """ROS 2 updates odometry for ENCODER (0) and WORLD (1) only; any other publishes its
    untouched message: the origin, heading 0, at rest (with the covariances it sets)."""
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, ("<publish_odom>true</publish_odom>",
                                       "<publish_odom>true</publish_odom>"
                                       f"<odometry_source>{source}</odometry_source>"))
    odometry, _ = _into_a_wall(robot, tmp_path)
    assert len(odometry) > 100
    for message in (odometry[0], odometry[100], odometry[-1]):
        pose, twist = message.pose.pose, message.twist.twist
        assert (pose.position.x, pose.position.y, pose.position.z) == (0.0, 0.0, 0.0)
        assert (pose.orientation.z, pose.orientation.w) == (0.0, 1.0)
        assert (twist.linear.x, twist.linear.y, twist.angular.z) == (0.0, 0.0, 0.0)
        assert message.pose.covariance[0] == pytest.approx(1e-5)


@pytest.mark.parametrize(("source", "world"), [(None, True), (TB3_SOURCE, False)])
def test_turtlebot3s_ros1_odometry_source(tmp_path, source, world):
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, source, file=TURTLEBOT3_GAZEBO) if source \
        else TURTLEBOT3
    odometry, truth = _into_a_wall(robot, tmp_path)
    last = odometry[-1].pose.pose.position
    on_truth = (last.x, last.y) == (float(truth[-1]["x_m"]), float(truth[-1]["y_m"]))
    assert on_truth is world


def _wheel_speeds(robot: Path, tmp_path: Path, joint: str) -> list[tuple[float, float]]:
    """(time [s], speed [rad/s]) of ``joint`` over 1 s ahead at 0.2 m/s, from --out's CSV.

    Not from the bag: sam_bot has no joint-state publisher, so its bag has no joint states.
    """
    scenario = tmp_path / "ahead.yaml"
    scenario.write_text("duration_s: 1\ncmd_vel: [{start_s: 0, duration_s: 1, linear_m_s: 0.2}]\n")
    bag_messages(robot, tmp_path, "-s", scenario, "--out", tmp_path / "out", duration_s="1")
    with (tmp_path / "out" / "joint_states.csv").open(newline="") as f:
        return [(float(row["time_s"]), float(row[f"{joint}_rad_s"]))
                for row in csv.DictReader(f)]


def test_sam_bots_wheels_ramp_at_its_max_wheel_acceleration(tmp_path):
    pytest.importorskip("rosbags")
    radius = 0.1  # <wheel_diameter>0.2</wheel_diameter>; <max_wheel_acceleration>1.0
    speeds = _wheel_speeds(SAM_BOT, tmp_path, "drivewhl_l_joint")
    for t, w in speeds:
        assert abs(w) * radius <= 1.0 * t + 0.011  # 1 m/s^2, the last step set whole
    assert abs(speeds[5][1]) * radius == pytest.approx(0.1, abs=0.025)  # 0.1 s: half way
    assert abs(speeds[-1][1]) * radius == pytest.approx(0.2)
    unlimited = edited(SAM_BOT, tmp_path / "unlimited", (
        "<max_wheel_acceleration>1.0</max_wheel_acceleration>",
        "<max_wheel_acceleration>0</max_wheel_acceleration>"))
    at_once = _wheel_speeds(unlimited, tmp_path / "unlimited", "drivewhl_l_joint")
    assert abs(at_once[5][1]) * radius == pytest.approx(0.2)


def test_turtlebot3s_wheels_ramp_at_its_wheel_acceleration(tmp_path):
    pytest.importorskip("rosbags")
    radius = 0.033  # <wheelDiameter>0.066; <wheelAcceleration>1, <updateRate>30
    speeds = _wheel_speeds(TURTLEBOT3, tmp_path, "wheel_left_joint")
    for t, w in speeds:
        assert abs(w) * radius <= 1.0 * t + 0.011
    # its joint states come at <updateRate> (publishWheelJointState): the one at 0.1 s
    at_tenth = min(speeds, key=lambda row: abs(row[0] - 0.1))
    assert 0.05 < abs(at_tenth[1]) * radius < 0.15
    assert abs(speeds[-1][1]) * radius == pytest.approx(0.2)
