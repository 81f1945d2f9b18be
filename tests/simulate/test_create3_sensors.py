"""simulate on iRobot's Create 3, unmodified: each of its eleven ray sensors as the URDF says.

``irobot_create_description`` (iRobotEducation/create3_sim, vendored under tests/realworld/ws/src)
carries four cliff sensors (one ray each, pitched 80 degrees down) and seven IR intensity
sensors behind the bumper (5 x 5 rays over 10 degrees, 25-200 mm), all Gazebo Classic ray
sensors at 62 Hz with iRobot's own ROS plugins. It is expanded as irobot_create_common_bringup's
``robot_description.launch.py`` expands it (``gazebo:=classic``, its default) and stands still
for two seconds with a wall ahead of its front IR sensor.

What is expected comes from the URDF alone: the real xacro expands it (``$(find)`` answered from
the workspace, as ament would), ElementTree reads the ``<sensor>`` tags, yourdfpy places their
links. The bag is read back by rosbags; what ``inspect --section topics`` lists is the contract.
"""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pytest

from tests.simulate.helpers import REALWORLD_SRC
from tests.simulate.plugin_robots import bag_messages, listed_topics

if TYPE_CHECKING:
    import yourdfpy

CREATE3 = REALWORLD_SRC / "irobot_create_description" / "urdf" / "create3.urdf.xacro"
LAUNCH_ARGS = {"gazebo": "classic", "visualize_rays": "false", "namespace": ""}
DURATION_S = 2
FRONT_IR = "ir_intensity_front_center_left"  # on the robot's axis, looking straight ahead
IR_WALL_M = 0.10  # from the front IR sensor to the wall's face
ONE_RAY_SLACK_M = 3e-5  # see test_a_one_sample_cliff_ray_is_cast_along_the_sensor_axis


@dataclass(frozen=True)
class RaySensor:
    """One ``<sensor type="ray">`` of the expanded URDF, as written there."""

    name: str
    link: str
    rate_hz: float
    samples: int
    min_angle_rad: float
    max_angle_rad: float
    min_range_m: float
    max_range_m: float


def _expanded(tmp_path: Path) -> Path:
    """create3.urdf.xacro expanded by the real xacro, with the launch file's arguments."""
    import xacro
    import xacro.substitution_args

    with pytest.MonkeyPatch.context() as patch:  # ament's index, for the vendored packages
        patch.setattr(xacro.substitution_args, "_eval_find",
                      lambda package: str(REALWORLD_SRC / package))
        document = xacro.process_file(str(CREATE3), mappings=LAUNCH_ARGS)
    urdf = tmp_path / "create3.urdf"
    urdf.write_text(document.toxml())
    return urdf


def _ray_sensors(urdf: Path) -> list[RaySensor]:
    """Every ray sensor with a ROS plugin, in URDF order."""
    sensors = []
    for gazebo in ET.parse(urdf).getroot().iter("gazebo"):
        for sensor in gazebo.findall("sensor[@type='ray']"):
            if sensor.find("plugin") is None:
                continue
            horizontal = sensor.find("ray/scan/horizontal")
            sensors.append(RaySensor(
                name=sensor.get("name"), link=gazebo.get("reference"),
                rate_hz=float(sensor.findtext("update_rate")),
                samples=int(float(horizontal.findtext("samples"))),
                min_angle_rad=float(horizontal.findtext("min_angle")),
                max_angle_rad=float(horizontal.findtext("max_angle")),
                min_range_m=float(sensor.findtext("ray/range/min")),
                max_range_m=float(sensor.findtext("ray/range/max"))))
    return sensors


def _scenario(tmp_path: Path, face_x_m: float) -> Path:
    """Two seconds standing still at the origin; a wall whose face is at x = ``face_x_m``."""
    scenario = tmp_path / "create3.yaml"
    scenario.write_text(f"""\
duration_s: {DURATION_S}
initial_pose: {{x_m: 0, y_m: 0, yaw_rad: 0}}
cmd_vel:
  - {{duration_s: {DURATION_S}, linear_m_s: 0}}
world:
  walls:
    - {{from_m: [{face_x_m + 0.05}, -1], to_m: [{face_x_m + 0.05}, 1], thickness_m: 0.1,
        height_m: 0.5}}
""")
    return scenario


@dataclass(frozen=True)
class Run:
    """The robot's sensors and transforms, inspect's listed topics and the run's outputs."""

    sensors: list[RaySensor]
    urdf: yourdfpy.URDF  # at the zero configuration
    listed: dict[str, dict]  # provider -> its published topic's record
    messages: dict[str, list]
    summary: dict


