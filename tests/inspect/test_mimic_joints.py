"""``inspect`` and joints that follow another (``<mimic>``).

Interbotix's locobot grippers: ``right_finger`` mimics ``left_finger`` with multiplier -1,
and their limits are mirrored. ``--joint left_finger=...`` was refused because the follower
stayed at 0, outside its limits; it now follows, as in ``fk``. Degrees of freedom count a
follower as none (Panda: 7 arm joints and one finger drive). Centres of mass are checked
against yourdfpy, which sets followers from their leaders itself.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import yourdfpy

from tests.conftest import run_servicebot
from tests.kinematics.robots import PANDA

GRIPPER = """<robot name="gripper">
  <link name="palm"><inertial><mass value="1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="left"><visual><geometry><box size="0.01 0.01 0.04"/></geometry></visual>
    <inertial><origin xyz="0 0 0.02"/><mass value="0.5"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right"><inertial><origin xyz="0 0 0.02"/><mass value="0.25"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="left_finger" type="prismatic"><parent link="palm"/><child link="left"/>
    <axis xyz="0 1 0"/><limit lower="0.015" upper="0.037" effort="5" velocity="1"/></joint>
  <joint name="right_finger" type="prismatic"><parent link="palm"/><child link="right"/>
    <axis xyz="0 1 0"/><limit lower="-0.037" upper="-0.015" effort="5" velocity="1"/>
    <mimic joint="left_finger" multiplier="-1" offset="0"/></joint>
</robot>
"""


def _centre_of_mass(path, joints):
    """By yourdfpy: each link's mass at its pose there."""
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    urdf.update_cfg({n: v for n, v in joints.items() if n in urdf.actuated_joint_names})
    total, moment = 0.0, np.zeros(3)
    for name, link in urdf.link_map.items():
        if link.inertial is None:
            continue
        origin = np.eye(4) if link.inertial.origin is None else link.inertial.origin
        pose = urdf.get_transform(name, urdf.base_link) @ origin
        total += link.inertial.mass
        moment += link.inertial.mass * pose[:3, 3]
    return moment / total


def test_a_named_leader_moves_its_follower(tmp_path):
    robot = tmp_path / "gripper.urdf"
    robot.write_text(GRIPPER)
    result = run_servicebot("inspect", robot, "--section", "totals", "--joint",
                            "left_finger=0.03", "--format", "json")
    assert result.returncode == 0, result.stderr
    totals = json.loads(result.stdout)["totals"]
    assert totals["configuration_rad_or_m"] == {"left_finger": 0.03, "right_finger": -0.03}
    assert totals["centre_of_mass_m"] == pytest.approx(
        _centre_of_mass(robot, {"left_finger": 0.03}), abs=1e-9)
    assert totals["dof"]["total"] == 1
    render = run_servicebot("inspect", robot, "--render", tmp_path / "g.png", "--joint",
                            "left_finger=0.02")
    assert render.returncode == 0 and (tmp_path / "g.png").stat().st_size > 0


def test_a_leader_that_puts_its_follower_outside_its_limits_is_refused(tmp_path):
    robot = tmp_path / "gripper.urdf"
    robot.write_text(GRIPPER.replace('lower="-0.037" upper="-0.015"',
                                     'lower="-0.025" upper="-0.015"'))
    result = run_servicebot("inspect", robot, "--section", "totals", "--joint",
                            "left_finger=0.03")
    assert result.returncode == 2
    assert "right_finger" in result.stderr and "mimics 'left_finger'" in result.stderr


def test_panda_has_eight_degrees_of_freedom():
    result = run_servicebot("inspect", PANDA, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["dof"] == {"total": 8, "wheels": 0, "arm": 8,
                                                          "chassis": 0}


def test_two_joints_that_follow_each_other_keep_one_degree_of_freedom(tmp_path):
    """A loop of <mimic> (check's SB211): one of them still moves the pair."""
    robot = tmp_path / "loop.urdf"
    robot.write_text(GRIPPER.replace('<axis xyz="0 1 0"/><limit lower="0.015"',
                                     '<axis xyz="0 1 0"/><mimic joint="right_finger"/>'
                                     '<limit lower="0.015"'))
    result = run_servicebot("inspect", robot, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["dof"]["total"] == 1
