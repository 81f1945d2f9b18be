"""SB519, and what simulate and inspect read: ROS 1 names in a ROS 2 file's plugins.

tortoisebot's ROS 2 description drives with a <ros> block and writes its camera's
<cameraName> and <frameName> as ROS 1 did: ROS 2's gazebo_ros_camera reads neither, names
its topics after the sensor and stamps the link Gazebo carries the camera on. inspect and
simulate said the ROS 1 names, and check said nothing.
"""

from __future__ import annotations

import json

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

_DRIVE = ('<gazebo><plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">{ros}'
          "<left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>"
          "<wheel_separation>0.2</wheel_separation><wheel_diameter>0.065</wheel_diameter>"
          "</plugin></gazebo>")
_WHEEL = ('<link name="{side}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
          'radius="0.0325" length="0.02"/></geometry></collision></link><joint '
          'name="{side}_wheel_joint" type="continuous"><parent link="base_link"/><child '
          'link="{side}_wheel"/><origin xyz="0 {y} 0.0325"/><axis xyz="0 1 0"/><limit effort="1" '
          'velocity="10"/></joint>')
_CAMERA = ('<link name="camera_link"/><joint name="camera_joint" type="fixed"><parent '
           'link="base_link"/><child link="camera_link"/><origin xyz="0.1 0 0.1"/></joint>'
           '<gazebo reference="camera_link"><sensor type="camera" name="camera1"><update_rate>30'
           "</update_rate><camera><image><width>80</width><height>60</height></image></camera>"
           '<plugin name="cam" filename="{plugin}"><cameraName>front</cameraName>'
           "<frameName>camera_link</frameName></plugin></sensor></gazebo>")


def _robot(tmp_path, ros: str, plugin: str = "libgazebo_ros_camera.so"):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"><collision><geometry><box size="0.2 '
                    '0.15 0.05"/></geometry></collision></link>'
                    + _WHEEL.format(side="left", y=0.1) + _WHEEL.format(side="right", y=-0.1)
                    + _DRIVE.format(ros=ros) + _CAMERA.format(plugin=plugin) + "</robot>")
    return path


def _sb519(path):
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json",
                            "--select", "SB519")
    return [(f["severity"], f["message"], f["fix"]) for f in findings(result.stdout)]


def _camera(path) -> dict:
    result = run_servicebot("inspect", path, "--section", "sensors", "--format", "json")
    assert result.returncode == 0, result.stderr
    (camera,) = [s for s in json.loads(result.stdout)["sensors"] if s["type"] == "camera"]
    return camera


def test_ros1_names_in_a_ros2_file_are_sb519_and_read_as_ros2_reads_them(tmp_path):
    path = _robot(tmp_path, "<ros><namespace>/</namespace></ros>")
    ((severity, message, fix),) = _sb519(path)
    assert severity == "warning"
    assert "<cameraName>, <frameName> are ROS 1 parameters, and the file's plugins are " \
        "ROS 2's (a <ros> block)" in message
    assert fix == "write <camera_name> for <cameraName>; <frame_name> for <frameName>"
    camera = _camera(path)
    assert camera["frame"] == "base_link"  # the link Gazebo carries it on, lumped
    assert "camera1/image_raw" in [topic["name"] for topic in camera["topics"]]


def test_ros1_names_in_a_ros1_file_are_read(tmp_path):
    path = _robot(tmp_path, "")
    assert _sb519(path) == []
    camera = _camera(path)
    assert camera["frame"] == "camera_link"
    assert "front/image_raw" in [topic["name"] for topic in camera["topics"]]


def test_another_packages_plugin_keeps_its_own_names(tmp_path):
    """velodyne_simulator's ROS 2 plugin reads <frameName>; only gazebo_plugins' do not."""
    path = _robot(tmp_path, "<ros><namespace>/</namespace></ros>",
                  plugin="libgazebo_ros_velodyne_laser.so")
    assert _sb519(path) == []


@pytest.mark.parametrize("ros", ["<ros><namespace>/</namespace></ros>", ""])
def test_simulate_stamps_what_inspect_says(tmp_path, ros):
    pytest.importorskip("rosbags")
    from tests.simulate.plugin_robots import bag_messages

    path = _robot(tmp_path, ros)
    messages = bag_messages(path, tmp_path)
    (info,) = [topic for topic in messages if topic.endswith("/camera_info")]
    assert messages[info][0].header.frame_id == ("base_link" if ros else "camera_link")


