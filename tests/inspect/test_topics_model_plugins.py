"""Topics of model-level Gazebo plugins, read from real descriptions with no ROS set.

sam_bot (Nav2's tutorial, ``tests/fixtures/sam_bot_description``) is driven by Gazebo
Classic's ``libgazebo_ros_diff_drive.so`` in the ``/demo`` namespace; Leo Rover
(``tests/fixtures/leo_description``) by gz-sim's DiffDrive and JointStatePublisher systems.
Neither has ros2_control, so without the plugins the robot would seem to take no command.
The expected names are those the plugins' sources document (gazebo_ros_pkgs' ROS 2
``gazebo_ros_diff_drive.cpp``, gz-sim's ``DiffDrive.cc`` and ``JointStatePublisher.cc``).
"""

from __future__ import annotations

import json

import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.inspect.plugins import plugins_info
from servicebot_cli.inspect.sensors import sensors_info
from servicebot_cli.inspect.topics import topics_info
from tests.conftest import REPO

FIXTURES = REPO / "tests" / "fixtures"
SAM_BOT = FIXTURES / "sam_bot_description" / "src" / "description" / "sam_bot_description.urdf"
LEO = FIXTURES / "leo_description" / "urdf" / "leo_sim.urdf.xacro"


def _plugin_topics(path):
    robot = load(RobotSource.of(path))
    plugins = plugins_info(robot.gazebo, robot.sensors, robot.ros2_control)
    rows = topics_info(sensors_info(robot.sensors), plugins.ros2_control, None, plugins.gazebo)
    return [(t.direction, t.name, t.message, t.provider) for t in rows
            if t.source.startswith("Gazebo plugin")], rows


def test_sam_bot_diff_drive_plugin_topics_are_in_its_namespace(monkeypatch):
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    rows, _ = _plugin_topics(SAM_BOT)
    assert rows == [
        ("in", "/demo/cmd_vel", "geometry_msgs/msg/Twist", "diff_drive"),
        ("out", "/demo/odom", "nav_msgs/msg/Odometry", "diff_drive"),  # <publish_odom>true
        ("out", "/tf", "tf2_msgs/msg/TFMessage", "diff_drive"),  # <publish_wheel_tf>true
    ]


def test_leo_gz_systems_topics_are_their_gz_topics(monkeypatch):
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    rows, everything = _plugin_topics(LEO)
    drive, joints = "ignition::gazebo::systems::DiffDrive", \
        "ignition::gazebo::systems::JointStatePublisher"
    assert ("in", "/cmd_vel", "geometry_msgs/msg/Twist", drive) in rows
    assert ("out", "/odom", "nav_msgs/msg/Odometry", drive) in rows
    assert ("out", "/tf", "tf2_msgs/msg/TFMessage", drive) in rows
    assert ("out", "/joint_states", "sensor_msgs/msg/JointState", joints) in rows
    assert everything[0].direction == "in"  # inputs first
    assert all("ros_gz_bridge" in (t.note or "") for t in everything
               if t.source.startswith("Gazebo plugin"))


def test_the_topics_section_lists_the_plugins_topics(run, monkeypatch):
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    result = run("inspect", SAM_BOT, "--section", "topics", "--format", "json")
    assert result.exit_code == 0, result.output
    topics = json.loads(result.stdout)["topics"]["topics"]
    assert {"direction": "in", "name": "/demo/cmd_vel"}.items() <= next(
        t for t in topics if t["name"] == "/demo/cmd_vel").items()
    assert any(t["name"] == "/demo/odom" and t["direction"] == "out" for t in topics)


CREATE3 = REPO / "tests" / "realworld" / "ws" / "src" / "irobot_create_description" / "urdf" \
    / "create3.urdf.xacro"


def test_create3_ground_truth_pose_from_its_p3d_plugin(monkeypatch):
    """create3's ``gazebo_ros_p3d`` remaps ``odom`` to ``sim_ground_truth_pose``."""
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    rows, everything = _plugin_topics(CREATE3)
    assert ("out", "/sim_ground_truth_pose", "nav_msgs/msg/Odometry",
            "gazebo_ros_p3d_robot") in rows
    (truth,) = [t for t in everything if t.name == "/sim_ground_truth_pose"]
    assert truth.note == "ground truth of base_link"


@pytest.mark.parametrize(("params", "topic"), [
    ("<ros><namespace>r1</namespace></ros><body_name>a</body_name>", "/r1/odom"),
    ("<body_name>a</body_name>", "/odom"),
    ("<frame_name>world</frame_name>", None),  # no <body_name>: it loads nothing
    ("<bodyName>a</bodyName><topicName>truth</topicName>", "/truth"),  # ROS 1
    ("<bodyName>a</bodyName>", None),  # ROS 1 without <topicName>: it does not run
])
def test_p3d_topic_as_gazebo_ros_p3d_reads_its_tags(tmp_path, monkeypatch, params, topic):
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><gazebo><plugin name="truth" '
                    f'filename="libgazebo_ros_p3d.so">{params}</plugin></gazebo></robot>')
    rows, _ = _plugin_topics(path)
    assert rows == ([("out", topic, "nav_msgs/msg/Odometry", "truth")] if topic else [])
