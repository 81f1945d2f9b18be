"""Mesh wheels that ``<ros2_control>`` commands by velocity make a differential drive.

A CAD export (every link a mesh) driven through gazebo_ros2_control has no diff-drive plugin
to name its wheels: the joints its ros2_control block commands by velocity are the wheels,
each rolling on its round mesh. The bundled real robot with its wheel cylinders replaced by
a cylinder mesh of the same size (written by trimesh) drives and simulates as the original.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh

from tests.conftest import REPO

_CYLINDER = ('<origin rpy="1.5707963267948966 0 0" xyz="0 0 0"/>\n      <geometry>\n'
             '        <cylinder length="0.04" radius="0.07"/>')


def _mesh_wheeled(tmp_path, control: bool = True, unit: float = 1.0):
    """The real robot with every wheel shape a cylinder mesh along y: 0.07 m, in ``unit``s
    per metre (1000: millimetres) and no scale."""
    wheel = trimesh.creation.cylinder(radius=0.07 * unit, height=0.04 * unit, sections=64)
    wheel.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    wheel.export(tmp_path / "wheel.stl")
    text = (REPO / "robots" / "service_robot_real.urdf.xml").read_text()
    assert text.count(_CYLINDER) == 8  # each wheel's visual and collision
    text = text.replace(_CYLINDER, '<origin rpy="0 0 0" xyz="0 0 0"/>\n      <geometry>\n'
                                   '        <mesh filename="wheel.stl"/>')
    if not control:
        start, end = text.index("<ros2_control"), text.index("</ros2_control>")
        text = text[:start] + text[end + len("</ros2_control>"):]
    robot = tmp_path / "mesh_wheels.urdf"
    robot.write_text(text)
    return robot


def test_simulate_drives_the_mesh_wheels_as_the_cylinders(run, tmp_path):
    robot = _mesh_wheeled(tmp_path)
    controllers = REPO / "robots" / "controllers.yaml"
    common = ("--headless", "--duration-s", "4", "--controllers", controllers, "--format", "json")
    meshes = run("simulate", robot, *common)
    cylinders = run("simulate", "--robot", "real", *common)
    assert meshes.exit_code == 0, meshes.stderr
    assert cylinders.exit_code == 0, cylinders.stderr
    got, want = json.loads(meshes.stdout), json.loads(cylinders.stdout)
    assert got["distance_m"] > 0.05
    # the same to the STL's float32 vertices (0.07 is 0.0700000003 there)
    assert abs(got["distance_m"] - want["distance_m"]) < 1e-7
    for key in ("x_m", "y_m", "yaw_rad"):
        assert abs(got["final_pose"][key] - want["final_pose"][key]) < 1e-7


def test_drive_plans_the_same_wheel_speeds(run, tmp_path):
    robot = _mesh_wheeled(tmp_path)
    plan = ("--dry-run", "--linear", "0.02", "--angular", "0.05", "--duration-s", "0.2")
    meshes, cylinders = run("drive", robot, *plan), run("drive", *plan)
    assert meshes.exit_code == 0, meshes.stderr
    assert "SET_WHEELS" in meshes.stdout and meshes.stdout == cylinders.stdout


@pytest.mark.parametrize(("unit", "said", "scale"), [
    (1000.0, "rolls on a radius of 70 m, which no wheel has",
     'scale="0.001 0.001 0.001" for millimetres'),
    (100.0, "rolls on a radius of 7 m, which no wheel has (from 0.0001 to 3 m)",
     '"0.01 0.01 0.01" for centimetres'),
])
def test_a_wheel_mesh_in_millimetres_or_centimetres_is_refused_with_the_scale_to_write(
        run, tmp_path, unit, said, scale):
    robot = _mesh_wheeled(tmp_path, unit=unit)
    result = run("simulate", robot, "--headless", "--duration-s", "1")
    assert result.exit_code == 2
    assert said in result.stderr and scale in result.stderr


def test_mesh_wheels_nothing_names_are_no_drive(run, tmp_path):
    robot = _mesh_wheeled(tmp_path, control=False)
    result = run("simulate", robot, "--headless", "--duration-s", "1")
    assert result.exit_code == 2
    assert "not a differential drive" in result.stderr
    assert "<ros2_control> velocity command names the joint" in result.stderr
