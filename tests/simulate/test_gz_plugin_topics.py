"""gz-sim's DiffDrive tf on its own topic; model plugins' topics a run does not write, said.

gz-sim's DiffDrive publishes odom -> base on ``<tf_topic>``, by default /model/MODEL/tf
(DiffDrive.cc), as inspect lists it: simulate recorded it on /tf. Its OdometryPublisher
(bcr_bot's default /odom) is not simulated, and the run said nothing: a bag without /odom
read as if the robot published none.
"""

from __future__ import annotations

import pytest

from tests.conftest import run_servicebot

WHEEL = ('<link name="{side}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
         'radius="0.1" length="0.04"/></geometry></collision></link><joint name="{side}_joint" '
         'type="continuous"><parent link="base_link"/><child link="{side}_wheel"/><origin '
         'xyz="0 {y} 0.1"/><axis xyz="0 1 0"/><limit effort="1" velocity="20"/></joint>')
DRIVE = ('<gazebo><plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">'
         '<left_joint>left_joint</left_joint><right_joint>right_joint</right_joint>'
         '<wheel_separation>0.4</wheel_separation><wheel_radius>0.1</wheel_radius>{more}'
         '</plugin></gazebo>')
ODOMETRY_PUBLISHER = ('<gazebo><plugin filename="gz-sim-odometry-publisher-system" '
                      'name="gz::sim::systems::OdometryPublisher"><odom_topic>odom</odom_topic>'
                      '<tf_topic>/tf</tf_topic></plugin></gazebo>')


def _robot(tmp_path, drive: str = "", extra: str = ""):
    path = tmp_path / "gzbot.urdf"
    path.write_text('<robot name="gzbot"><link name="base_link"><collision><geometry><box '
                    'size="0.5 0.3 0.1"/></geometry></collision></link>'
                    + WHEEL.format(side="left", y=0.2) + WHEEL.format(side="right", y=-0.2)
                    + DRIVE.format(more=drive) + extra + "</robot>")
    return path


def _run(path, tmp_path):
    result = run_servicebot("simulate", path, "--headless", "--duration-s", "1", "--bag",
                            tmp_path / "bag")
    assert result.returncode == 0, result.stderr
    return result


@pytest.mark.parametrize(("drive", "topic"), [("", "/model/gzbot/tf"),
                                              ("<tf_topic>/tf</tf_topic>", "/tf")])
def test_the_diff_drives_tf_is_on_its_own_topic(tmp_path, drive, topic):
    pytest.importorskip("rosbags")
    from rosbags.rosbag2 import Reader

    _run(_robot(tmp_path, drive), tmp_path)
    with Reader(tmp_path / "bag") as reader:
        counts = {c.topic: c.msgcount for c in reader.connections}
    assert counts[topic] == 50  # the odometry's 50 Hz, gz-sim's default
    assert "/tf" not in counts or topic == "/tf"


def test_an_odometry_publisher_not_simulated_is_said(tmp_path):
    result = _run(_robot(tmp_path, extra=ODOMETRY_PUBLISHER), tmp_path)
    assert ("note: /odom (nav_msgs/msg/Odometry) of plugin gz-sim-odometry-publisher-system "
            "is not simulated: the run writes no such topic") in result.stderr