@pytest.fixture(scope="module")
def create3(tmp_path_factory) -> Run:
    pytest.importorskip("rosbags")
    import yourdfpy

    tmp_path = tmp_path_factory.mktemp("create3")
    urdf_path = _expanded(tmp_path)
    sensors = _ray_sensors(urdf_path)
    urdf = yourdfpy.URDF.load(str(urdf_path), load_meshes=False,
                              build_collision_scene_graph=False)
    front = urdf.get_transform(FRONT_IR, "base_link")
    scenario = _scenario(tmp_path, float(front[0, 3]) + IR_WALL_M)
    out = tmp_path / "out"
    messages = bag_messages(CREATE3, tmp_path, "-s", scenario, "--out", out,
                            duration_s=str(DURATION_S))
    listed = {t["provider"]: t for t in listed_topics(CREATE3)
              if t["direction"] == "out" and t["provider"] in {s.name for s in sensors}}
    summary = json.loads((out / "summary.json").read_text())
    return Run(sensors, urdf, listed, messages, summary)


def _topic(run: Run, sensor: RaySensor) -> str:
    """The sensor's topic in the bag: inspect's name, absolute (the plugins' nodes are at /)."""
    return "/" + run.listed[sensor.name]["name"].lstrip("/")


def test_inspect_lists_a_topic_for_each_ray_sensor_of_the_urdf(create3):
    names = [s.name for s in create3.sensors]
    assert len(names) == 11
    assert sum(n.startswith("cliff_") for n in names) == 4
    assert sum(n.startswith("ir_intensity_") for n in names) == 7
    assert set(create3.listed) == set(names)


def test_every_listed_ray_topic_is_in_the_bag_in_the_type_inspect_names(create3):
    for sensor in create3.sensors:
        topic = _topic(create3, sensor)
        assert topic in create3.messages, (sensor.name, sorted(create3.messages))
        message_type = create3.listed[sensor.name]["message"]
        assert {m.__msgtype__ for m in create3.messages[topic]} == {message_type}, topic


def test_each_sensor_publishes_at_its_update_rate(create3):
    for sensor in create3.sensors:
        topic = _topic(create3, sensor)
        expected = math.floor(DURATION_S * sensor.rate_hz + 1e-9)  # one per period, not at 0
        assert len(create3.messages[topic]) == expected, topic
        assert create3.summary["messages"][topic] == expected, topic
        stamps_s = np.array([m.header.stamp.sec + m.header.stamp.nanosec * 1e-9
                             for m in create3.messages[topic]])
        assert np.all(np.diff(stamps_s) > 0), topic
        assert np.mean(np.diff(stamps_s)) == pytest.approx(1 / sensor.rate_hz, abs=1e-3)
        assert 0 < stamps_s[0] <= 1 / sensor.rate_hz + 1e-3
        assert stamps_s[-1] <= DURATION_S + 1e-9


def test_each_scan_is_in_its_sensors_link_with_its_rays_and_limits(create3):
    for sensor in create3.sensors:
        for message in create3.messages[_topic(create3, sensor)]:
            assert message.header.frame_id == sensor.link
            assert len(message.ranges) == sensor.samples
            assert (message.range_min, message.range_max) == \
                pytest.approx((sensor.min_range_m, sensor.max_range_m))
            assert message.angle_min == pytest.approx(sensor.min_angle_rad)
            assert message.angle_max == pytest.approx(sensor.max_angle_rad)
            # Gazebo's RaySensor divides the span by (samples - 1): a cliff sensor's one ray
            # has a step of +inf
            span = sensor.max_angle_rad - sensor.min_angle_rad
            assert message.angle_increment == (math.inf if sensor.samples == 1 else
                                               pytest.approx(span / (sensor.samples - 1)))


def _floor_z_m(urdf: yourdfpy.URDF) -> float:
    """Height of the floor in base_link: the lowest point of the drive wheels at rest.

    Each wheel is a cylinder on a continuous joint; with its axis ``a`` (unit, in base_link)
    its lowest point is ``c_z - r sqrt(1 - a_z^2) - (L/2) |a_z|``.
    """
    lowest = []
    for joint in urdf.robot.joints:
        if joint.type != "continuous":
            continue
        link = urdf.link_map[joint.child]
        transform_wheel_to_base = urdf.get_transform(link.name, "base_link")
        for collision in link.collisions:
            cylinder = collision.geometry.cylinder
            placed = transform_wheel_to_base @ (collision.origin if collision.origin is not None
                                                else np.eye(4))
            axis_z = placed[2, 2]
            lowest.append(placed[2, 3] - cylinder.radius * math.sqrt(1 - axis_z**2)
                          - cylinder.length / 2 * abs(axis_z))
    assert len(lowest) == 2  # left and right
    return min(lowest)


def _cliff_floor_ranges(run: Run) -> dict[str, float]:
    """Each cliff sensor's distance to the floor along its x axis (Gazebo's one-sample ray)."""
    floor_z = _floor_z_m(run.urdf)
    ranges = {}
    for sensor in run.sensors:
        if not sensor.name.startswith("cliff_"):
            continue
        transform_sensor_to_base = run.urdf.get_transform(sensor.link, "base_link")
        origin, direction = transform_sensor_to_base[:3, 3], transform_sensor_to_base[:3, 0]
        assert direction[2] < -0.9  # it looks down
        ranges[sensor.name] = (floor_z - origin[2]) / direction[2]
    return ranges


