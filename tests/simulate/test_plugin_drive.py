"""A base that a Gazebo diff-drive plugin drives: odometry where, how often and how sure the
plugin says, read back from the bag by rosbags (a reader that shares no code with ours).

Real descriptions, no ROS set: Nav2's sam_bot (Gazebo Classic's ROS 2 plugin in /demo,
default 100 Hz), TurtleBot3 (the ROS 1 plugin, ``<updateRate>30``) and Leo Rover (gz-sim's
DiffDrive system, ``<odom_publish_frequency>20``, acceleration limits). The numbers the
plugins default to are those of their sources (gazebo_ros_pkgs, gz-sim).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import REPO, assert_one_line_error, run_servicebot
from tests.simulate.helpers import NO_ROS, REALWORLD_SRC
from tests.simulate.plugin_robots import run_with_bag

FIXTURES = REPO / "tests" / "fixtures"
SAM_BOT = FIXTURES / "sam_bot_description" / "src" / "description" / "sam_bot_description.urdf"
LEO = FIXTURES / "leo_description" / "urdf" / "leo_sim.urdf.xacro"
TURTLEBOT3 = REALWORLD_SRC / "turtlebot3_description" / "urdf" / "turtlebot3_burger.urdf.xacro"
PLUGIN = "Gazebo plugin libgazebo_ros_diff_drive.so"


def _run(robot: Path, tmp_path: Path, *extra: str) -> tuple[dict, dict[str, list]]:
    stdout, messages = run_with_bag(robot, tmp_path, "--format", "json", *extra,
                                    duration_s="10")
    return json.loads(stdout), messages


def test_sam_bot_odometry_is_the_classic_plugins_in_its_namespace(tmp_path):
    pytest.importorskip("rosbags")
    summary, messages = _run(SAM_BOT, tmp_path)
    assert "/diff_controller/odom" not in messages
    odometry = messages["/demo/odom"]
    assert len(odometry) == 1000  # 10 s at <update_rate>'s default, 100 Hz
    pose = list(odometry[-1].pose.covariance)
    assert (pose[0], pose[7], pose[14], pose[35]) == (1e-5, 1e-5, 1e12, 1e-3)
    assert list(odometry[-1].twist.covariance) == pose
    assert summary["controller"]["publish_rate_hz"] == {"value": 100.0, "source": PLUGIN}
    assert summary["controller"]["update_rate_hz"]["source"] == "default"


def test_turtlebot3_odometry_is_its_ros1_plugins_odometry_topic_at_its_update_rate(tmp_path):
    pytest.importorskip("rosbags")
    summary, messages = _run(TURTLEBOT3, tmp_path)
    assert len(messages["/odom"]) == 300  # <updateRate>30</updateRate>
    assert len(messages["/imu"]) == 1000  # the IMU's 200 Hz, at most once a control tick
    assert summary["controller"]["publish_rate_hz"] == {"value": 30.0, "source": PLUGIN}


def test_leo_odometry_and_limits_are_the_gz_diff_drive_systems(tmp_path):
    pytest.importorskip("rosbags")
    summary, messages = _run(LEO, tmp_path)
    assert len(messages["/odom"]) == 200  # <odom_publish_frequency>20
    source = "Gazebo plugin libignition-gazebo-diff-drive-system.so"
    controller = summary["controller"]
    assert controller["max_linear_acceleration_m_s2"] == {"value": 2.5, "source": source}
    assert controller["min_angular_acceleration_rad_s2"] == {"value": -3.0, "source": source}
    assert controller["max_linear_velocity_m_s"] == {"value": None, "source": "default"}


def test_a_controllers_file_given_wins_over_the_plugin(tmp_path):
    pytest.importorskip("rosbags")
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 50\n"
                           "    base:\n      type: diff_drive_controller/DiffDriveController\n"
                           "base:\n  ros__parameters:\n    publish_rate: 10.0\n")
    summary, messages = _run(SAM_BOT, tmp_path, "--controllers", str(controllers))
    assert len(messages["/base/odom"]) == 100 and "/demo/odom" not in messages
    assert summary["controller"]["publish_rate_hz"] == {"value": 10.0,
                                                        "source": str(controllers)}


def test_the_bundled_robot_keeps_its_controllers_file(run):
    result = run("simulate", "--headless", "--duration-s", "1", "--format", "json")
    assert result.exit_code == 0, result.output
    controller = json.loads(result.stdout)["controller"]
    assert controller["max_linear_acceleration_m_s2"]["value"] == 0.05
    assert controller["max_linear_acceleration_m_s2"]["source"].endswith(
        "robots/controllers.yaml")


def test_a_plugin_number_that_is_not_one_is_one_error_line(tmp_path):
    robot = tmp_path / "sam_bot.urdf"
    robot.write_text(SAM_BOT.read_text().replace(
        "<publish_odom>true</publish_odom>",
        "<publish_odom>true</publish_odom><update_rate>fast</update_rate>"))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1", env=NO_ROS)
    line = assert_one_line_error(result, 2, "<update_rate>", "'fast'")
    assert str(robot) in line


def _sam_bot_with(tmp_path: Path, old: str, new: str) -> Path:
    robot = tmp_path / "sam_bot.urdf"
    text = SAM_BOT.read_text()
    assert old in text
    robot.write_text(text.replace(old, new))
    return robot


def test_sam_bots_plugin_broadcasts_no_odom_tf_and_holds_commands(tmp_path):
    pytest.importorskip("rosbags")
    summary, messages = _run(SAM_BOT, tmp_path)  # <publish_odom_tf>false</publish_odom_tf>
    # no odom -> base and no joint states: on /tf only the wheels <publish_wheel_tf> sends
    assert "/joint_states" not in messages
    assert {t.child_frame_id for m in messages["/tf"] for t in m.transforms} == {
        "drivewhl_l_link", "drivewhl_r_link"}
    assert summary["controller"]["cmd_vel_timeout_s"] == {"value": None, "source": PLUGIN}


def test_with_publish_odom_tf_the_plugin_broadcasts_odom_to_base(tmp_path):
    pytest.importorskip("rosbags")
    robot = _sam_bot_with(tmp_path, "<publish_odom_tf>false", "<publish_odom_tf>true")
    summary, messages = _run(robot, tmp_path)
    parents = {(t.header.frame_id, t.child_frame_id) for m in messages["/tf"]
               for t in m.transforms}
    assert ("odom", "base_link") in parents
    assert summary["odometry_published_on"][-1] == "/tf"


def test_without_publish_odom_no_odometry_is_published_anywhere(tmp_path):
    pytest.importorskip("rosbags")
    robot = _sam_bot_with(tmp_path, "<publish_odom>true</publish_odom>", "")
    summary, messages = _run(robot, tmp_path)
    assert not [t for t in messages if "odom" in t]
    assert summary["odometry_drift"]["final_position_m"] >= 0  # the summary still has it
    assert summary["odometry_published_on"] == []  # and says nothing published it


def test_a_ros1_plugin_on_its_default_topics_is_read_as_ros1(run, tmp_path):
    # TurtleBot3's plugin without <commandTopic> and <odometryTopic>: ROS 1 defaults
    source = TURTLEBOT3.parent / "turtlebot3_burger.gazebo.xacro"
    text = source.read_text()
    for tag in ("<commandTopic>cmd_vel</commandTopic>", "<odometryTopic>odom</odometryTopic>"):
        assert tag in text
        text = text.replace(tag, "")
    package = tmp_path / "turtlebot3_description"
    (package / "urdf").mkdir(parents=True)
    for name in ("package.xml",):
        (package / name).write_text((TURTLEBOT3.parents[1] / name).read_text())
    for path in TURTLEBOT3.parent.iterdir():
        (package / "urdf" / path.name).write_text(path.read_text())
    (package / "urdf" / source.name).write_text(text)
    result = run("inspect", package / "urdf" / TURTLEBOT3.name, "--section", "topics",
                 "--format", "json")
    assert result.exit_code == 0, result.stderr
    names = {t["name"] for t in json.loads(result.stdout)["topics"]["topics"]}
    assert {"/cmd_vel", "/odom", "/tf"} <= names


def test_a_controllers_file_without_a_diff_drive_leaves_the_base_to_the_plugin(tmp_path):
    """turtlebot3_manipulation: Gazebo Classic's diff-drive plugin drives the base, and
    gazebo_ros2_control's file holds only the arm's controllers and a joint_state_broadcaster.
    Gazebo runs both: /odom is the plugin's, /joint_states the broadcaster's."""
    pytest.importorskip("rosbags")
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 20\n"
                           "    joint_state_broadcaster:\n"
                           "      type: joint_state_broadcaster/JointStateBroadcaster\n")
    robot = tmp_path / "sam_bot.urdf"
    robot.write_text(SAM_BOT.read_text().replace("</robot>", f"""
  <ros2_control name="arm" type="system">
    <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin></hardware>
  </ros2_control>
  <gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">
    <parameters>{controllers}</parameters></plugin></gazebo>
