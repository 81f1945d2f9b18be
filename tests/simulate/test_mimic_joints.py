"""A ``<mimic>`` joint moves with its leader in ``simulate``, as Gazebo's ros2_control holds it.

The bundled robot gets a finger on its last arm link that mimics that link's joint
(``-2 x + 0.1``, with a velocity limit lower than twice the leader's): at every tick of the
run the finger is where the rule puts it, its frame in the bag's ``/tf`` is posed by that
angle (read back with rosbags), and a scenario that commands the finger itself is refused.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from rosbags.highlevel import AnyReader

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate.scenario.definition import load_scenario
from servicebot_cli.simulate.scenario.located import ScenarioError
from servicebot_cli.simulate.session import Outputs, run_and_write
from tests.conftest import assert_one_line_error, run_servicebot

ROBOT = Path(__file__).resolve().parents[2] / "robots" / "service_robot.urdf.xml"
FINGER = """
  <link name="arm_finger"/>
  <joint name="arm_finger_joint" type="revolute">
    <parent link="arm_link4"/>
    <child link="arm_finger"/>
    <origin xyz="0.3 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="0.5"/>
    <mimic joint="arm_link3_to_link4" multiplier="-2" offset="0.1"/>
  </joint>
  <ros2_control"""
SCENARIO = """duration_s: 6
arm:
  joint_names: [{joint}]
  points:
    - {{time_from_start_s: 2, positions: [0.8]}}
    - {{time_from_start_s: 4, positions: [-0.4]}}
