"""The bundled robot: generated files reproduce, pass check_urdf, and say what ROBOT.md decided."""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.description.sensors import camera_spec, imu_spec, lidar_spec
from servicebot_cli.kinematics.drive_geometry import drive_geometry
from tests.conftest import CONTROLLERS_YAML, REAL_URDF, REPO, SIM_URDF, XACRO_SOURCE


@pytest.mark.parametrize(("hardware", "committed"), [("sim", SIM_URDF), ("real", REAL_URDF)])
def test_expand_regenerates_committed_urdf_byte_for_byte(run, tmp_path, hardware, committed):
    out = tmp_path / committed.name
    result = run("expand", XACRO_SOURCE, f"hardware:={hardware}", "-o", out)
    assert result.exit_code == 0, result.stderr
    assert out.read_bytes() == committed.read_bytes(), (
        f"{committed.name} is stale: regenerate it with "
        f"servicebot expand robots/service_robot.urdf.xacro hardware:={hardware} -o {committed}"
    )


@pytest.mark.parametrize(("name", "committed"), [("sim", SIM_URDF), ("real", REAL_URDF)])
def test_expand_without_file_gives_the_bundled_urdf(run, name, committed):
    result = run("expand", "--robot", name)
    assert result.exit_code == 0, result.stderr
    assert result.stdout == committed.read_text(encoding="utf-8")


def _check_urdf() -> str:
    found = shutil.which("check_urdf") or str(Path(sys.executable).parent / "check_urdf")
    assert Path(found).exists(), "check_urdf comes with cmeel-urdfdom (installed by pin)"
    return found


@pytest.mark.parametrize("urdf", [SIM_URDF, REAL_URDF])
def test_committed_urdf_passes_check_urdf(urdf):
    result = subprocess.run([_check_urdf(), str(urdf)], capture_output=True, text=True, timeout=30)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Successfully Parsed XML" in result.stdout
    assert "root Link: base_link has 8 child(ren)" in result.stdout


def test_check_urdf_oracle_rejects_a_broken_file(tmp_path):
    broken = tmp_path / "broken.urdf"
    broken.write_text('<robot name="r"><link name="a"/><joint name="j" type="revolute">'
                      '<parent link="a"/><child link="b"/></joint></robot>')
    result = subprocess.run([_check_urdf(), str(broken)], capture_output=True, text=True)
    assert result.returncode != 0


@pytest.fixture(scope="module", params=["sim", "real"])
def robot(request):
    return load(RobotSource.bundled(request.param))


def test_links_masses_and_inertias_follow_the_geometry(robot):
    masses = {link.name: link.inertial.mass_kg for link in robot.links if link.inertial}
    assert masses["base_link"] == 10.0
    assert masses["lidar_link"] == 0.2 and masses["camera_link"] == 0.1
    assert masses["imu_link"] == 0.05 and masses["arm_base_link"] == 2.0
    assert all(masses[f"arm_link{i}"] == 1.0 for i in range(1, 5))
    assert math.isclose(sum(masses.values()), 20.35)
    for link in robot.links:
        if link.inertial is None:
            assert link.name in ("camera_link_optical", "arm_tool_link")
            continue
        shape = link.collisions[0].geometry
        m = link.inertial.mass_kg
        ixx, _, _, iyy, _, izz = link.inertial.inertia_kg_m2
        if shape.kind == "box":
            x, y, z = shape.size
            expected = tuple(m * (a * a + b * b) / 12 for a, b in ((y, z), (x, z), (x, y)))
        else:  # wheels: cylinders about y
            r, h = shape.radius, shape.length
            across = m * (3 * r * r + h * h) / 12
            expected = (across, m * r * r / 2, across)
        assert (ixx, iyy, izz) == pytest.approx(expected, rel=1e-8), link.name
    assert robot.link("front_left_wheel").inertial.inertia_kg_m2[3] == pytest.approx(0.00245)


def test_joints_frames_and_limits(robot):
    wheel_limit = 0.44 if robot.path == SIM_URDF else 0.5
    names = [j.name for j in robot.movable_joints]
    assert names == [
        "front_left_wheel_joint", "front_right_wheel_joint", "rear_left_wheel_joint",
        "rear_right_wheel_joint", "arm_base_to_link1", "arm_link1_to_link2",
        "arm_link2_to_link3", "arm_link3_to_link4",
    ]
    for joint in robot.movable_joints[:4]:
        assert joint.type == "continuous" and joint.axis == (0.0, 1.0, 0.0)
        assert joint.limits.velocity == wheel_limit
        assert abs(joint.origin.xyz[0]) == 0.17 and abs(joint.origin.xyz[1]) == 0.27
        assert joint.origin.xyz[2] == -0.08
    for joint in robot.movable_joints[4:]:
        assert joint.type == "revolute"
        assert (joint.limits.lower, joint.limits.upper) == (-1.57, 1.57)
        assert (joint.limits.velocity, joint.limits.effort) == (1.0, 20.0)
    assert robot.joint("arm_base_to_link1").axis == (0.0, 0.0, 1.0)
    fixed = {f.name: (f.parent, f.origin.xyz) for f in robot.fixed_frames}
    assert fixed["lidar_link"] == ("base_link", (0.18, 0.0, 0.125))
    assert fixed["camera_link"] == ("base_link", (0.275, 0.0, 0.05))
    assert fixed["imu_link"] == ("base_link", (0.0, 0.0, 0.0))
    assert fixed["arm_base_link"] == ("base_link", (-0.1, 0.0, 0.2))
    assert fixed["arm_tool_link"] == ("arm_link4", (0.3, 0.0, 0.0))
    assert robot.root_link == "base_link"


