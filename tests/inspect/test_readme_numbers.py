"""Every number robots/README.md states about the robot equals what `inspect` computes.

The README is parsed, not copied: change a number there or in the xacro, and this fails
until the two agree again. A README number with d decimals must match to half a unit in
its last place.
"""

from __future__ import annotations

import json
import re

import pytest
from click.testing import CliRunner

from servicebot_cli.cli import main
from tests.conftest import ROBOTS

README = (ROBOTS / "README.md").read_text()
NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"


def _section(title: str) -> str:
    return README.split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]


def _rows(title: str) -> dict[str, list[str]]:
    """A README table: first cell (without backticks) to the other cells."""
    rows = {}
    lines = [line for line in _section(title).splitlines() if line.startswith("|")]
    for line in lines[2:]:  # after the header and the rule
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        rows[cells[0].replace("`", "")] = cells[1:]
    return rows


def close(actual: float, stated: str) -> bool:
    """``actual`` equals ``stated`` to the precision the README writes it with."""
    decimals = len(stated.split(".")[1]) if "." in stated and "e" not in stated else 9
    return abs(actual - float(stated)) <= 0.5 * 10 ** -decimals + 1e-12


def _assert_close(actual: list[float], text: str) -> None:
    stated = re.findall(NUMBER, re.sub(r"(?<=\d)-(?=\d)", " ", text))  # "0.12-12" is a range
    assert len(actual) == len(stated), (actual, stated)
    for a, s in zip(actual, stated, strict=True):
        assert close(a, s), f"inspect says {a}, README says {s} in {text!r}"


@pytest.fixture(scope="module")
def sim():
    """inspect's JSON of both bundled robots, by name."""

    def get(robot: str) -> dict:
        result = CliRunner().invoke(main, ["inspect", "--robot", robot, "--format", "json"])
        assert result.exit_code == 0, result.output
        return json.loads(result.stdout)

    return {"sim": get("sim"), "real": get("real")}


def test_totals(sim):
    rows, totals = _rows("Totals (zero configuration)"), sim["sim"]["totals"]
    dof = totals["dof"]
    _assert_close([dof["total"], dof["wheels"], dof["arm"]], rows["degrees of freedom"][0])
    _assert_close([totals["mass_kg"]], rows["total mass"][0])
    _assert_close(totals["centre_of_mass_m"], rows["centre of mass"][0])
    box = totals["bounding_box_m"]
    _assert_close([v for axis in range(3) for v in (box["min_m"][axis], box["max_m"][axis])],
                  rows["bounding box (visual geometry)"][0])
    reach = rows["arm reach"][0]
    assert totals["arm"]["shoulder"] in reach and totals["arm"]["tip"] in reach
    _assert_close([totals["arm"]["reach_m"]], reach.split(",")[0])
    drive = totals["drive"]
    _assert_close([drive["wheel_radius_m"], drive["track_m"], drive["wheelbase_m"]],
                  rows["wheel radius, track (wheel separation), wheelbase"][0])


def test_top_speeds_of_both_files(sim):
    text = _rows("Totals (zero configuration)")["top speed, top turn rate in place"][0]
    for robot, part in zip(("sim", "real"), text.split(";"), strict=True):
        assert robot in part
        drive = sim[robot]["totals"]["drive"]
        _assert_close([drive["top_speed_m_s"], drive["top_turn_rate_rad_s"]],
                      part.replace(robot, ""))


def test_links_mass_geometry_and_inertia(sim):
    links = {link["name"]: link for link in sim["sim"]["links"]}
    for name, (geometry, mass, inertia) in _rows("Links").items():
        if name == "arm_link2..4":
            names = ["arm_link2", "arm_link3", "arm_link4"]
        elif "," in name:
            names = [n.strip() for n in name.split(",")]
        else:
            names = [n for n in links if re.fullmatch(name.split(" (")[0].replace("*", ".*"), n)]
        assert names, name
        if name.endswith("(4)"):
            assert len(names) == 4
        for n in names:
            link = links[n]
            if mass == "0":
                assert link["mass_kg"] is None and not link["visuals"]
                continue
            _assert_close([link["mass_kg"]], mass.split()[0])
            i = link["inertia_kg_m2"]
            if "(each)" in inertia:
                assert i["ixx"] == i["iyy"] == i["izz"]
                _assert_close([i["ixx"]], inertia)
            else:
                _assert_close([i["ixx"], i["iyy"], i["izz"]], inertia)
            assert i["ixy"] == i["ixz"] == i["iyz"] == 0
            _check_geometry(link, geometry)


