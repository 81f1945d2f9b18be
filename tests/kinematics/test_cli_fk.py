"""``servicebot fk`` from the command line: text, JSON, frames, units, bad input."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import FIXTURES, assert_one_line_error, run_servicebot
from tests.kinematics.robots import PANDA, UR5


def test_default_is_the_arm_tool_frame_at_zero(run):
    result = run("fk")
    assert result.exit_code == 0 and result.stderr == ""
    assert result.stdout.splitlines() == [
        "arm_tool_link in base_link",
        "  position [m]          0.8  0  0.6",
        "  roll pitch yaw [rad]  0  0  0",
        "  quaternion x y z w    0  0  0  1",
        "  matrix                1  0  0  0.8",
        "                        0  1  0    0",
        "                        0  0  1  0.6",
        "                        0  0  0    1",
    ]


def test_json_has_every_representation(run):
    result = run("fk", "-j", "arm_base_to_link1=0.5", "-j", "arm_link1_to_link2=-0.4",
                 "--format", "json")
    assert result.exit_code == 0
    answer = json.loads(result.stdout)
    assert list(answer) == ["robot", "relative_to", "angle_unit", "joints", "poses"]
    assert answer["relative_to"] == "base_link" and answer["angle_unit"] == "rad"
    assert answer["joints"]["arm_base_to_link1"] == 0.5
    assert answer["joints"]["front_left_wheel_joint"] == 0.0
    [pose] = answer["poses"]
    assert list(pose) == ["frame", "position_m", "rpy_rad", "quaternion_xyzw", "matrix"]
    reach = 0.9 * np.array([math.cos(0.5) * math.cos(-0.4), math.sin(0.5) * math.cos(-0.4),
                            math.sin(0.4)])
    assert pose["position_m"] == pytest.approx([-0.1 + reach[0], reach[1], 0.6 + reach[2]])
    assert pose["rpy_rad"] == pytest.approx([0.0, -0.4, 0.5])
    matrix = np.array(pose["matrix"])
    assert matrix[:3, 3] == pytest.approx(pose["position_m"])
    x, y, z, w = pose["quaternion_xyzw"]
    assert matrix[0, 0] == pytest.approx(1 - 2 * (y * y + z * z))


def test_degrees_in_and_out(run):
    rad = json.loads(run("fk", "-j", "arm_link1_to_link2=0.5", "--format", "json").stdout)
    deg = json.loads(run("fk", "--deg", "-j", f"arm_link1_to_link2={math.degrees(0.5)}",
                         "--format", "json").stdout)
    assert deg["angle_unit"] == "deg" and deg["joints"]["arm_link1_to_link2"] == \
        pytest.approx(math.degrees(0.5))
    assert deg["poses"][0]["position_m"] == pytest.approx(rad["poses"][0]["position_m"])
    assert deg["poses"][0]["rpy_deg"] == pytest.approx([0, math.degrees(0.5), 0])


def test_several_frames_relative_to_another(run):
    result = run("fk", "-f", "arm_link2", "-f", "arm_tool_link", "--relative-to",
                 "arm_base_link", "--format", "json")
    poses = json.loads(result.stdout)["poses"]
    assert [p["frame"] for p in poses] == ["arm_link2", "arm_tool_link"]
    assert poses[0]["position_m"] == pytest.approx([0, 0, 0.4])
    assert poses[1]["position_m"] == pytest.approx([0.9, 0, 0.4])
    text = run("fk", "-f", "arm_link2", "-f", "camera_link").stdout
    assert "arm_link2 in base_link" in text and "\n\ncamera_link in base_link" in text


def test_all_frames_is_one_table_of_every_link(run):
    result = run("fk", "--all-frames")
    lines = result.stdout.splitlines()
    assert lines[0] == "every frame in base_link"
    assert lines[1].split()[:4] == ["frame", "x", "[m]", "y"]
    frames = [line.split()[0] for line in lines[3:]]
    assert len(frames) == 15 and frames[0] == "base_link" and frames[-1] == "arm_tool_link"
    optical = next(line for line in lines if line.startswith("camera_link_optical"))
    assert optical.split()[1:] == ["0.275", "0", "0.05", "-1.5708", "0", "-1.5708"]
    assert len(json.loads(run("fk", "--all-frames", "--format", "json").stdout)["poses"]) == 15


def test_continuous_joints_take_any_angle(run):
    result = run("fk", "-j", "front_left_wheel_joint=7", "-f", "front_left_wheel",
                 "--format", "json")
    pose = json.loads(result.stdout)["poses"][0]
    assert pose["rpy_rad"][1] == pytest.approx(math.asin(math.sin(7.0)))
    assert json.loads(result.stdout)["joints"]["front_left_wheel_joint"] == 7.0


def test_other_robots_tool_frames_and_a_note_when_the_choice_is_not_named_tool(run):
    assert run("fk", UR5).stdout.startswith("tool0 in world")
    panda = run("fk", PANDA, "-j", "panda_joint4=-1")
    assert panda.stdout.startswith("panda_hand_tcp in panda_link0") and panda.stderr == ""
    planar = run("fk", FIXTURES / "planar_2r.urdf")
    assert planar.stdout.startswith("tip in base")
    assert planar.stderr == ("note: no --frame given; using 'tip', the tip of the longest "
                             "chain (2 joints)\n")


def test_mimic_joints_follow_and_unnamed_joints_outside_limits_are_noted(run):
    result = run("fk", PANDA, "-j", "panda_finger_joint1=0.03", "-f", "panda_rightfinger",
                 "--relative-to", "panda_hand", "--format", "json")
    assert json.loads(result.stdout)["poses"][0]["position_m"][1] == pytest.approx(-0.03)
    assert result.stderr == ("note: panda_joint4 not given: 0, outside the limits "
                             "(give panda_joint4=VALUE for a reachable pose)\n")


def test_a_mimic_joint_given_a_value_the_mimic_does_not_make_is_noted(run):
    """A joint_states snapshot may give the followers too: used as given, as
    robot_state_publisher does, where it agrees silently, and where not with a note (it was
    used with none)."""
    agrees = run("fk", PANDA, "-j", "panda_joint4=-1", "-j", "panda_finger_joint1=0.03",
                 "-j", "panda_finger_joint2=0.03", "-f", "panda_rightfinger",
                 "--relative-to", "panda_hand", "--format", "json")
    assert agrees.stderr == ""
    result = run("fk", PANDA, "-j", "panda_joint4=-1", "-j", "panda_finger_joint1=0.03",
                 "-j", "panda_finger_joint2=0.01", "-f", "panda_rightfinger",
                 "--relative-to", "panda_hand", "--format", "json")
    assert json.loads(result.stdout)["poses"][0]["position_m"][1] == pytest.approx(-0.01)
    assert result.stderr == ("note: joint 'panda_finger_joint2' follows 'panda_finger_joint1' "
                             "(<mimic>), which makes it 0.03; the 0.01 given is used, as "
                             "robot_state_publisher takes a value from joint_states\n")


@pytest.mark.parametrize(("args", "needles"), [
    (["-f", "tool"], ["no frame 'tool'", "nearest first: arm_tool_link,"]),
    (["-f", "arm_tol_link"], ["did you mean 'arm_tool_link'"]),
    (["--relative-to", "base"], ["no frame 'base'", "did you mean 'base_link'"]),
    (["-j", "arm_link1_to_lnk2=0.1"], ["no joint 'arm_link1_to_lnk2'",
                                       "did you mean 'arm_link1_to_link2'"]),
    (["-j", "arm_link1_to_link2=2"], ["'arm_link1_to_link2' = 2 rad is outside its limits "
                                      "[-1.57, 1.57] rad", "--clamp"]),
    (["--deg", "-j", "arm_link1_to_link2=100"], ["= 100 deg is outside its limits "
                                                 "[-89.9544, 89.9544] deg"]),
    (["-j", "arm_link1_to_link2=abc"], ["'abc' for joint 'arm_link1_to_link2' is not a number"]),
    (["-j", "arm_link1_to_link2=nan"], ["not a finite number"]),
    (["-j", "arm_link1_to_link2"], ["is not NAME=VALUE"]),
    (["-j", "arm_link1_to_link2=1", "-j", "arm_link1_to_link2=0"], ["given twice"]),
    (["-f", "arm_link2", "--all-frames"], ["--frame or --all-frames, not both"]),
    (["-o", "x.jsonl"], ["--output has no effect without --configs FILE"]),
])
def test_bad_input_is_one_line_and_exit_2(run, args, needles):
    assert_one_line_error(run("fk", *args), 2, *needles)


def test_clamp_clamps_instead(run):
    result = run("fk", "-j", "arm_link1_to_link2=2", "--clamp", "--format", "json")
    assert json.loads(result.stdout)["joints"]["arm_link1_to_link2"] == 1.57


def test_as_a_real_process():
    result = run_servicebot("fk", "-j", "arm_base_to_link1=0.3", "--format", "json")
    assert result.returncode == 0 and result.stderr == ""
    assert json.loads(result.stdout)["poses"][0]["frame"] == "arm_tool_link"


def _bundled_with(path: Path, joints: str) -> Path:
    """The bundled robot with ``joints`` (links and joints) added before its ros2_control."""
    bundled = Path(__file__).resolve().parents[2] / "robots" / "service_robot.urdf.xml"
    path.write_text(bundled.read_text().replace("\n  <ros2_control",
                                                joints.rstrip("\n") + "\n  <ros2_control", 1))
    return path


def test_a_follower_its_leader_puts_outside_its_limits_names_the_leader(run, tmp_path):
    """The user gave the leader a value inside its limits: the error says which to change."""
    robot = _bundled_with(tmp_path / "fingered.urdf", """
  <link name="arm_finger"/>
  <joint name="arm_finger_joint" type="revolute">
    <parent link="arm_link4"/><child link="arm_finger"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="0.5"/>
    <mimic joint="arm_link3_to_link4" multiplier="-2" offset="0.1"/>
  </joint>
