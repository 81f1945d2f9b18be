"""An IMU or a camera is published only by what publishes it: the topics ``inspect`` lists.

Gazebo Classic publishes a sensor on ROS only through a ROS plugin: the sensor's own
(``gazebo_ros_imu_sensor``, ``gazebo_ros_camera``) or, for an IMU, a ROS 1 ``gazebo_ros_imu``
model plugin on its link (TurtleBot3's); gz-sim's sensors publish on their ``<topic>``
(``test_gz_sensor_topics``). Nav2's sam_bot edited one tag at a time, and TurtleBot3, read
back from the bag by rosbags and from ``inspect --format json``.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import (
    SAM_BOT,
    TURTLEBOT3,
    TURTLEBOT3_GAZEBO,
    bag_messages,
    edited,
)

IMU, CAMERA_INFO = "sensor_msgs/msg/Imu", "sensor_msgs/msg/CameraInfo"
NO_IMU_PLUGIN = (('<plugin filename="libgazebo_ros_imu_sensor.so" name="imu_plugin">',
                  '<!-- <plugin filename="libgazebo_ros_imu_sensor.so" name="imu_plugin">'),
                 ("<initial_orientation_as_reference>false</initial_orientation_as_reference>\n"
                  "      </plugin>",
                  "<initial_orientation_as_reference>false</initial_orientation_as_reference>\n"
                  "      </plugin> -->"))
NO_CAMERA_PLUGIN = (('<plugin name="depth_camera_controller" filename="libgazebo_ros_camera.so">',
                     '<!-- <plugin name="depth_camera_controller">'),
                    ("<hackBaseline>0</hackBaseline>\n      </plugin>",
                     "<hackBaseline>0</hackBaseline>\n      </plugin> -->"))


def _listed(robot: Path, message: str) -> set[str]:
    """``inspect --section topics``: the topics of type ``message`` it publishes, absolute."""
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return {"/" + t["name"].lstrip("/") for t in json.loads(result.stdout)["topics"]["topics"]
            if t["message"] == message and t["direction"] == "out"}


def _bagged(messages: dict[str, list], kind: str) -> set[str]:
    return {topic for topic, m in messages.items() if type(m[0]).__name__.endswith(kind)}


def test_an_imu_without_a_ros_plugin_publishes_nothing(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, *NO_IMU_PLUGIN)
    assert _listed(robot, IMU) == set()
    messages = bag_messages(robot, tmp_path, "--out", tmp_path / "out")
    assert _bagged(messages, "__Imu") == set()
    assert "imu.csv" not in {p.name for p in (tmp_path / "out").iterdir()}


def test_a_camera_without_a_ros_plugin_publishes_nothing(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, *NO_CAMERA_PLUGIN)
    assert _listed(robot, CAMERA_INFO) == set()
    assert _bagged(bag_messages(robot, tmp_path), "CameraInfo") == set()


def test_sam_bots_imu_and_camera_with_their_plugins_are_where_inspect_lists_them(tmp_path):
    pytest.importorskip("rosbags")
    messages = bag_messages(SAM_BOT, tmp_path)
    assert _bagged(messages, "__Imu") == _listed(SAM_BOT, IMU) == {"/demo/imu"}
    assert _bagged(messages, "CameraInfo") == _listed(SAM_BOT, CAMERA_INFO)


def test_turtlebot3s_imu_is_its_ros1_model_plugins_topic_and_frame(tmp_path):
    pytest.importorskip("rosbags")
    messages = bag_messages(TURTLEBOT3, tmp_path)
    assert _bagged(messages, "__Imu") == _listed(TURTLEBOT3, IMU) == {"/imu"}
    assert messages["/imu"][-1].header.frame_id == "imu_link"  # <frameName>


TB3_IMU_SENSOR = ('<sensor type="imu" name="imu">\n      <always_on>true</always_on>\n'
                  '      <visualize>$(arg imu_visual)</visualize>\n    </sensor>', "")


def test_turtlebot3s_imu_plugin_publishes_with_no_imu_sensor(tmp_path):
    """noetic gazebo_ros_imu.cpp measures its <bodyName> link itself: no sensor needed."""
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, TB3_IMU_SENSOR, file=TURTLEBOT3_GAZEBO)
    messages = bag_messages(robot, tmp_path)
    assert _bagged(messages, "__Imu") == _listed(robot, IMU) == {"/imu"}
    assert messages["/imu"][-1].header.frame_id == "imu_link"


def test_the_imu_plugins_rate_noise_and_frame_are_its_own(tmp_path):
    """<updateRate>, <frameName>, <gaussianNoise> (its square on all three covariances)."""
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, TB3_IMU_SENSOR,
                   ("<frameName>imu_link</frameName>", "<frameName>imu_frame</frameName>"),
                   ("<gaussianNoise>0.0</gaussianNoise>", "<gaussianNoise>0.1</gaussianNoise>"),
                   ("<updateRate>0</updateRate>", "<updateRate>20</updateRate>"),
                   file=TURTLEBOT3_GAZEBO)
    imu = bag_messages(robot, tmp_path)["/imu"]
    assert len(imu) == pytest.approx(2 * 20, abs=1)  # 2 s at 20 Hz
    assert imu[-1].header.frame_id == "imu_frame"
    for covariance in (imu[-1].orientation_covariance, imu[-1].angular_velocity_covariance,
                       imu[-1].linear_acceleration_covariance):
        assert list(covariance) == pytest.approx([0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01])
    rates = [m.angular_velocity.x for m in imu]
    assert max(rates) - min(rates) > 0.05  # noisy, standing still


def test_an_imu_plugin_with_an_empty_topic_publishes_nothing(tmp_path):
    """``<topicName></topicName>``: the plugin advertises nothing (noetic gazebo_ros_imu)."""
    pytest.importorskip("rosbags")
    robot = edited(TURTLEBOT3, tmp_path, ("<topicName>imu</topicName>",
                                          "<topicName></topicName>"), file=TURTLEBOT3_GAZEBO)
    assert _listed(robot, IMU) == set()
    assert _bagged(bag_messages(robot, tmp_path), "__Imu") == set()
