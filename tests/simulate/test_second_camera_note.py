"""simulate runs one camera and one IMU: any other says so instead of vanishing.

summit_xl has a PTZ camera and an RGB-D camera; the run published the first one's
camera_info and nothing of the second, without a word.
"""

from __future__ import annotations

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, edited

SECOND_CAMERA = (
    '<gazebo reference="base_link"><sensor name="rear_camera" type="camera"><update_rate>5'
    '</update_rate><camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width>'
    '<height>48</height></image></camera><plugin filename="libgazebo_ros_camera.so" '
    'name="rear"><camera_name>rear</camera_name></plugin></sensor></gazebo></robot>')


def _notes(robot) -> list[str]:
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "0.2", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return [line for line in result.stderr.splitlines() if "is not simulated" in line]


def test_a_second_camera_is_named_as_not_simulated(tmp_path):
    assert _notes(SAM_BOT) == []  # one camera, one IMU
    robot = edited(SAM_BOT, tmp_path, ("</robot>", SECOND_CAMERA))
    assert _notes(robot) == ["note: camera 'rear_camera' is not simulated: simulate runs one "
                             "camera, the first ('depth_camera')"]