""")
    assert_one_line_error(
        run("fk", robot, "-j", "arm_link3_to_link4=0.9", "-f", "arm_finger"), 2,
        "joint 'arm_finger_joint' = -1.7 rad is outside its limits [-1, 1] rad: it mimics "
        "'arm_link3_to_link4' = 0.9 rad (x -2 + 0.1 rad); give 'arm_link3_to_link4' a value "
        "that keeps it inside, or --clamp")
    assert_one_line_error(
        run("fk", robot, "--deg", "-j", "arm_link3_to_link4=50", "-f", "arm_finger"), 2,
        "it mimics 'arm_link3_to_link4' = 50 deg (x -2 + 5.72958 deg)")
    inside = run("fk", robot, "-j", "arm_link3_to_link4=0.5", "-f", "arm_finger",
                 "--format", "json")
    assert inside.exit_code == 0, inside.stderr
    assert json.loads(inside.stdout)["joints"]["arm_finger_joint"] == pytest.approx(-0.9)


def test_a_follower_of_a_follower_is_checked_and_names_the_joint_given(run, tmp_path):
    """fa follows fb, which follows the arm joint: fa's limits hold too, and the message
    gives the composed rule from the joint the user gave (a negative offset as such)."""
    robot = _bundled_with(tmp_path / "chained.urdf", """
  <link name="fb"/><link name="fa"/>
  <joint name="fb_joint" type="revolute">
    <parent link="arm_link4"/><child link="fb"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="0.5"/>
    <mimic joint="arm_link3_to_link4" multiplier="1" offset="-0.1"/>
  </joint>
  <joint name="fa_joint" type="revolute">
    <parent link="fb"/><child link="fa"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="0.5"/>
    <mimic joint="fb_joint" multiplier="2"/>
  </joint>
