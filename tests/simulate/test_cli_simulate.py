"""``servicebot simulate`` end to end: outputs, repeatability, the bag read back, errors."""

from __future__ import annotations

import json

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

SHORT = """\
duration_s: 12
initial_pose: {x_m: 0.0, y_m: 0.0, yaw_rad: 0.0}
slip: {track_factor: 1.2}
cmd_vel:
  - {duration_s: 6, linear_m_s: 0.02, angular_rad_s: 0.03}
  - {duration_s: 6, linear_m_s: 0.5}
arm:
  joint_names: [arm_base_to_link1, arm_link1_to_link2]
  points:
    - {time_from_start_s: 2, positions: [0.5, -0.3]}
    - {time_from_start_s: 8, positions: [-0.5, 0.3]}
world:
  walls:
    - {from_m: [0.95, -1], to_m: [0.95, 1]}
  cylinders:
    - {center_m: [-0.6, 0.4], radius_m: 0.1}
"""
STREAMS = ["camera_info.csv", "cmd_vel.csv", "collisions.csv", "ground_truth.csv", "imu.csv",
           "joint_states.csv", "odometry.csv", "scan.csv", "summary.json"]


@pytest.fixture(scope="module")
def scenario(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenario") / "short.yaml"
    path.write_text(SHORT)
    return path


def _outputs(run, tmp_path, scenario, name, seed):
    base = tmp_path / name
    base.mkdir()
    result = run("simulate", "--headless", "-s", scenario, "--seed", seed, "--out", base / "out",
                 "--bag", base / "bag", "--plot", base / "run.png")
    assert result.exit_code == 0, result.stderr
    files = {p.relative_to(base).as_posix(): p.read_bytes() for p in sorted(base.rglob("*"))
             if p.is_file()}
    return result, files


def test_same_seed_same_bytes_in_every_output(run, tmp_path, scenario):
    first, a = _outputs(run, tmp_path, scenario, "a", 7)
    second, b = _outputs(run, tmp_path, scenario, "b", 7)
    _, c = _outputs(run, tmp_path, scenario, "c", 8)
    assert sorted(a) == sorted(b) == sorted(
        [f"out/{s}" for s in STREAMS] + ["bag/bag_0.mcap", "bag/metadata.yaml", "run.png"])
    for name in a:
        assert a[name] == b[name], f"{name} differs between two runs with the same seed"
    assert first.stdout == second.stdout
    for noisy in ("out/scan.csv", "out/imu.csv", "bag/bag_0.mcap"):
        assert a[noisy] != c[noisy], f"{noisy} did not change with the seed"
    assert a["out/ground_truth.csv"] == c["out/ground_truth.csv"]  # noise-free streams


def test_summary_and_collision(run, tmp_path, scenario):
    result = run("simulate", "--headless", "-s", scenario, "--out", tmp_path / "o",
                 "--format", "json")
    summary = json.loads(result.stdout)
    assert summary == json.loads((tmp_path / "o" / "summary.json").read_text())
    # the arm, reaching 0.8 m ahead, touches the wall first; the base creeps on as it swings
    assert {c["obstacle"] for c in summary["collisions"]} == {"wall 1"}
    assert summary["collisions"][0]["link"] == "arm_link4"
    assert summary["min_obstacle_distance_m"] == 0.0
    assert summary["odometry_drift"]["final_position_m"] > 0.01  # slip: odometry drifts
    assert summary["messages"]["/scan"] == 120 and summary["messages"]["/imu/data"] == 1200
    assert summary["end_effector"]["frame"] == "arm_tool_link"
    lines = (tmp_path / "o" / "collisions.csv").read_text().splitlines()
    assert lines[0] == "time_s,obstacle,link,x_m,y_m,yaw_rad" and lines[1].split(",")[1] == "wall 1"
    header = (tmp_path / "o" / "joint_states.csv").read_text().splitlines()[0]
    assert header.startswith("time_s,front_left_wheel_joint_rad,")


def test_bag_reads_back_with_another_library(run, tmp_path, scenario):
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    bag = tmp_path / "bag"
    assert run("simulate", "--headless", "-s", scenario, "--bag", bag).exit_code == 0
    store = get_typestore(Stores.ROS2_HUMBLE)
    seen: dict[str, list] = {}
    with Reader(bag) as reader:
        assert reader.message_count == sum(c.msgcount for c in reader.connections)
        types = {c.topic: c.msgtype for c in reader.connections}
        for connection, stamp, raw in reader.messages():
            seen.setdefault(connection.topic, []).append(
                (stamp, store.deserialize_cdr(raw, connection.msgtype)))
    assert types == {
        "/scan": "sensor_msgs/msg/LaserScan", "/imu/data": "sensor_msgs/msg/Imu",
        "/pi_camera/camera_info": "sensor_msgs/msg/CameraInfo",
        "/joint_states": "sensor_msgs/msg/JointState", "/diff_controller/odom":
        "nav_msgs/msg/Odometry", "/tf": "tf2_msgs/msg/TFMessage",
        "/tf_static": "tf2_msgs/msg/TFMessage", "/clock": "rosgraph_msgs/msg/Clock",
        "/robot_description": "std_msgs/msg/String"}
    scan_stamp, scan = seen["/scan"][0]
    assert scan_stamp == 100_000_000 and scan.header.frame_id == "lidar_link"
    assert len(scan.ranges) == 360 and scan.range_min == pytest.approx(0.12)
    _, imu = seen["/imu/data"][0]
    assert imu.linear_acceleration.z == pytest.approx(9.8, abs=0.05)
    _, odom = seen["/diff_controller/odom"][-1]
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_link")
    _, joints = seen["/joint_states"][-1]
    assert list(joints.name[:1]) == ["front_left_wheel_joint"] and len(joints.position) == 8
    _, info = seen["/pi_camera/camera_info"][0]
    assert (info.width, info.height, info.header.frame_id) == (1920, 1080, "camera_link_optical")
    _, static = seen["/tf_static"][0]
    assert {t.child_frame_id for t in static.transforms} >= {"lidar_link", "arm_tool_link"}
    children = {t.child_frame_id for _, m in seen["/tf"] for t in m.transforms}
    assert {"base_link", "arm_link1", "front_left_wheel"} <= children
    stamps = [s for topic in seen.values() for s, _ in topic]
    assert max(stamps) == 12_000_000_000
    metadata = (bag / "metadata.yaml").read_text()
    assert "storage_identifier: mcap" in metadata and "bag_0.mcap" in metadata


def test_default_scenario_runs_out_of_the_box():
    result = run_servicebot("simulate", "--headless")
    assert result.returncode == 0, result.stderr
    assert "scenario default, 180 s" in result.stdout and "collisions        0" in result.stdout
    assert "real-time factor" in result.stderr and "\r" not in result.stderr  # no bar in pipes


def test_without_a_display_it_asks_for_headless():
    result = run_servicebot("simulate", env={"DISPLAY": "", "WAYLAND_DISPLAY": ""})
    line = assert_one_line_error(result, 2, "--headless")
    assert "display" in line


def test_existing_bag_is_refused_and_nothing_is_written(run, tmp_path, scenario):
    (tmp_path / "bag").mkdir()
    assert_one_line_error(run("simulate", "--headless", "-s", scenario, "--bag",
                              tmp_path / "bag"), 2, "already exists")
    assert list(tmp_path.iterdir()) == [tmp_path / "bag"]


def test_output_directory_problems_are_one_line(run, tmp_path, scenario):
    (tmp_path / "file").write_text("x")
    assert_one_line_error(run("simulate", "--headless", "-s", scenario, "--out",
                              tmp_path / "file"), 2, "is a file")
    assert_one_line_error(run("simulate", "--headless", "-s", scenario, "--plot",
                              tmp_path / "missing" / "p.png"), 2, "does not exist")
    assert not (tmp_path / "missing").exists()


def test_command_line_overrides_reach_the_controller(run):
    per_wheel = run("simulate", "--headless", "--duration-s", "20", "--saturation", "per-wheel",
                    "--format", "json")
    curvature = run("simulate", "--headless", "--duration-s", "20", "--format", "json")
    assert json.loads(per_wheel.stdout)["distance_m"] == pytest.approx(
        json.loads(curvature.stdout)["distance_m"])  # straight segment: same either way
    wide = run("simulate", "--headless", "--duration-s", "60", "--wheel-separation-multiplier",
               "1.1", "--format", "json")
    assert json.loads(wide.stdout)["odometry_drift"]["final_yaw_rad"] < json.loads(
        run("simulate", "--headless", "--duration-s", "60", "--format", "json").stdout
    )["odometry_drift"]["final_yaw_rad"]  # the default floor slips like a 1.1 multiplier


def test_mesh_obstacle_is_seen_and_stops_the_base(run, tmp_path):
    import trimesh

    trimesh.creation.box(extents=(0.2, 4.0, 1.0)).export(tmp_path / "wall.stl")
    path = tmp_path / "mesh.yaml"
    path.write_text("duration_s: 30\ncmd_vel:\n  - {duration_s: 30, linear_m_s: 0.1}\n"
                    "world:\n  meshes:\n    - {file: wall.stl, xyz_m: [1.0, 0, 0.5]}\n")
    result = run("simulate", "--headless", "-s", path, "--out", tmp_path / "o",
                 "--format", "json")
    assert result.exit_code == 0, result.stderr
    summary = json.loads(result.stdout)
    assert [c["obstacle"] for c in summary["collisions"]] == ["mesh 1"]
    first_scan = (tmp_path / "o" / "scan.csv").read_text().splitlines()[1].split(",")
    assert float(first_scan[1]) == pytest.approx(0.9 - 0.18 - 0.1 * 0.1, abs=0.05)
