"""ROS 1 sensor plugins' <gaussianNoise>: read, shown and simulated.

gazebo_ros_range (Magni's sonars) and gazebo_ros_imu_sensor add N(0, gaussianNoise) to every
reading, on top of the sensor's own noise. inspect said 'noise none' and simulate published
exact readings.
"""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS

INERTIAL = ('<inertial><mass value="{m}"/><inertia ixx="0.0001" iyy="0.0001" izz="0.0002" '
            'ixz="0" ixy="0" iyz="0"/></inertial>')


def _wheel(side: str, y_m: float) -> str:
    return (f'<joint name="{side}_wheel_joint" type="continuous"><parent link="base_link"/>'
            f'<child link="{side}_wheel"/><origin xyz="0 {y_m} 0" rpy="-1.5708 0 0"/>'
            '<axis xyz="0 0 1"/><limit effort="10" velocity="10"/></joint>'
            f'<link name="{side}_wheel"><collision><geometry><cylinder radius="0.05" '
            f'length="0.02"/></geometry></collision>{INERTIAL.format(m=0.2)}</link>')


def _robot(imu_noise: str) -> str:
    return (f'<robot name="sonar_bot"><link name="base_link">{INERTIAL.format(m=1)}</link>'
            '<joint name="sonar_joint" type="fixed"><parent link="base_link"/>'
            '<child link="sonar_0"/><origin xyz="0.1 0 0.1"/></joint><link name="sonar_0"/>'
            '<gazebo reference="sonar_0"><sensor name="sonar" type="ray"><update_rate>5'
            '</update_rate><ray><scan><horizontal><samples>5</samples><min_angle>-0.24'
            '</min_angle><max_angle>0.24</max_angle></horizontal></scan><range><min>0.02</min>'
            '<max>4.0</max></range></ray><plugin filename="libgazebo_ros_range.so" name="r">'
            '<gaussianNoise>0.015</gaussianNoise><topicName>sonar_0</topicName>'
            '<frameName>sonar_0</frameName><radiation>ultrasound</radiation><fov>0.5</fov>'
            '</plugin></sensor></gazebo>'
            '<gazebo reference="base_link"><sensor name="imu" type="imu"><update_rate>100'
            f'</update_rate>{imu_noise}<plugin filename="libgazebo_ros_imu_sensor.so" '
            'name="imu_plugin"><topicName>imu</topicName><bodyName>base_link</bodyName>'
            '<gaussianNoise>0.01</gaussianNoise><frameName>base_link</frameName></plugin>'
            f'</sensor></gazebo>{_wheel("left", 0.15)}{_wheel("right", -0.15)}</robot>')


OWN_NOISE = ("<imu><angular_velocity>" + "".join(
    f"<{a}><noise type=\"gaussian\"><mean>0</mean><stddev>0.02</stddev></noise></{a}>"
    for a in "xyz") + "</angular_velocity></imu>")


@pytest.mark.parametrize(("own", "gyro_stddev"), [
    ("", 0.01), (OWN_NOISE, float(np.hypot(0.02, 0.01)))])
def test_a_ros1_plugins_gaussian_noise_is_the_sensors(tmp_path, own, gyro_stddev):
    path = tmp_path / "robot.urdf"
    path.write_text(_robot(own))
    result = run_servicebot("inspect", path, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    sensors = {s["name"]: s for s in json.loads(result.stdout)["sensors"]}
    assert sensors["sonar"]["lidar"]["noise"]["stddev"] == 0.015
    gyro = sensors["imu"]["imu"]["angular_velocity_noise"]
    assert [n["stddev"] for n in gyro] == pytest.approx([gyro_stddev] * 3)
    assert [n["stddev"] for n in sensors["imu"]["imu"]["linear_acceleration_noise"]] == \
        pytest.approx([0.01] * 3)
    out = tmp_path / "out"
    run = run_servicebot("simulate", path, "--headless", "--duration-s", "4", "--out", out,
                         env=NO_ROS)
    assert run.returncode == 0, run.stderr
    with (out / "imu.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    # 400 samples; on a flat floor the base never rolls: the roll rate is the noise alone
    spread = float(np.std([float(r["wx_rad_s"]) for r in rows]))
    assert spread == pytest.approx(gyro_stddev, rel=0.15)


def test_a_plugin_that_reads_no_gaussian_noise_adds_none(tmp_path):
    """ROS 1 gazebo_ros_laser reads no <gaussianNoise>; one copied into it changes nothing."""
    path = tmp_path / "robot.urdf"
    path.write_text(_robot("").replace("libgazebo_ros_range.so", "libgazebo_ros_laser.so"))
    result = run_servicebot("inspect", path, "--section", "sensors", "--format", "json",
                            env=NO_ROS)
    sensors = {s["name"]: s for s in json.loads(result.stdout)["sensors"]}
    assert sensors["sonar"]["lidar"]["noise"] is None
