"""A gz-sim camera's camera_info and frame_id are gz-sensors', not gazebo_ros_camera's.

gz-sensors fills K from gz-rendering's projectionToCameraIntrinsic, principal point (w/2,
h/2), and stamps images and camera_info with <optical_frame_id> when given; the run wrote
gazebo_ros_camera's ((w+1)/2, (h+1)/2) and the link's name. The images stay the same: the
same rays, whichever way the principal point is written.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.simulate.plugin_robots import bag_messages

_BASE = ('<link name="base_link"><collision><geometry><box size="0.4 0.3 0.1"/></geometry>'
         '</collision></link>'
         + "".join(f'<link name="{s}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry>'
                   '<cylinder radius="0.1" length="0.04"/></geometry></collision></link>'
                   f'<joint name="{s}_wheel_joint" type="continuous"><parent link="base_link"/>'
                   f'<child link="{s}_wheel"/><origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>'
                   '</joint>' for s, y in (("left", 0.18), ("right", -0.18)))
         + '<link name="camera_link"/><joint name="c" type="fixed"><parent link="base_link"/>'
         '<child link="camera_link"/><origin xyz="0.2 0 0.1"/></joint>')
_CAMERA = ("<camera><horizontal_fov>1.3962634</horizontal_fov><image><width>64</width>"
           "<height>48</height></image><clip><near>0.1</near><far>15</far></clip>{optical}"
           "</camera><update_rate>10</update_rate>")
_GZ = ('<gazebo reference="camera_link"><sensor name="camera" type="camera">'
       + _CAMERA.format(optical="<optical_frame_id>camera_optical</optical_frame_id>")
       + "<topic>camera/image</topic></sensor></gazebo>")
_CLASSIC = ('<gazebo reference="camera_link"><sensor name="camera" type="camera">'
            + _CAMERA.format(optical="")
            + '<plugin name="cam" filename="libgazebo_ros_camera.so"/></sensor></gazebo>')


def _run(tmp_path, sensor: str, name: str):
    robot = tmp_path / f"{name}.urdf"
    robot.write_text(f'<robot name="r">{_BASE}{sensor}</robot>')
    (tmp_path / name).mkdir()
    return bag_messages(robot, tmp_path / name, "--camera-scale", "1", duration_s="0.3")


def test_gz_camera_info_is_centred_and_in_its_optical_frame(tmp_path):
    pytest.importorskip("rosbags")
    gz = _run(tmp_path, _GZ, "gz")
    info = gz["/camera/camera_info"][-1]
    assert (info.k[2], info.k[5]) == (32.0, 24.0)
    assert info.header.frame_id == "camera_optical"
    assert gz["/camera/image"][-1].header.frame_id == "camera_optical"
    classic = _run(tmp_path, _CLASSIC, "classic")
    (topic,) = [t for t in classic if t.endswith("camera_info")]
    assert (classic[topic][-1].k[2], classic[topic][-1].k[5]) == (32.5, 24.5)
    (image,) = [t for t in classic if t.endswith("image_raw")]
    assert np.array_equal(np.asarray(gz["/camera/image"][-1].data),
                          np.asarray(classic[image][-1].data))