""")
    assert_one_line_error(
        run("fk", robot, "-j", "arm_link3_to_link4=0.9", "-f", "fa"), 2,
        "joint 'fa_joint' = 1.6 rad is outside its limits [-1, 1] rad: it mimics "
        "'arm_link3_to_link4' = 0.9 rad (x 2 - 0.2 rad); give 'arm_link3_to_link4' a value")
    inside = run("fk", robot, "-j", "arm_link3_to_link4=0.5", "-f", "fa", "--format", "json")
    assert inside.exit_code == 0, inside.stderr
    assert json.loads(inside.stdout)["joints"]["fa_joint"] == pytest.approx(0.8)


def test_a_sliding_follower_of_a_turning_leader_shows_the_rule_in_the_units_shown(run,
                                                                                 tmp_path):
    robot = _bundled_with(tmp_path / "slider.urdf", """
  <link name="slider"/>
  <joint name="slider_joint" type="prismatic">
    <parent link="arm_link4"/><child link="slider"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.01" effort="1" velocity="0.5"/>
    <mimic joint="arm_link3_to_link4" multiplier="0.02"/>
  </joint>
""")
    result = run("fk", robot, "--deg", "-j", "arm_link3_to_link4=60", "-f", "slider")
    # 60 deg x 0.000349066 m/deg = 0.020944 m
    assert_one_line_error(result, 2, "'slider_joint' = 0.020944 m is outside its limits "
                          "[0, 0.01] m: it mimics 'arm_link3_to_link4' = 60 deg "
                          "(x 0.000349066 + 0 m)")


def test_a_base_too_far_out_for_a_double_is_refused(run):
    """At 1e308 m the arm's own offset was lost without a word (1e308 + 0.3 is 1e308)."""
    assert_one_line_error(run("fk", "--base", "1e308", "1e308", "0"), 2,
                          "--base: x and y are metres within +-1e+06")
