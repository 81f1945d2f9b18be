"""Sections, formats, widths, colour, JSON stability, topics and totals."""

from __future__ import annotations

import json
import os
import pty
import subprocess
import sys

import pytest

from servicebot_cli.inspect import SCHEMA, SECTIONS
from tests.conftest import (
    CONTROLLERS_YAML,
    REAL_URDF,
    SIM_URDF,
    XACRO_SOURCE,
    assert_one_line_error,
    run_servicebot,
)


@pytest.mark.parametrize("robot", ["sim", "real"])
def test_every_section_fits_100_columns_and_shows(run, robot):
    result = run("inspect", "--robot", robot)
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert max(map(len, lines)) <= 100, max(lines, key=len)
    for title in ("Kinematic tree (15 links, 14 joints)", "Links (15): mass and inertia",
                  "Link geometry", "Joints (8 movable)", "Joint limits", "Fixed frames (6)",
                  "ros2_control hardware", "ros2_control interfaces", "Consumed", "Published",
                  "Totals (at the zero configuration)"):
        assert any(line.startswith(title) for line in lines), title
    assert ("Sensors (3)" in result.stdout) == (robot == "sim")
    assert "…" not in result.stdout  # nothing had to be cut to fit


def test_piped_output_has_no_colour_and_a_terminal_gets_bold():
    piped = run_servicebot("inspect", "--section", "totals")
    assert piped.returncode == 0 and "\x1b[" not in piped.stdout
    leader, follower = pty.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "servicebot_cli", "inspect", "--section",
                             "totals"], stdout=follower, stderr=subprocess.PIPE)
    os.close(follower)
    chunks = []
    while True:
        try:
            chunk = os.read(leader, 65536)
        except OSError:
            break
        if not chunk:
            break
        chunks.append(chunk)
    proc.wait(timeout=60)
    os.close(leader)
    assert b"\x1b[1mTotals" in b"".join(chunks)


def test_section_selects_and_repeats(run):
    result = run("inspect", "--section", "frames", "--section", "joints", "--format", "json")
    document = json.loads(result.stdout)
    assert list(document) == ["schema", "robot", "file", "xacro_args", "joints", "frames"]


def test_unknown_section_names_the_valid_ones(run):
    line = assert_one_line_error(run("inspect", "--section", "link"), 2, "'link' is not one of")
    for name in SECTIONS:
        assert f"'{name}'" in line


def test_json_is_stable_and_documented(run, inspect_json):
    document = inspect_json()
    assert document["schema"] == SCHEMA
    assert list(document) == ["schema", "robot", "file", "xacro_args", *SECTIONS]
    again = run("inspect", "--format", "json").stdout
    assert json.loads(again) == document
    joint = {j["name"]: j for j in document["joints"]}["arm_link1_to_link2"]
    assert joint["limits"] == {"lower": -1.57, "upper": 1.57, "velocity": 1.0, "effort": 20.0,
                               "units": {"position": "rad", "velocity": "rad/s",
                                         "effort": "N m"}}
    assert set(document["totals"]) == {"frame", "configuration_rad_or_m", "dof", "mass_kg",
                                       "centre_of_mass_m", "bounding_box_m", "arm", "drive",
                                       "notes"}


def test_markdown_has_a_mermaid_tree_and_tables(run):
    out = run("inspect", "--format", "markdown").stdout
    assert out.startswith("# service_robot\n")
    assert "```mermaid\nflowchart TD\n" in out
    assert "| link | mass [kg] | centre of mass [m] |" in out
    assert "|---|---:|---|---:|---:|---:|" in out
    assert "| arm_link1_to_link2 | -1.57 | 1.57 | 1 | 20 | rad, rad/s, N m |" in out


def test_graph_formats_refuse_other_sections(run):
    assert_one_line_error(run("inspect", "--format", "dot", "--section", "links"), 2,
                          "draws the kinematic tree only")
    assert run("inspect", "--format", "mermaid", "--section", "tree").exit_code == 0


def test_topics_say_where_they_come_from(inspect_json):
    topics = inspect_json("--section", "topics")["topics"]
    assert topics["controllers_found_by"] == "gazebo_ros2_control"
    assert topics["controllers_file"].endswith("controllers.yaml")
    by_name = {t["name"]: t for t in topics["topics"]}
    cmd_vel = by_name["/diff_controller/cmd_vel"]
    assert (cmd_vel["direction"], cmd_vel["message"], cmd_vel["provider"]) == \
        ("in", "geometry_msgs/msg/Twist", "diff_controller")
    assert "diff_drive_controller/DiffDriveController" in cmd_vel["source"]
    assert "cmd_vel_unstamped" in cmd_vel["note"]
    trajectory = by_name["/arm_controller/joint_trajectory"]
    assert (trajectory["direction"], trajectory["message"]) == \
        ("in", "trajectory_msgs/msg/JointTrajectory")
    assert by_name["scan"]["source"] == "ray sensor on lidar_link (libgazebo_ros_ray_sensor.so)"
    assert {n for n, t in by_name.items() if t["direction"] == "out"} == {
        "/diff_controller/odom", "/tf", "/joint_states", "scan", "pi_camera/image_raw",
        "pi_camera/camera_info", "imu/data"}