"""


def _robot(tmp_path: Path) -> Path:
    robot = tmp_path / "fingered.urdf"
    robot.write_text(ROBOT.read_text().replace("\n  <ros2_control", FINGER, 1))
    controllers = ROBOT.parent / "controllers.yaml"  # beside the robot, as in robots/
    (tmp_path / controllers.name).write_text(controllers.read_text())
    return robot


def test_the_finger_follows_its_leader_at_every_tick(tmp_path):
    robot = _robot(tmp_path)
    scenario_file = tmp_path / "arm.yaml"
    scenario_file.write_text(SCENARIO.format(joint="arm_link3_to_link4"))
    report = run_and_write(load(RobotSource.of(str(robot))), load_scenario(str(scenario_file)),
                           seed=0, outputs=Outputs(bag=str(tmp_path / "bag")),
                           scenario_dir=tmp_path, keep_run=True)
    result = report.result
    assert result is not None
    joints = result.body.arm_joints
    leader = result.arm_positions_rad[:, joints.index("arm_link3_to_link4")]
    finger = result.arm_positions_rad[:, joints.index("arm_finger_joint")]
    assert np.ptp(leader) > 1.0  # the leader moved, faster than the finger's own limit allows
    assert np.max(np.abs(np.diff(finger))) > 0.5 * result.plan.dt_s * 1.5
    assert np.array_equal(finger, -2 * leader + 0.1)
    with AnyReader([tmp_path / "bag"]) as reader:
        angles = {}
        for connection, _, raw in reader.messages(
                [c for c in reader.connections if c.topic == "/tf"]):
            message = reader.deserialize(raw, connection.msgtype)
            for transform in message.transforms:
                if transform.child_frame_id == "arm_finger":
                    q = transform.transform.rotation  # about z: (0, 0, sin, cos) of half the angle
                    stamp = transform.header.stamp
                    angles[stamp.sec + stamp.nanosec * 1e-9] = 2 * math.atan2(q.z, q.w)
    assert len(angles) > 100
    times = np.arange(len(leader)) * result.plan.dt_s
    for time_s, angle in list(angles.items())[::50]:
        tick = int(round(time_s / result.plan.dt_s))
        assert times[tick] == pytest.approx(time_s)
        assert angle == pytest.approx(finger[tick], abs=1e-9)


def test_a_scenario_moving_the_finger_itself_is_refused(tmp_path):
    robot = _robot(tmp_path)
    scenario_file = tmp_path / "finger.yaml"
    scenario_file.write_text(SCENARIO.format(joint="arm_finger_joint"))
    with pytest.raises(ScenarioError, match="mimics 'arm_link3_to_link4'"):
        run_and_write(load(RobotSource.of(str(robot))), load_scenario(str(scenario_file)),
                      seed=0, outputs=Outputs(), scenario_dir=tmp_path)
    result = run_servicebot("simulate", robot, "-s", scenario_file, "--headless")
    assert_one_line_error(result, 2, "'arm_finger_joint' mimics 'arm_link3_to_link4' (x -2 + "
                          "0.1) and moves with it; move 'arm_link3_to_link4' instead")


def _with_joints(tmp_path: Path, joints: str, replace: tuple[str, str] = ("", "")) -> Path:
    robot = tmp_path / "mimics.urdf"
    text = ROBOT.read_text().replace(*replace) if replace[0] else ROBOT.read_text()
    robot.write_text(text.replace("\n  <ros2_control", joints + "\n  <ros2_control", 1))
    controllers = ROBOT.parent / "controllers.yaml"
    (tmp_path / controllers.name).write_text(controllers.read_text())
    return robot


def _follower(name: str, parent: str, leader: str, multiplier: float = 1.0) -> str:
    return f"""
  <link name="{name}_link"/>
  <joint name="{name}" type="revolute">
    <parent link="{parent}"/>
    <child link="{name}_link"/>
    <axis xyz="0 0 1"/>
    <limit lower="-50" upper="50" effort="1" velocity="100"/>
    <mimic joint="{leader}" multiplier="{multiplier}"/>
  </joint>"""


def test_the_built_in_scenario_leaves_a_follower_to_its_leader_with_a_note(tmp_path):
    # the bundled arm's last joint made to follow the one before it
    robot = _with_joints(tmp_path, "", (
        '<limit effort="20.0" lower="-1.57" upper="1.57" velocity="1.0"/>\n  </joint>\n  '
        "<!-- End effector",
        '<limit effort="20.0" lower="-1.57" upper="1.57" velocity="1.0"/>\n    '
        '<mimic joint="arm_link2_to_link3" multiplier="-0.5"/>\n  </joint>\n  <!-- End effector'))
    assert "<mimic" in robot.read_text()
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "20",
                            "--format", "json")
    assert result.returncode == 0, result.stderr
    assert ("note: the built-in scenario moves 'arm_link3_to_link4'; service_robot makes it "
            "mimic 'arm_link2_to_link3', so it follows that joint instead") in result.stderr
    summary = json.loads(result.stdout)
    assert summary["duration_s"] == 20


def test_a_chain_of_followers_names_its_root_and_a_loop_is_told(tmp_path):
    chain = (_follower("f1", "arm_link4", "arm_link3_to_link4")
             + _follower("f2", "f1_link", "f1"))
    robot = _with_joints(tmp_path, chain)
    scenario_file = tmp_path / "f2.yaml"
    scenario_file.write_text(SCENARIO.format(joint="f2"))
    result = run_servicebot("simulate", robot, "-s", scenario_file, "--headless")
    assert_one_line_error(result, 2, "'f2' mimics 'f1' (x 1 + 0)",
                          "move 'arm_link3_to_link4' instead")
    loop = _with_joints(tmp_path, _follower("fa", "arm_link4", "fb")
                        + _follower("fb", "fa_link", "fa"))
    scenario_file.write_text(SCENARIO.format(joint="fa"))
    result = run_servicebot("simulate", loop, "-s", scenario_file, "--headless")
    assert_one_line_error(result, 2, "'fa' is in a loop of <mimic> joints (fa -> fb -> fa)")


def test_a_follower_of_a_wheel_turns_with_it_in_joint_states(tmp_path):
    robot = _with_joints(tmp_path, _follower("spinner", "base_link", "front_left_wheel_joint",
                                             -2.0))
    scenario_file = tmp_path / "spin.yaml"
    scenario_file.write_text(SCENARIO.format(joint="spinner"))
    refused = run_servicebot("simulate", robot, "-s", scenario_file, "--headless")
    assert_one_line_error(refused, 2, "'spinner' mimics 'front_left_wheel_joint' (x -2 + 0) and "
                          "turns with the wheel 'front_left_wheel_joint'; leave it out of arm:")
    scenario_file.write_text("duration_s: 4\ncmd_vel:\n  - {duration_s: 4, linear_m_s: 0.2}\n")
    done = run_servicebot("simulate", robot, "-s", scenario_file, "--headless", "--bag",
                          tmp_path / "bag")
    assert done.returncode == 0, done.stderr
    pairs = []
    with AnyReader([tmp_path / "bag"]) as reader:
        for connection, _, raw in reader.messages(
                [c for c in reader.connections if c.topic == "/joint_states"]):
            message = reader.deserialize(raw, connection.msgtype)
            position = dict(zip(message.name, message.position, strict=True))
            pairs.append((position["front_left_wheel_joint"], position["spinner"]))
    wheel, spinner = np.array(pairs).T
    assert np.ptp(wheel) > 1.0  # the wheel turned
    assert np.allclose(spinner, -2 * wheel, rtol=0, atol=1e-12)
