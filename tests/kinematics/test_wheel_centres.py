"""A wheel's centre is its cylinder's, which may sit along the axle from the wheel's joint.

AgileX limo's wheels are offset outward by half their width from their joints: the track
between the wheels' mid-planes is 0.175 m, between the joints 0.13 m. inspect showed 0.13 m
and check controllers refused the package's own 0.172 m as SB604.
"""

from __future__ import annotations

import json

import pytest
import yourdfpy

from tests.conftest import run_servicebot

WHEEL = """  <link name="{side}_wheel_link">
    <inertial><mass value="0.5"/>
      <inertia ixx="0.0003" iyy="0.0005" izz="0.0003" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0.0225 0" rpy="1.5708 0 0"/>
      <geometry><cylinder length="0.045" radius="0.045"/></geometry></collision>
  </link>
  <joint name="{side}_wheel" type="continuous">
    <parent link="base_link"/><child link="{side}_wheel_link"/>
    <origin xyz="0 {y} -0.1" rpy="{roll} 0 0"/><axis xyz="0 1 0"/>
    <limit effort="5" velocity="20"/>
  </joint>
"""
ROBOT = ("""<?xml version="1.0"?>
<robot name="offset_wheels">
  <link name="base_link">
    <inertial><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
    </inertial>
    <collision><geometry><box size="0.3 0.1 0.1"/></geometry></collision>
  </link>
""" + WHEEL.format(side="left", y="0.065", roll="0")
         + WHEEL.format(side="right", y="-0.065", roll="3.14159265") + "</robot>\n")
CONTROLLERS = """controller_manager:
  ros__parameters:
    diff_drive_controller:
      type: diff_drive_controller/DiffDriveController
diff_drive_controller:
  ros__parameters:
    left_wheel_names: ["left_wheel"]
    right_wheel_names: ["right_wheel"]
    wheel_separation: {separation}
    wheel_radius: 0.045
"""


def _cylinder_centres_y(path) -> list[float]:
    """Each wheel cylinder's centre, y in the base frame, as yourdfpy places it."""
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    centres = []
    for side in ("left", "right"):
        link = urdf.link_map[f"{side}_wheel_link"]
        placed = urdf.get_transform(link.name, "base_link") @ link.collisions[0].origin
        centres.append(float(placed[1, 3]))
    return centres


@pytest.fixture()
def robot(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT)
    return path


def test_the_track_is_between_the_cylinders(robot):
    left, right = _cylinder_centres_y(robot)
    assert (left, right) == pytest.approx((0.0875, -0.0875), abs=1e-6)
    result = run_servicebot("inspect", robot, "--section", "totals", "--format", "json")
    drive = json.loads(result.stdout)["totals"]["drive"]
    assert drive["track_m"] == pytest.approx(left - right, abs=1e-6)


@pytest.mark.parametrize(("separation", "said"), [
    ("0.175", None),
    ("0.172", "warning"),  # the package's own value: odometry calibrated to the floor
    ("0.19", "warning"),
    ("0.13", "error"),  # the joints' track: the wrong wheels' centres
    ("175", "error"),  # millimetres
])
def test_controllers_are_held_to_the_wheels_mid_planes(robot, tmp_path, separation, said):
    yaml = tmp_path / "controllers.yaml"
    yaml.write_text(CONTROLLERS.format(separation=separation))
    result = run_servicebot("check", "controllers", yaml, "--urdf", robot, "--isolated")
    assert result.returncode == (1 if said == "error" else 0), result.stdout
    if said is None:
        assert "SB604" not in result.stdout
        return
    assert f"{said} SB604 [wheel-separation] diff_drive_controller: wheel_separation " \
        f"{float(separation):g} m disagrees with the URDF's 0.175 m" in result.stdout
    assert ("a calibration to the floor, if on purpose" in result.stdout) is (said == "warning")
