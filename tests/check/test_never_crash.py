"""Broken values are findings, never an internal error or a library's warning on stderr.

The rules that compute (inertia against geometry, mesh sizes) run on validated values only;
a property test mutates real URDFs (attributes, numbers, elements) and checks every outcome.
"""

from __future__ import annotations

import random
import warnings
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.runner import check_source
from servicebot_cli.check.settings import Settings
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.description.packages import PackageResolver
from tests.check.corpus import check_urdf_drops, erd_root, erd_urdfs
from tests.check.helpers import codes, tetrahedron_stl
from tests.conftest import REAL_URDF
from tests.mutants import mutate

ROBOT = """<robot name="r">
  <link name="base">
    <inertial><mass value="1"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision>{origin}<geometry>{geometry}</geometry></collision>
  </link>
  <link name="arm">
    <inertial><mass value="1"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""
BOX = '<box size="1 1 1"/>'


CASES = [
    ('<origin rpy="0 0"/>', BOX, "SB013"),
    ('<origin xyz=" "/>', BOX, "SB013"),
    ('<origin xyz="nan 0 0"/>', BOX, "SB014"),
    ('<origin xyz="0 inf 0"/>', BOX, "SB014"),
    ("", '<cylinder radius="0.1" length="inf"/>', "SB014"),
    ("", '<mesh filename="m.stl" scale="0 0 0"/>', "SB405"),
    ("", '<sphere radius="\uff10.\uff11"/>', "SB013"),  # full-width digits
    ("", '<sphere radius="\u0660.\u0661"/>', "SB013"),  # Arabic-Indic digits
    ("", '<mesh filename="m.stl" scale="1 1 1 1"/>', "SB013"),
    ("", '<mesh filename=""/>', "SB012"),
    ("", '<plane normal="0 0 1"/>', "SB406"),
]


@pytest.mark.parametrize(("origin", "geometry", "code"), CASES)
def test_bad_values_are_errors_where_urdfdom_drops_the_shape(run, tmp_path, origin, geometry,
                                                              code):
    """check_urdf exits 0 on these, but urdfdom drops the shape: the robot changes."""
    (tmp_path / "m.stl").write_bytes(tetrahedron_stl(0.1))
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(origin=origin, geometry=geometry))
    result = run("check", path, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.stderr
    assert code in codes(result.stdout)
    assert result.stderr == ""
    # urdfdom accepts an empty filename and a zero scale (Gazebo and hpp-fcl do not)
    assert check_urdf_drops(path) == (code not in ("SB012", "SB405"))


def test_a_mesh_with_huge_coordinates_is_a_size_warning(run, tmp_path):
    (tmp_path / "m.stl").write_bytes(tetrahedron_stl(1e30))
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(origin="", geometry='<mesh filename="m.stl"/>'))
    result = run("check", path, "--format", "json", "--isolated")
    assert result.exit_code == 0 and result.stderr == ""
    assert "SB404" in codes(result.stdout)


def test_a_texture_without_filename_is_a_warning(run, tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(origin="", geometry=BOX).replace(
        "<collision>", '<visual><geometry><box size="1 1 1"/></geometry>'
        '<material name="m"><texture/></material></visual><collision>'))
    result = run("check", path, "--format", "json", "--isolated")
    assert "SB112" in codes(result.stdout) and result.exit_code == 0


# -- property test: mutations of real URDFs -------------------------------------------------

_SOURCES = [REAL_URDF, *[p for p in erd_urdfs() if p.name in ("ur5_robot.urdf", "solo12.urdf")]]


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(source=st.sampled_from(_SOURCES), seed=st.integers(0, 2**32 - 1),
       steps=st.integers(1, 12))
def test_mutated_real_urdfs_never_crash_or_warn(tmp_path_factory, source, seed, steps):
    root = ET.parse(source).getroot()
    mutate(root, random.Random(seed), steps)
    path = tmp_path_factory.mktemp("mutant") / "robot.urdf"
    path.write_bytes(ET.tostring(root))
    env = CheckEnv(resolver=PackageResolver.from_environment(
        {"example-robot-data": erd_root()}, environ={}))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a numpy or library warning fails the test
        report = check_source(RobotSource.of(path), Settings(), env)
    assert all(f.message for f in report.findings)
