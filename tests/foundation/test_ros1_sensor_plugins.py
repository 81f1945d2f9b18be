"""Sensor topics and frames of Gazebo plugins written the ROS 1 way (gazebo_ros_pkgs before
ROS 2), as TurtleBot3's URDF and many others still write them: <topicName>, <frameName>,
<robotNamespace>, a camera's <cameraName>/<imageTopicName>."""

from __future__ import annotations

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.description.sensors import camera_spec, imu_spec, lidar_spec
from tests.conftest import REPO

TURTLEBOT3 = REPO / "tests" / "realworld" / "ws" / "src" / "turtlebot3_description" / "urdf" \
    / "turtlebot3_burger.urdf.xacro"

CAMERA = """<robot name="r"><link name="base"/><link name="cam"/>
  <joint name="j" type="fixed"><parent link="base"/><child link="cam"/></joint>
  <gazebo reference="cam"><sensor name="c" type="camera"><update_rate>10</update_rate>
    <camera><horizontal_fov>1</horizontal_fov><image><width>64</width><height>48</height>
    </image></camera>
    <plugin name="cam_ctrl" filename="libgazebo_ros_camera.so">
      <robotNamespace>/bot</robotNamespace><cameraName>front</cameraName>
      <imageTopicName>image_raw</imageTopicName>
      <cameraInfoTopicName>camera_info</cameraInfoTopicName><frameName>cam_optical</frameName>
    </plugin></sensor></gazebo></robot>"""


def test_turtlebot3s_lidar_and_imu_topics_and_frames():
    robot = load(RobotSource.of(TURTLEBOT3))
    by_type = {s.type: s for s in robot.sensors}
    scan = lidar_spec(by_type["ray"])
    assert (scan.topic, scan.frame) == ("scan", "base_scan")


def test_a_ros1_camera_plugin_names_its_topics_under_its_camera_and_namespace(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(CAMERA)
    [sensor] = load(RobotSource.of(path)).sensors
    camera = camera_spec(sensor)
    assert (camera.image_topic, camera.info_topic, camera.frame) == \
        ("bot/front/image_raw", "bot/front/camera_info", "cam_optical")


def test_a_ros2_plugin_keeps_its_remapping():
    """The bundled robot's ROS 2 plugins: <ros><remapping>~/out:=data</remapping>..."""
    robot = load(RobotSource.of(REPO / "robots" / "service_robot.urdf.xml"))
    imu = next(imu_spec(s) for s in robot.sensors if s.type == "imu")
    assert imu.topic == "imu/data"