@pytest.mark.parametrize(("ros", "written", "expected_hz"), [
    ("", "<updateRate>10</updateRate>", 10),  # ROS 1 throttles the sensor's 30 Hz
    ("", "<updateRate>0</updateRate>", 30),  # 0: no throttle
    ("<ros><namespace>/</namespace></ros>", "<updateRate>10</updateRate>", 30)])  # ROS 2: none
def test_a_ros1_cameras_update_rate_throttles_it(tmp_path, ros, written, expected_hz):
    """gazebo_ros_camera_utils (ROS 1) publishes once 1/updateRate has passed: a camera of
    30 Hz under <updateRate>10 published 30 frames a second in simulate."""
    path = _robot(tmp_path, ros)
    path.write_text(path.read_text().replace("<cameraName>", f"{written}<cameraName>"))
    assert _camera(path)["update_rate_hz"] == expected_hz
    pytest.importorskip("rosbags")
    from tests.simulate.plugin_robots import bag_messages

    messages = bag_messages(path, tmp_path)
    (info,) = [topic for topic in messages if topic.endswith("/camera_info")]
    assert len(messages[info]) == pytest.approx(2 * expected_hz, abs=1)  # 2 s


def test_inspect_lists_the_topics_a_ros2_drive_uses(tmp_path):
    """inspect rebuilt the plugins it lists without the file's ROS 2 mark: it said the
    drive listened on <commandTopic> and published <odometryTopic>, which ROS 2's plugin
    does not read (check: SB519; simulate published no odometry)."""
    path = _robot(tmp_path, "")
    path.write_text(path.read_text().replace(
        "<left_joint>", "<commandTopic>cmd1</commandTopic><odometryTopic>odom1</odometryTopic>"
        "<left_joint>").replace("<plugin name=\"cam\" filename=\"libgazebo_ros_camera.so\">",
                                "<plugin name=\"cam\" filename=\"libgazebo_ros_camera.so\">"
                                "<ros><namespace>x</namespace></ros>"))
    result = run_servicebot("inspect", path, "--section", "topics", "--format", "json")
    assert result.returncode == 0, result.stderr
    names = {topic["name"] for topic in json.loads(result.stdout)["topics"]["topics"]}
    assert "/cmd_vel" in names and not names & {"/cmd1", "/odom1", "cmd1", "odom1"}


def test_a_plugin_only_ros2_has_makes_the_file_ros2s(tmp_path):
    """RoverSimulation's drive: gazebo_ros2_control and gazebo_ros_ray_sensor (both ROS 2's
    only), no <ros> block, and a laser with ROS 1's <topicName>/<frameName>: inspect said
    /scan and lidar_link, which ROS 2's plugin does not read, and check said nothing."""
    laser = ('<link name="lidar_link"/><joint name="lidar_joint" type="fixed"><parent '
             'link="base_link"/><child link="lidar_link"/><origin xyz="0 0 0.2"/></joint>'
             '<gazebo reference="lidar_link"><sensor type="ray" name="laser"><update_rate>10'
             '</update_rate><ray><scan><horizontal><samples>90</samples><min_angle>-1'
             '</min_angle><max_angle>1</max_angle></horizontal></scan><range><min>0.1</min>'
             '<max>10</max></range></ray><plugin name="laser_plugin" '
             'filename="libgazebo_ros_ray_sensor.so"><topicName>/scan</topicName><frameName>'
             'lidar_link</frameName><output_type>sensor_msgs/LaserScan</output_type></plugin>'
             '</sensor></gazebo><gazebo><plugin filename="libgazebo_ros2_control.so" '
             'name="gazebo_ros2_control"><parameters>c.yaml</parameters></plugin></gazebo>')
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"><collision><geometry><box '
                    f'size="0.2 0.15 0.05"/></geometry></collision></link>{laser}</robot>')
    ((severity, message, _),) = _sb519(path)
    assert severity == "warning" and "<topicName>, <frameName> are ROS 1 parameters" in message
    assert "('libgazebo_ros2_control.so' exists for ROS 2 only)" in message
    result = run_servicebot("inspect", path, "--section", "sensors", "--format", "json")
    (laser_spec,) = json.loads(result.stdout)["sensors"]
    assert laser_spec["frame"] == "base_link"  # Gazebo lumps lidar_link into it
    assert [t["name"] for t in laser_spec["topics"]] == ["laser_plugin/out"]
