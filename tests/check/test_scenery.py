"""A ground plane or a scene (one massless link) may be of any size: no SB404."""

from __future__ import annotations

import shutil

import pytest

from tests.check.corpus import pybullet_urdfs
from tests.check.helpers import codes

SCENES = ["plane.urdf", "plane100.urdf", "samurai.urdf"]  # 200 m and 124.5 m across


@pytest.mark.parametrize("name", SCENES)
def test_pybullet_ground_planes_and_scenes_are_not_in_millimetres(run, name):
    (path,) = [p for p in pybullet_urdfs() if p.name == name]
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert "SB404" not in codes(result.stdout), result.stdout


@pytest.mark.parametrize(("mass", "second_link", "expected"), [
    ("0", False, False),
    ("", False, False),  # no <inertial> at all
    ("2", False, True),  # a 200 m body of 2 kg: a mesh in millimetres
    ("0", True, True),  # a robot's part
])
def test_a_huge_mesh_is_a_size_warning_unless_it_is_a_massless_single_link(run, tmp_path, mass,
                                                                           second_link,
                                                                           expected):
    (plane,) = [p for p in pybullet_urdfs() if p.name == "plane.urdf"]
    shutil.copy(plane.parent / "plane100.obj", tmp_path / "plane100.obj")
    inertial = (f'<inertial><mass value="{mass}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" '
                'iyz="0" izz="1"/></inertial>') if mass else ""
    other = ('<link name="b"/><joint name="j" type="fixed"><parent link="a"/><child link="b"/>'
             '</joint>') if second_link else ""
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="a">{inertial}<visual><geometry>'
                    f'<mesh filename="plane100.obj"/></geometry></visual></link>{other}</robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB404")
    assert ("SB404" in codes(result.stdout)) is expected, result.stdout
