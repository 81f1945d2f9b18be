"""Topics inspect left out: a depth camera's depth outputs and sensor broadcasters' topics.

gazebo_ros_camera on a ``depth`` sensor (ROS 2) also publishes CAMERA/depth/image_raw,
CAMERA/depth/camera_info and CAMERA/points; ROS 1's gazebo_ros_openni_kinect names them in
its depth*TopicName tags (summit_xl's front camera). ros2_controllers' force/torque, IMU and
range broadcasters publish ~/wrench, ~/imu and ~/range; a gripper action controller serves
~/gripper_cmd.
"""

from __future__ import annotations

import json

import pytest

CAMERA = """<robot name="depth_bot"><link name="base_link"/>
  <gazebo reference="base_link"><sensor name="depth_sensor" type="{kind}">
    <update_rate>20</update_rate><camera><horizontal_fov>1.0</horizontal_fov>
    <image><width>64</width><height>48</height></image><clip><near>0.05</near><far>3.5</far>
    </clip></camera>
    <plugin filename="{plugin}" name="depth_cam">{params}</plugin>
  </sensor></gazebo></robot>"""
ROS2 = "<ros><namespace>cam</namespace></ros><camera_name>front</camera_name>"
KINECT = ("<cameraName>front_rgbd_camera</cameraName><imageTopicName>rgb/image_raw"
          "</imageTopicName><cameraInfoTopicName>rgb/camera_info</cameraInfoTopicName>"
          "<depthImageTopicName>depth/image_raw</depthImageTopicName><pointCloudTopicName>"
          "depth/points</pointCloudTopicName><frameName>camera_link</frameName>")


def _published(run, path, *extra: str) -> dict[str, str]:
    result = run("inspect", path, "--section", "topics", "--format", "json", *extra)
    assert result.exit_code == 0, result.output
    return {t["name"]: t["message"] for t in json.loads(result.stdout)["topics"]["topics"]
            if t["direction"] == "out"}


@pytest.mark.parametrize(("kind", "plugin", "params", "expected"), [
    ("depth", "libgazebo_ros_camera.so", ROS2, {
        "cam/front/image_raw": "sensor_msgs/msg/Image",
        "cam/front/camera_info": "sensor_msgs/msg/CameraInfo",
        "cam/front/depth/image_raw": "sensor_msgs/msg/Image",
        "cam/front/depth/camera_info": "sensor_msgs/msg/CameraInfo",
        "cam/front/points": "sensor_msgs/msg/PointCloud2"}),
    ("camera", "libgazebo_ros_camera.so", ROS2, {  # a colour camera: no depth
        "cam/front/image_raw": "sensor_msgs/msg/Image",
        "cam/front/camera_info": "sensor_msgs/msg/CameraInfo"}),
    ("depth", "libgazebo_ros_openni_kinect.so", KINECT, {
        "front_rgbd_camera/rgb/image_raw": "sensor_msgs/msg/Image",
        "front_rgbd_camera/rgb/camera_info": "sensor_msgs/msg/CameraInfo",
        "front_rgbd_camera/depth/image_raw": "sensor_msgs/msg/Image",
        "front_rgbd_camera/depth/camera_info": "sensor_msgs/msg/CameraInfo",  # its default
        "front_rgbd_camera/depth/points": "sensor_msgs/msg/PointCloud2"}),
])
def test_a_depth_camera_lists_its_depth_outputs(run, tmp_path, kind, plugin, params, expected):
    path = tmp_path / "depth.urdf"
    path.write_text(CAMERA.format(kind=kind, plugin=plugin, params=params))
    assert _published(run, path) == expected


def test_sensor_broadcasters_and_a_gripper_controller_list_their_topics(run, tmp_path):
    path = tmp_path / "depth.urdf"
    path.write_text(CAMERA.format(kind="camera", plugin="libgazebo_ros_camera.so", params=ROS2))
    controllers = tmp_path / "controllers.yaml"
    types = {"ft": "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster",
             "imu": "imu_sensor_broadcaster/IMUSensorBroadcaster",
             "range": "range_sensor_broadcaster/RangeSensorBroadcaster",
             "gripper": "position_controllers/GripperActionController"}
    controllers.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
                           + "".join(f"    {name}:\n      type: {kind}\n"
                                     for name, kind in types.items()))
    published = _published(run, path, "--controllers", controllers)
    assert {k: v for k, v in published.items() if not k.startswith("cam/")} == {
        "/ft/wrench": "geometry_msgs/msg/WrenchStamped", "/imu/imu": "sensor_msgs/msg/Imu",
        "/range/range": "sensor_msgs/msg/Range"}
    result = run("inspect", path, "--section", "topics", "--format", "json",
                 "--controllers", controllers)
    served = [t for t in json.loads(result.stdout)["topics"]["topics"] if t["kind"] == "action"]
    assert [(t["name"], t["message"]) for t in served] == [
        ("/gripper/gripper_cmd", "control_msgs/action/GripperCommand")]


def test_a_ros1_topic_is_cleaned_as_roscpp_cleans_it(run, tmp_path):
    """HSR's openni plugin names '//hsrb/head_rgbd_sensor/rgb/image_rect_color': roscpp's
    names::clean makes '//' one '/'; inspect listed it as written."""
    path = tmp_path / "depth.urdf"
    path.write_text(CAMERA.format(kind="depth", plugin="libgazebo_ros_openni_kinect.so",
                                  params=KINECT.replace("<imageTopicName>rgb/image_raw",
                                                        "<imageTopicName>//hsrb/rgb/")))
    assert "/hsrb/rgb" in _published(run, path)