def test_topics_of_the_real_robot_and_from_the_xacro(inspect_json):
    real = inspect_json("--robot", "real", "--section", "topics")["topics"]
    assert real["controllers_found_by"] == "beside"
    device = next(t for t in real["topics"] if t["kind"] == "device")
    assert device["source"] == ("ros2_control hardware robot_control/SimpleHardwareInterface "
                                "(system ServiceRobotSystem)")
    xacro = inspect_json(XACRO_SOURCE, "hardware:=real", "--section", "topics")
    assert xacro["xacro_args"] == {"hardware": "real"}
    assert xacro["topics"]["topics"] == real["topics"]


def test_controllers_option_and_its_errors(run, inspect_json, tmp_path):
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(REAL_URDF.read_text())
    alone = inspect_json(urdf, "--section", "topics")["topics"]
    assert alone["controllers"] == [] and "--controllers FILE" in alone["notes"][-1]
    given = inspect_json(urdf, "--controllers", CONTROLLERS_YAML, "--section", "topics")
    assert given["topics"]["controllers_found_by"] == "--controllers"
    assert len(given["topics"]["controllers"]) == 3
    bad = tmp_path / "bad.yaml"
    bad.write_text("controller_manager: [unclosed\n")
    assert_one_line_error(run("inspect", urdf, "--controllers", bad), 2, "bad.yaml:2",
                          "not valid YAML")
    other = tmp_path / "other.yaml"
    other.write_text("a: 1\n")
    assert_one_line_error(run("inspect", urdf, "--controllers", other), 2,
                          "no 'controller_manager: ros__parameters:'")
    assert_one_line_error(run("inspect", urdf, "--controllers", tmp_path / "none.yaml"), 2,
                          "none.yaml")


def test_totals_match_pinocchio_free_base(inspect_json):
    import pinocchio as pin

    totals = inspect_json("--section", "totals")["totals"]
    model = pin.buildModelFromUrdf(str(SIM_URDF), pin.JointModelFreeFlyer())
    data = model.createData()
    q = pin.neutral(model)
    assert totals["mass_kg"] == pytest.approx(pin.computeTotalMass(model))
    assert totals["centre_of_mass_m"] == pytest.approx(pin.centerOfMass(model, data, q), abs=1e-9)
    fixed = pin.buildModelFromUrdf(str(SIM_URDF))
    assert pin.computeTotalMass(fixed) == pytest.approx(8.0)  # why we do not use it


def test_totals_follow_the_joint_values(inspect_json):
    bent = inspect_json("--section", "totals", "--joint", "arm_link1_to_link2=-1.57")
    totals = bent["totals"]
    assert totals["configuration_rad_or_m"] == {"arm_link1_to_link2": -1.57}
    # the arm points (almost) straight up from the shoulder at (-0.1, 0, 0.6): top at 1.5 m
    assert totals["bounding_box_m"]["max_m"][2] == pytest.approx(1.5, abs=1e-3)
    assert totals["centre_of_mass_m"][0] < 0.039975 < inspect_json("--section", "totals")[
        "totals"]["centre_of_mass_m"][0]
    assert totals["arm"]["reach_m"] == 0.9  # reach does not depend on the pose


def test_clamp_and_bad_joint_values(run, inspect_json):
    assert_one_line_error(run("inspect", "--joint", "arm_link1_to_link2=2"), 2,
                          "--joint", "outside its limits [-1.57, 1.57]", "--clamp")
    clamped = inspect_json("--section", "totals", "--joint", "arm_link1_to_link2=2", "--clamp")
    assert clamped["totals"]["configuration_rad_or_m"] == {"arm_link1_to_link2": 1.57}
    assert_one_line_error(run("inspect", "--joint", "arm_link1_to_link2=abc"), 2, "not a number")
    assert_one_line_error(run("inspect", "--joint", "arm_link1_to_link2"), 2, "NAME=VALUE")
    assert_one_line_error(run("inspect", "--joint", "camera_joint=0.1"), 2, "is fixed")


def test_a_robot_without_sensors_or_drive(run, inspect_json, tmp_path):
    from tests.inspect.conftest import write_chain

    chain = write_chain(tmp_path / "arm.urdf", 3)
    document = inspect_json(chain)
    assert document["sensors"] == [] and document["totals"]["drive"] is None
    assert "not a differential drive" in document["totals"]["notes"][0]
    # joints 0.1 m apart along z, turning about y: from j0 (z 0.1) to l3 (z 0.3)
    assert document["totals"]["arm"] == {"shoulder": "j0", "tip": "l3", "reach_m": 0.2,
                                         "travel_m": 0.0}
    text = run("inspect", chain).stdout
    assert "Sensors (0): no sensors" in text and "Totals" in text


def test_help_is_light():
    probe = ("import sys, json; from servicebot_cli.cli import main\n"
             "try:\n    main(['inspect', '--help'])\nexcept SystemExit:\n    pass\n"
             "print(json.dumps(sorted(sys.modules)))")
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                            timeout=60)
    modules = {m.split(".")[0] for m in json.loads(result.stdout.splitlines()[-1])}
    assert not modules & {"numpy", "pinocchio", "matplotlib", "trimesh", "yaml", "lxml"}