def test_cliff_sensors_read_the_floor_distance_their_pose_implies(create3):
    expected = _cliff_floor_ranges(create3)
    assert len(expected) == 4
    for sensor in create3.sensors:
        if sensor.name not in expected:
            continue
        assert sensor.min_range_m < expected[sensor.name] < sensor.max_range_m
        assert expected[sensor.name] == pytest.approx(0.01498, abs=1e-5)  # 14.75 mm / sin 80
        ranges = np.array([m.ranges[0] for m in create3.messages[_topic(create3, sensor)]])
        np.testing.assert_allclose(ranges, expected[sensor.name], rtol=0,
                                   atol=ONE_RAY_SLACK_M, err_msg=sensor.name)


def test_a_one_sample_cliff_ray_is_cast_along_the_sensor_axis(create3):
    # the cliff scans span [-2.5, 2.5] degrees with one sample: at -2.5 degrees the range is
    # 1/cos(2.5 deg) longer, 1.4e-5 m here, within ONE_RAY_SLACK_M above
    expected = _cliff_floor_ranges(create3)
    for sensor in create3.sensors:
        if sensor.name in expected:
            ranges = [m.ranges[0] for m in create3.messages[_topic(create3, sensor)]]
            assert ranges == pytest.approx([expected[sensor.name]] * len(ranges), abs=1e-6)


def test_ir_sensors_facing_the_wall_read_its_distance(create3):
    face_x_m = create3.urdf.get_transform(FRONT_IR, "base_link")[0, 3] + IR_WALL_M
    for sensor in create3.sensors:
        if not sensor.name.startswith("ir_intensity_"):
            continue
        transform_sensor_to_base = create3.urdf.get_transform(sensor.link, "base_link")
        origin, direction = transform_sensor_to_base[:3, 3], transform_sensor_to_base[:3, 0]
        along_m = (face_x_m - origin[0]) / direction[0] if direction[0] > 0 else math.inf
        expected = along_m if along_m < sensor.max_range_m else math.inf
        middle = sensor.samples // 2  # the ray on the sensor's axis; noise: none
        readings = [m.ranges[middle] for m in create3.messages[_topic(create3, sensor)]]
        if sensor.name == FRONT_IR:
            assert expected == pytest.approx(IR_WALL_M)
        if math.isinf(expected):  # the wall is beyond its reach
            assert set(readings) == {math.inf}, sensor.name
        else:
            error_m = np.abs(np.array(readings) - expected)
            assert error_m.max() < 1e-6, (sensor.name, expected, readings[0])


def test_the_wheel_drops_are_running_gear_not_an_arm(create3):
    """Its wheels hang from prismatic wheel-drop joints: inspect's chassis, as a suspension's
    rockers are; the summary has no arm and no end effector, and the drops' states are sent."""
    drops = [j.name for j in create3.urdf.robot.joints if j.type == "prismatic"]
    assert len(drops) == 2
    assert create3.summary["arm_final_positions_rad"] == {}
    assert create3.summary["end_effector"] is None
    states = create3.messages["/joint_states"]
    assert set(drops) <= set(states[-1].name)
    assert all(states[-1].position[list(states[-1].name).index(d)] == 0.0 for d in drops)


def test_the_plot_names_the_first_ray_sensor_by_its_topic_on_a_robot_without_a_lidar(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.simulate.files.plot import Track, _draw_map
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.simulate.session import Outputs, default_arm_for, run_and_write

    urdf = _expanded(tmp_path)
    labels, topics = {}, {}
    for name, source in (("create3", RobotSource.of(str(urdf))),
                         ("bundled", RobotSource.bundled("sim"))):
        robot = load(source)
        scenario, _ = default_arm_for(load_scenario(None), robot)  # as the command does
        run = run_and_write(robot, scenario, seed=0, outputs=Outputs(),
                            scenario_dir=tmp_path, keep_run=True).result
        assert run is not None
        track = Track(run, len(run.odometry.times_s))
        track.add(run)
        assert track.scan is not None
        if not len(track.scan):  # the IR sensor sees no wall at the end: a point to draw
            track.scan = np.array([[0.0, 0.0]])
        figure, axes = plt.subplots()
        _draw_map(axes, track)
        labels[name] = [text.get_text() for text in axes.legend().get_texts()]
        plt.close(figure)
        topic = run.body.ray_sensors[0].spec.topic
        assert f"scan on {topic} at {track.scan_time_s:.1f} s" in labels[name]
        topics[name] = topic
    assert topics["bundled"].endswith("scan")  # its LIDAR
    # an IR sensor, named by its topic (one that begins with "_", which a legend would hide)
    assert "ir_intensity" in topics["create3"]
    assert not any("LIDAR" in label for label in labels["create3"])