def test_tool_frame_at_zero_configuration(robot):
    import pinocchio as pin

    model, data = robot.model, robot.data
    pin.framesForwardKinematics(model, data, robot.joint_space.neutral())
    tool = data.oMf[model.getFrameId("arm_tool_link")].translation
    assert tool == pytest.approx([0.8, 0.0, 0.6], abs=1e-12)


def test_drive_geometry_is_what_the_urdf_implies(robot):
    geometry = drive_geometry(robot)
    assert geometry.left == ("front_left_wheel_joint", "rear_left_wheel_joint")
    assert geometry.right == ("front_right_wheel_joint", "rear_right_wheel_joint")
    assert geometry.wheel_radius_m == pytest.approx(0.07)
    assert geometry.track_m == pytest.approx(0.54)


def test_hardware_blocks(robot):
    (control,) = robot.ros2_control
    assert [j.name for j in control.joints] == [j.name for j in robot.movable_joints]
    if robot.path == SIM_URDF:
        assert control.plugin == "gazebo_ros2_control/GazeboSystem"
        assert control.hardware_params == ()
        assert [p.filename for p in robot.plugins] == [
            "libgazebo_ros2_control.so", "libgazebo_ros_ray_sensor.so",
            "libgazebo_ros_camera.so", "libgazebo_ros_imu_sensor.so",
        ]
    else:
        assert control.plugin == "robot_control/SimpleHardwareInterface"
        assert control.hardware_param("port") == "/dev/ttyUSB0"
        assert control.hardware_param("baud_rate") == "9600"
        assert robot.gazebo == ()


def test_sim_sensors_are_the_documented_ones():
    robot = load(RobotSource.bundled("sim"))
    lidar, camera, imu = robot.sensors
    scan = lidar_spec(lidar)
    assert (lidar.reference, scan.samples, scan.update_rate_hz) == ("lidar_link", 360, 10.0)
    assert (scan.min_angle_rad, scan.max_angle_rad) == (0.0, 6.2831853)
    assert (scan.min_range_m, scan.max_range_m, scan.range_resolution_m) == (0.12, 12.0, 0.015)
    assert (scan.noise.mean, scan.noise.stddev) == (0.0, 0.01)
    assert (scan.topic, scan.frame) == ("scan", "lidar_link")
    cam = camera_spec(camera)
    assert (cam.width_px, cam.height_px, cam.update_rate_hz) == (1920, 1080, 30.0)
    assert cam.noise.stddev == 0.007
    assert (cam.image_topic, cam.info_topic) == ("pi_camera/image_raw", "pi_camera/camera_info")
    inertial = imu_spec(imu)
    assert (imu.reference, inertial.update_rate_hz) == ("imu_link", 100.0)
    assert inertial.topic == "imu/data"
    assert [n.stddev for n in inertial.angular_velocity_noise] == [0.00033] * 3
    assert [n.stddev for n in inertial.linear_acceleration_noise] == [0.005] * 3


def test_controllers_yaml_agrees_with_the_urdf():
    config = yaml.safe_load(CONTROLLERS_YAML.read_text())
    manager = config["controller_manager"]["ros__parameters"]
    assert manager["diff_controller"]["type"] == "diff_drive_controller/DiffDriveController"
    assert manager["arm_controller"]["type"] == (
        "joint_trajectory_controller/JointTrajectoryController")
    assert manager["joint_state_broadcaster"]["type"] == (
        "joint_state_broadcaster/JointStateBroadcaster")
    diff = config["diff_controller"]["ros__parameters"]
    geometry = drive_geometry(load(RobotSource.bundled("sim")))
    assert diff["left_wheel_names"] == list(geometry.left)
    assert diff["right_wheel_names"] == list(geometry.right)
    assert diff["wheel_separation"] == pytest.approx(geometry.track_m)
    assert diff["wheel_radius"] == pytest.approx(geometry.wheel_radius_m)
    assert diff["linear.x.max_velocity"] == pytest.approx(geometry.max_linear_m_s, rel=1e-3)
    assert diff["angular.z.max_velocity"] == pytest.approx(geometry.max_angular_rad_s, rel=1e-2)
    arm = config["arm_controller"]["ros__parameters"]
    assert arm["joints"] == [
        "arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"
    ]


def test_unknown_hardware_argument_is_refused(run, monkeypatch):
    monkeypatch.chdir(REPO)
    result = run("expand", "robots/service_robot.urdf.xacro", "hardware:=hil")
    assert result.exit_code == 2
    assert result.stderr == ("Error: robots/service_robot.urdf.xacro:63:3: xacro: hardware:=hil "
                             "is unknown; use hardware:=sim or hardware:=real\n")