</robot>"""))
    summary, messages = _run(robot, tmp_path)
    assert len(messages["/demo/odom"]) == 1000  # the plugin's, at its 100 Hz
    assert len(messages["/joint_states"]) == 200  # the broadcaster's, at the file's 20 Hz
    assert summary["controller"]["publish_rate_hz"] == {"value": 100.0, "source": PLUGIN}


def test_a_sensor_on_a_link_the_robot_lacks_is_left_out_with_a_note(tmp_path):
    """interbotix's locobot names its Create 3 cliff sensors' links without the robot's
    prefix: sdformat drops such a block, so Gazebo makes no sensor. simulate refused the
    robot ("no frame"); it now leaves the sensor out and says so."""
    pytest.importorskip("rosbags")
    robot = tmp_path / "sam_bot.urdf"
    robot.write_text(SAM_BOT.read_text().replace("</robot>", """
  <gazebo reference="cliff_side_left">
    <sensor name="cliff" type="ray"><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>1</samples><min_angle>0</min_angle>
        <max_angle>0</max_angle></horizontal></scan><range><min>0.01</min><max>0.2</max></range>
      </ray>
      <plugin filename="libgazebo_ros_ray_sensor.so" name="cliff">
        <ros><remapping>~/out:=cliff</remapping></ros><output_type>sensor_msgs/Range</output_type>
      </plugin>
    </sensor>
  </gazebo>
