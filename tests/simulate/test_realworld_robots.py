"""simulate on real diff-drive robots (vendored under tests/realworld/ws/src), no ROS set.

TurtleBot3 Burger's base_footprint root carries no shape (base_link, fixed to it, does), and
neither it nor ros2_control_demos' diffbot has an arm; diffbot has no sensor at all. Each runs
headless with the built-in scenario or one of its own, and what it writes is read back by
readers that share no code with servicebot's writers (rosbags, the csv module).
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from tests.conftest import REPO, assert_one_line_error, run_servicebot
from tests.simulate.helpers import DIFFBOT, DRIVE_ONLY, NO_ROS, REALWORLD_SRC

SRC = REALWORLD_SRC
TURTLEBOT3 = SRC / "turtlebot3_description" / "urdf" / "turtlebot3_burger.urdf.xacro"


def test_turtlebot3_runs_the_built_in_scenario_without_its_arm_goal():
    result = run_servicebot("simulate", TURTLEBOT3, "--headless", "--duration-s", "20",
                            "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    note, timing = result.stderr.splitlines()
    assert note.startswith("note: the built-in scenario moves the bundled robot's arm; "
                           "turtlebot3_burger has no joint 'arm_base_to_link1'")
    assert timing.startswith("simulated 20 s in ")
    summary = json.loads(result.stdout)
    assert summary["robot"] == "turtlebot3_burger"
    assert summary["arm_final_positions_rad"] == {}
    assert summary["distance_m"] > 1.0  # it drove: the shape is base_link's, fixed to the root


def test_a_robot_without_arm_or_sensors_runs_its_own_scenario(tmp_path):
    scenario = tmp_path / "drive.yaml"
    scenario.write_text(DRIVE_ONLY)
    out = tmp_path / "out"
    result = run_servicebot("simulate", DIFFBOT, "--headless", "-s", scenario, "--out", out,
                            "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith("simulated 12 s in "), result.stderr
    summary = json.loads(result.stdout)
    # no controllers file found: no diff drive publishes odometry, no broadcaster joint states
    assert set(summary["messages"]) == {"/robot_description", "/tf_static", "/clock"}
    with (out / "ground_truth.csv").open(newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 1201  # 12 s at 100 Hz, both ends
    # the wheels' 1 rad/s limit, radius 0.015 m, track 0.1 m: 0.015 m/s and 0.3 rad/s at most
    assert float(rows[-1]["x_m"]) == pytest.approx(6 * 0.015)
    assert float(rows[-1]["yaw_rad"]) == pytest.approx(6 * 0.3)


def test_turtlebot3_plot_and_bag_are_written_quietly_and_read_back(tmp_path):
    rosbags = pytest.importorskip("rosbags")
    del rosbags
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    bag, plot = tmp_path / "bag", tmp_path / "run.png"
    result = run_servicebot("simulate", TURTLEBOT3, "--headless", "--duration-s", "4",
                            "--bag", bag, "--plot", plot, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert [line.split(" ", 1)[0] for line in result.stderr.splitlines()] == \
        ["note:", "simulated"], result.stderr  # no matplotlib warning
    assert plot.stat().st_size > 0
    store = get_typestore(Stores.ROS2_HUMBLE)
    last = {}
    with Reader(Path(bag)) as reader:
        for connection, _, raw in reader.messages():
            last[connection.topic] = store.deserialize_cdr(raw, connection.msgtype)
    scan = last["/scan"]  # the plugin's <topicName>
    assert scan.header.frame_id == "base_scan"
    assert len(scan.ranges) == 360
    assert (scan.range_min, scan.range_max) == pytest.approx((0.12, 3.5))
    assert list(last["/joint_states"].name) == ["wheel_left_joint", "wheel_right_joint"]
    assert last["/odom"].child_frame_id == "base_footprint"  # its diff drive plugin's topic


def test_an_arm_goal_for_a_robot_with_only_wheels_says_so(tmp_path):
    scenario = tmp_path / "arm.yaml"
    scenario.write_text(DRIVE_ONLY + "arm:\n  joint_names: [shoulder]\n"
                        "  points: [{time_from_start_s: 1, positions: [0.1]}]\n")
    result = run_servicebot("simulate", TURTLEBOT3, "--headless", "-s", scenario, env=NO_ROS)
    assert_one_line_error(result, 2, f"{scenario}:7: arm.joint_names[0]: unknown arm joint: "
                          "'shoulder'; turtlebot3_burger has no movable joints but its wheels")


def test_an_arm_tip_that_a_joint_shares_its_name_with_ends_the_run(tmp_path):
    # baxter's fixed joints are named as their child links: Pinocchio then holds two frames
    # of that name, and the summary's end effector must ask for the link's
    robot = tmp_path / "same_name.urdf"
    robot.write_text((REPO / "robots" / "service_robot.urdf.xml").read_text().replace(
        '<joint name="arm_tool_joint" type="fixed">', '<joint name="arm_tool_link" type="fixed">'))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "2",
                            "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["end_effector"]["frame"] == "arm_tool_link"


def test_tiagos_forty_six_arm_joints_plot_quietly(tmp_path):
    """TIAGo (example-robot-data) with its hand: a legend of every joint overflowed its axes,
    and matplotlib said on stderr that the layout did not fit."""
    from tests.kinematics.robots import example_robot

    tiago = example_robot("tiago_description/robots/tiago.urdf")
    scenario = tmp_path / "open.yaml"
    scenario.write_text("duration_s: 1\ninitial_pose: {x_m: 0, y_m: 0, yaw_rad: 0}\n"
                        "cmd_vel:\n  - {start_s: 0, duration_s: 1, linear_m_s: 0.3}\n")
    plot = tmp_path / "tiago.png"
    result = run_servicebot("simulate", tiago, "-s", scenario, "--headless", "--plot", plot,
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert [line.split()[0] for line in result.stderr.splitlines()] == ["note:", "simulated"]
    assert result.stderr.startswith("note: /ground_truth_odom (nav_msgs/msg/Odometry) of plugin "
                                    "libgazebo_ros_p3d.so is not simulated")
    assert plot.stat().st_size > 0