def _check_geometry(link: dict, text: str) -> None:
    visual, collision = link["visuals"][0], link["collisions"][0]
    assert {k: v for k, v in visual.items() if k != "material"} == \
        {k: v for k, v in collision.items() if k != "material"}
    if text.startswith("box"):
        dims = text.split(",")[0]
        _assert_close(visual["size_m"], dims)
        if "centre" in text:
            _assert_close(visual["xyz_m"], text.split("centre")[1])
    else:
        assert text.startswith("cylinder")
        _assert_close([visual["radius_m"], visual["length_m"]], text.split(", axis")[0])


def test_joint_limits(sim):
    for robot in ("sim", "real"):
        joints = {j["name"]: j for j in sim[robot]["joints"]}
        rows = _rows("Joints")
        wheel_text = rows["4 wheel joints"][1]
        velocity = re.search(rf"({NUMBER}) rad/s \({robot}\)", wheel_text).group(1)
        for name in ("front_left_wheel_joint", "front_right_wheel_joint",
                     "rear_left_wheel_joint", "rear_right_wheel_joint"):
            lim = joints[name]["limits"]
            assert joints[name]["type"] == "continuous" and joints[name]["axis"] == [0, 1, 0]
            _assert_close([lim["velocity"]], velocity)
            _assert_close([lim["effort"]], wheel_text.split("effort")[1])
        for key, (kind, limits) in rows.items():
            for name in re.findall(r"arm_\w+", key):
                j = joints[name]
                assert j["type"] == kind.split(",")[0]
                _assert_close(j["axis"], kind.split("axis")[1].split("(")[0])
                lim = j["limits"]
                _assert_close([lim["lower"], lim["upper"], lim["velocity"], lim["effort"]],
                              limits)


def test_frame_tree_origins_and_the_tool(sim):
    """Each line of the README's frame tree: parent, joint, type, axis and origin."""
    tree = README.split("## Frames", 1)[1].split("```", 2)[1]
    edges = {e["name"]: e for e in sim["sim"]["tree"]["edges"]}
    stack: list[str] = []
    for line in tree.strip().splitlines()[1:]:
        match = re.match(r"^([│ ├└─]*)(\w+)\s+(\w+)\s+(\w+)(.*)$", line)
        assert match, line
        depth = len(match.group(1)) // 4
        child, joint, kind, rest = match.group(2), match.group(3), match.group(4), match.group(5)
        stack[depth - 1:] = [child]
        edge = edges[joint]
        assert (edge["child"], edge["type"]) == (child, kind.rstrip(","))
        assert edge["parent"] == (stack[depth - 2] if depth > 1 else "base_link")
        at = rest.split(" at ")[1] if " at " in rest else "(0, 0, 0)"
        _assert_close(edge["xyz_m"], at.split(")")[0])
        if "rpy" in rest:
            rpy = [float(v.replace("-pi/2", "-1.5707963")) for v in
                   re.findall(r"-?pi/2|-?\d+", rest.split("rpy")[1])]
            assert edge["rpy_rad"] == pytest.approx(rpy, abs=1e-6)
    tool = {f["name"]: f for f in sim["sim"]["frames"]}["arm_tool_link"]
    stated = re.search(r"`arm_tool_link` at (\([^)]*\))", README).group(1)
    _assert_close(tool["root_xyz_m"], stated)