</robot>"""))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1",
                            "--format", "json")
    assert result.returncode == 0, result.stderr
    assert ("note: sensor 'cliff' is not simulated: its <gazebo reference=\"cliff_side_left\"> "
            "names no link or joint, so Gazebo drops it") in result.stderr
    _, messages = _run(robot, tmp_path)
    assert "/cliff" not in messages and len(messages["/demo/odom"]) == 1000
    on_a_joint = tmp_path / "ft.urdf"  # a force-torque sensor sits on a joint: no note
    on_a_joint.write_text(SAM_BOT.read_text().replace("</robot>", """
  <gazebo reference="drivewhl_l_joint"><sensor name="ft" type="force_torque">
    <update_rate>10</update_rate></sensor></gazebo>
</robot>"""))
    quiet = run_servicebot("simulate", on_a_joint, "--headless", "--duration-s", "1")
    assert quiet.returncode == 0 and "not simulated" not in quiet.stderr, quiet.stderr


def test_a_ros1_drive_publishing_wheel_joint_states_sends_its_two_wheels_at_its_rate(tmp_path):
    """GazeboRosDiffDrive::publishWheelJointState sends the left and right joints once per
    <updateRate>; the run sent every movable joint (a pan joint too) at the control rate."""
    pytest.importorskip("rosbags")
    wheel = ('<link name="{s}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
             'radius="0.05" length="0.02"/></geometry></collision></link><joint '
             'name="{s}_wheel_joint" type="continuous"><parent link="base_link"/><child '
             'link="{s}_wheel"/><origin xyz="0 {y} 0"/><axis xyz="0 1 0"/></joint>')
    robot = tmp_path / "wheelstates.urdf"
    robot.write_text(
        '<robot name="w"><link name="base_link"/>' + wheel.format(s="left", y=0.15)
        + wheel.format(s="right", y=-0.15) + '<link name="pan"/><joint name="pan_joint" '
        'type="revolute"><parent link="base_link"/><child link="pan"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint><gazebo><plugin '
        'filename="libgazebo_ros_diff_drive.so" name="d"><updateRate>40</updateRate>'
        "<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>"
        "<wheelSeparation>0.3</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
        "<publishWheelJointState>true</publishWheelJointState></plugin></gazebo></robot>")
    _, messages = run_with_bag(robot, tmp_path, duration_s="5")
    states = messages["/joint_states"]
    assert {tuple(m.name) for m in states} == {("left_wheel_joint", "right_wheel_joint")}
    assert len(states) == 200  # 5 s at <updateRate>40
