"""Every published ray sensor is simulated: its own pose, rays, rate, noise, type, topic, frame.

Nav2's sam_bot (a 360-ray LaserScan LIDAR at 5 Hz) with two more ray sensors, as a Create 3
or a PMB2 carries them beside their LIDAR: a front sonar publishing ``sensor_msgs/Range``
(5 x 5 rays, gaussian noise, 10 Hz) and a rear IR sensor publishing a three-ray LaserScan
(no noise, 20 Hz), each through its own ``gazebo_ros_ray_sensor``. The robot stands still
between two walls at known distances; the bag is read back by rosbags.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import run_servicebot
from tests.simulate.plugin_robots import (
    SAM_BOT,
    bag_messages,
    edited,
    listed_topics,
    run_with_bag,
)

SENSOR = """
  <link name="{name}_link"/>
  <joint name="{name}_joint" type="fixed">
    <parent link="base_link"/>
    <child link="{name}_link"/>
    <origin xyz="{x} 0 0" rpy="0 0 {yaw}"/>
  </joint>
  <gazebo reference="{name}_link">
    <sensor name="{name}" type="ray">
      <update_rate>{rate}</update_rate>
      <ray>
        <scan>
          <horizontal><samples>{samples}</samples><min_angle>-{half}</min_angle>
            <max_angle>{half}</max_angle></horizontal>
          {vertical}
        </scan>
        <range><min>0.02</min><max>{max}</max><resolution>0.01</resolution></range>
        {noise}
      </ray>
      <plugin name="{name}_plugin" filename="libgazebo_ros_ray_sensor.so">
        <ros><remapping>~/out:={name}</remapping></ros>
        <output_type>{output}</output_type>
        <radiation_type>ultrasound</radiation_type>
        <frame_name>{name}_link</frame_name>
      </plugin>
    </sensor>
  </gazebo>
"""
SONAR = SENSOR.format(
    name="sonar_front", x=0.22, yaw=0, rate=10, samples=5, half=0.1, max=2.0,
    vertical="<vertical><samples>5</samples><min_angle>-0.1</min_angle>"
             "<max_angle>0.1</max_angle></vertical>",
    noise="<noise><type>gaussian</type><mean>0</mean><stddev>0.005</stddev></noise>",
    output="sensor_msgs/Range")
IR = SENSOR.format(name="ir_rear", x=-0.22, yaw=math.pi, rate=20, samples=3, half=0.05,
                   max=4.0, vertical="", noise="", output="sensor_msgs/LaserScan")
SONAR_WALL_M, IR_WALL_M = 0.78, 1.28  # from each sensor to the wall it faces
SCENARIO = f"""\
duration_s: 2
initial_pose: {{x_m: 0, y_m: 0, yaw_rad: 0}}
cmd_vel:
  - {{duration_s: 2, linear_m_s: 0}}
world:
  walls:
    - {{from_m: [{0.22 + SONAR_WALL_M + 0.05}, -5], to_m: [{0.22 + SONAR_WALL_M + 0.05}, 5],
        thickness_m: 0.1, height_m: 1}}
    - {{from_m: [{-0.22 - IR_WALL_M - 0.05}, -5], to_m: [{-0.22 - IR_WALL_M - 0.05}, 5],
        thickness_m: 0.1, height_m: 1}}