def test_sensors(sim):
    sensors = {s["name"]: s for s in sim["sim"]["sensors"]}
    rows = _rows("Sensors (simulation file only)")
    lidar = sensors["lidar"]
    link, rate, topic, details = rows["lidar (ray), libgazebo_ros_ray_sensor.so"]
    assert lidar["link"] == link and lidar["plugin"] == "libgazebo_ros_ray_sensor.so"
    assert [(t["name"], t["message"]) for t in lidar["topics"]] == \
        [(re.search(r"`(\w+)`", topic).group(1), "sensor_msgs/msg/LaserScan")]
    assert lidar["frame"] == topic.split("frame ")[1]
    _assert_close([lidar["update_rate_hz"]], rate)
    spec = lidar["lidar"]
    _assert_close([spec["samples"], spec["min_angle_rad"], spec["max_angle_rad"],
                   spec["min_range_m"], spec["max_range_m"], spec["range_resolution_m"],
                   spec["noise"]["mean"], spec["noise"]["stddev"]], details)
    camera = sensors["pi_camera"]
    link, rate, topic, details = rows["pi_camera (camera), libgazebo_ros_camera.so"]
    cam = camera["camera"]
    assert (camera["link"], cam["frame"]) == (link, "camera_link_optical")
    assert [t["name"] for t in camera["topics"]] == re.findall(r"`([\w/]+)`", topic)
    _assert_close([camera["update_rate_hz"]], rate)
    _assert_close([cam["width_px"], cam["height_px"], cam["horizontal_fov_rad"],
                   cam["near_clip_m"], cam["far_clip_m"], cam["noise"]["stddev"]],
                  details.replace("R8G8B8", ""))
    imu = sensors["imu"]
    link, rate, topic, details = rows["imu (imu), libgazebo_ros_imu_sensor.so"]
    assert imu["link"] == link and imu["imu"]["topic"] == "imu/data"
    _assert_close([imu["update_rate_hz"]], rate)
    gyro, accel = imu["imu"]["angular_velocity_noise"], imu["imu"]["linear_acceleration_noise"]
    assert all(n == gyro[0] for n in gyro) and all(n == accel[0] for n in accel)
    assert gyro[0]["bias_mean"] == gyro[0]["bias_stddev"] == 0  # "no bias"
    _assert_close([gyro[0]["stddev"], accel[0]["stddev"]], details.replace("m/s^2", "m/s"))


def test_interfaces_topics_and_hardware(sim):
    text = _section("Interfaces")
    for robot, limit in (("sim", "0.44"), ("real", "0.5")):
        joints = {j["name"]: j for j in sim[robot]["interfaces"]["joints"]}
        wheel = joints["front_left_wheel_joint"]
        assert [i["name"] for i in wheel["command"]] == ["velocity"]
        assert [i["name"] for i in wheel["state"]] == ["position", "velocity"]
        assert f"+/-{limit} rad/s ({robot})" in text
        _assert_close([-wheel["command"][0]["min"], wheel["command"][0]["max"]],
                      f"{limit} {limit}")
        arm = joints["arm_link1_to_link2"]["command"][0]
        assert arm["name"] == "position"
        _assert_close([arm["min"], arm["max"]], "[-1.57, 1.57]")
    names = {t["name"] for t in sim["sim"]["topics"]["topics"]}
    paragraphs = text.split("`ros2_control` system")[0]
    assert "Inputs:" in paragraphs and "Outputs:" in paragraphs
    for topic in re.findall(r"`(/?[a-z_]+(?:/[a-z_]+)*)`", paragraphs):
        if topic != "/dev/ttyUSB0":
            assert topic in names, topic
    hardware = {p["name"]: p["value"] for p in sim["real"]["plugins"]["ros2_control"][0]["params"]}
    for key, value in re.findall(r"`(\w+)` = `([^`]+)`", text):
        assert hardware[key] == value
    devices = [t for t in sim["real"]["topics"]["topics"] if t["kind"] == "device"]
    assert [(d["name"], d["message"]) for d in devices] == [("/dev/ttyUSB0", "serial, 9600 baud")]