"""


def _robot(tmp_path: Path, *sensors: str) -> Path:
    """sam_bot with ``sensors`` (URDF text) added."""
    return edited(SAM_BOT, tmp_path / "robot", ("</robot>", "".join(sensors) + "</robot>"))


def _run(robot: Path, tmp_path: Path) -> tuple[dict[str, list], Path]:
    """The bag's messages by topic, and the ``--out`` directory, of the scenario's run."""
    scenario = tmp_path / "scenario.yaml"
    scenario.write_text(SCENARIO)
    out = tmp_path / "out"
    return bag_messages(robot, tmp_path, "-s", scenario, "--out", out), out


@pytest.fixture(scope="module")
def three_sensors(tmp_path_factory) -> tuple[Path, dict[str, list], Path]:
    pytest.importorskip("rosbags")
    tmp_path = tmp_path_factory.mktemp("three")
    robot = _robot(tmp_path, SONAR, IR)
    return robot, *_run(robot, tmp_path)


def test_every_listed_ray_sensor_topic_is_in_the_bag_in_its_type(three_sensors):
    robot, messages, _ = three_sensors
    listed = {"/" + t["name"].lstrip("/"): t["message"] for t in listed_topics(robot)
              if t["provider"] in ("lidar", "sonar_front", "ir_rear")}
    assert listed == {"/scan": "sensor_msgs/msg/LaserScan",
                      "/sonar_front": "sensor_msgs/msg/Range",
                      "/ir_rear": "sensor_msgs/msg/LaserScan"}
    for topic, message in listed.items():
        assert messages[topic][0].__msgtype__ == message


def test_each_ray_sensor_keeps_its_rate_frame_and_rays(three_sensors):
    _, messages, out = three_sensors
    scan, sonar, ir = messages["/scan"], messages["/sonar_front"], messages["/ir_rear"]
    assert (len(scan), len(sonar), len(ir)) == (10, 20, 40)  # 2 s at 5, 10 and 20 Hz
    assert {m.header.frame_id for m in scan} == {"lidar_link"}
    assert {m.header.frame_id for m in sonar} == {"sonar_front_link"}
    assert {m.header.frame_id for m in ir} == {"ir_rear_link"}
    assert {len(m.ranges) for m in scan} == {360}
    assert {len(m.ranges) for m in ir} == {3}
    assert [m.header.stamp.nanosec for m in sonar[:2]] == [100_000_000, 200_000_000]
    summary = json.loads((out / "summary.json").read_text())
    assert [summary["messages"][t] for t in ("/scan", "/sonar_front", "/ir_rear")] == \
        [10, 20, 40]


def test_a_range_sensor_facing_a_wall_reads_its_distance_within_its_noise(three_sensors):
    _, messages, _ = three_sensors
    sonar = messages["/sonar_front"]
    first = sonar[0]
    assert first.radiation_type == 0  # ULTRASOUND
    assert first.field_of_view == pytest.approx(0.2)
    assert (first.min_range, first.max_range) == pytest.approx((0.02, 2.0))
    ranges = np.array([m.range for m in sonar])
    # the least of 25 rays: the middle one meets the wall square on, its noise 5 mm
    assert np.all(np.abs(ranges - SONAR_WALL_M) < 0.025)
    assert abs(np.median(ranges) - SONAR_WALL_M) < 0.015
    assert np.std(ranges) > 0  # noisy


def test_a_noiseless_ir_sensor_facing_backwards_reads_the_rear_wall(three_sensors):
    _, messages, _ = three_sensors
    scan = messages["/ir_rear"][0]
    assert (scan.angle_min, scan.angle_max) == pytest.approx((-0.05, 0.05))
    expected = IR_WALL_M / np.cos(np.array([-0.05, 0.0, 0.05]))
    for message in messages["/ir_rear"]:
        assert np.array(message.ranges) == pytest.approx(expected, abs=1e-6)


def test_each_ray_sensor_has_its_csv_file(three_sensors):
    _, _, out = three_sensors
    for name, rays in (("scan.csv", 360), ("scan_sonar_front.csv", 25),
                       ("scan_ir_rear.csv", 3)):
        header, *rows = (out / name).read_text().splitlines()
        assert len(header.split(",")) == 1 + rays, name
        assert rows
    ir = (out / "scan_ir_rear.csv").read_text().splitlines()
    assert float(ir[1].split(",")[2]) == IR_WALL_M  # the middle ray, exactly


def test_more_ray_sensors_leave_the_lidar_scans_as_they_were(three_sensors, tmp_path):
    _, messages, _ = three_sensors
    alone, _ = _run(_robot(tmp_path), tmp_path)
    assert set(alone) == set(messages) - {"/sonar_front", "/ir_rear"}
    assert [m.ranges.tolist() for m in alone["/scan"]] == \
        [m.ranges.tolist() for m in messages["/scan"]]


def test_sensors_on_bare_links_cast_the_base_together_as_each_alone(tmp_path):
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.sensors import lidar
    from servicebot_cli.simulate.sensors.scan_jobs import fixed_ranges_of

    # the rear sensor looks across the base: its rays meet the base box and the wheels
    body = sim_robot(load(RobotSource.of(_robot(tmp_path, SONAR, IR.replace(
        'xyz="-0.22 0 0" rpy="0 0 3.141592653589793"', 'xyz="0.22 0 0" rpy="0 0 3.14"')))))
    assert [m.link for m in body.ray_sensors] == ["lidar_link", "sonar_front_link",
                                                  "ir_rear_link"]
    together = fixed_ranges_of(body.ray_sensors, body.shape)
    assert together[0] is None  # the LIDAR's link holds a part: cast on its own
    for mounted, fixed in zip(body.ray_sensors[1:], together[1:], strict=True):
        rays = lidar.ray_directions(mounted.spec, mounted.transform_sensor_to_base)
        alone = lidar.fixed_ranges(body.shape, mounted.link, mounted.transform_sensor_to_base,
                                   rays, lidar.ray_start_m(mounted.spec))
        np.testing.assert_array_equal(fixed, alone)
    assert np.isfinite(together[2]).all()  # the turned one's rays all meet the base


def test_two_sensors_on_one_link_and_topic_draw_their_own_noise(tmp_path):
    """A bracket with two sonars publishing on one topic: each its own noise stream."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.simulator import scan_stream

    twin = SONAR.replace('name="sonar_front"', 'name="sonar_twin"').replace(
        '<link name="sonar_front_link"/>', "").split('<gazebo reference="sonar_front_link">')[1]
    robot = _robot(tmp_path, SONAR, '<gazebo reference="sonar_front_link">' + twin)
    body = sim_robot(load(RobotSource.of(robot)))
    sonars = [(i, m) for i, m in enumerate(body.ray_sensors) if m.link == "sonar_front_link"]
    assert [m.name for _, m in sonars] == ["sonar_front", "sonar_twin"]
    assert sonars[0][1].spec.topic == sonars[1][1].spec.topic
    assert scan_stream(*sonars[0]) != scan_stream(*sonars[1])


def test_a_topic_two_sensors_publish_in_two_types_keeps_the_first_and_says_why(tmp_path):
    """One topic holds one message type in a bag: the IR sensor's LaserScan on the sonar's
    Range topic is left out with a note, and the bag reads back whole."""
    pytest.importorskip("rosbags")
    clash = IR.replace("~/out:=ir_rear", "~/out:=sonar_front")
    robot = _robot(tmp_path, SONAR, clash)
    _, messages = run_with_bag(robot, tmp_path)
    assert "/ir_rear" not in messages
    assert {type(m).__name__ for m in messages["/sonar_front"]} == {"sensor_msgs__msg__Range"}
    assert len(messages["/sonar_front"]) == 20  # the sonar's 10 Hz alone, 2 s
    notes = run_servicebot("simulate", robot, "--headless", "--duration-s", "0.5").stderr
    assert ("note: /sonar_front (ray sensor 'ir_rear') is not simulated: ray sensor "
            "'sonar_front' publishes sensor_msgs/Range on that topic, and this one "
            "sensor_msgs/LaserScan; give one of them its own topic") in notes


def test_a_topic_too_long_for_a_file_name_still_gets_its_csv_file(tmp_path):
    """A 290-character topic: its file name is cut to fit (255 bytes at most)."""
    topic = "ir/" + "x" * 287
    robot = _robot(tmp_path, IR.replace("~/out:=ir_rear", f"~/out:={topic}"))
    out = tmp_path / "out"
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "0.5",
                            "--out", out)
    assert result.returncode == 0, result.stderr
    [name] = [p.name for p in out.iterdir() if p.name.startswith("scan_")]
    assert name == f"scan_{('ir_' + 'x' * 287)[:100]}.csv"


@pytest.mark.parametrize(("change", "note"), [
    (("<samples>3</samples>", "<samples>1000000000</samples>"),
     "its 1,000,000,000 rays a scan are more than the 1,000,000 the simulator casts"),
    (("<range><min>0.02</min>", "<range><min>inf</min>"), "its <range><min> must be a number"),
    (("<max>4.0</max>", "<max>nan</max>"), "its <range><min> must be a number"),
    (("<min_angle>-0.05</min_angle>", "<min_angle>nan</min_angle>"),
     "its <min_angle> and <max_angle> must be numbers"),
    (("</range>", "</range><noise><type>gaussian</type><mean>0</mean><stddev>nan</stddev>"
                  "</noise>"), "its <noise> means and standard deviations must be numbers"),
])
def test_a_ray_sensor_the_simulator_cannot_cast_is_left_out_with_a_note(tmp_path, change, note):
    """Values no sensor can have: the run goes on without the sensor and says why (it ended
    in an internal error, or was killed for memory)."""
    robot = _robot(tmp_path, IR.replace(*change))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1")
    assert result.returncode == 0, result.stderr
    assert f"note: /ir_rear (ray sensor 'ir_rear') is not simulated: {note}" in result.stderr
    assert "Warning" not in result.stderr and "Traceback" not in result.stderr


def test_a_ray_sensor_faster_than_gazebos_step_or_beyond_float_is_simulated_as_gazebo_would(
        tmp_path):
    """An update rate of 1e9 Hz is one scan a physics step (1 kHz); a range max of 1e308 is
    +inf in the message's float32, without a warning."""
    pytest.importorskip("rosbags")
    robot = _robot(tmp_path, IR.replace("<update_rate>20</update_rate>",
                                        "<update_rate>1e9</update_rate>")
                   .replace("<max>4.0</max>", "<max>1e308</max>"))
    stdout, messages = run_with_bag(robot, tmp_path, duration_s="0.5")
    scans = messages["/ir_rear"]
    assert len(scans) == 500
    assert all(m.range_max == math.inf for m in scans)

