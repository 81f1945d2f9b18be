"""check on ros/urdf_tutorial (vendored under tests/realworld/ws/src), as its readers run it.

Every step passes: check_urdf accepts each one, and what servicebot still says is a warning
a reader can act on, each kind justified below.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from tests.check.corpus import check_urdf_drops
from tests.check.helpers import findings
from tests.conftest import REPO, run_servicebot

TUTORIAL = REPO / "tests" / "realworld" / "ws" / "src" / "urdf_tutorial"
STEPS = sorted((TUTORIAL / "urdf").glob("0*"))
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}
JUSTIFIED = {
    "SB011",  # <axis rpy="..."/>: urdfdom reads only xyz, the rotation is silently ignored
    "SB215",  # wheel joints without a velocity limit: `drive` cannot scale commands to them
    "SB301",  # 0.001 kg m^2 everywhere: 32 times too small for the 2 kg head of radius 0.2 m
    "SB303",  # step 06 has no inertia at all: fine for RViz, not for a simulator (a warning)
    "SB309",  # the root link carries mass that KDL ignores (an info)
}


@pytest.mark.parametrize("path", STEPS, ids=lambda p: p.name)
def test_every_step_passes_with_justified_warnings_only(path, tmp_path):
    result = run_servicebot("check", "urdf", path, "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stdout
    found = findings(result.stdout)
    assert {f["severity"] for f in found} <= {"warning", "info"}
    assert {f["code"] for f in found} <= JUSTIFIED
    expanded = tmp_path / "robot.urdf"
    expand = run_servicebot("expand", path, "-o", expanded, env=NO_ROS)
    assert expand.returncode == 0, expand.stderr
    assert not check_urdf_drops(expanded)


def test_the_flexible_step_is_kinematic_only_and_says_so():
    result = run_servicebot("check", "urdf", TUTORIAL / "urdf" / "06-flexible.urdf",
                            "--format", "json", env=NO_ROS)
    moving = [f for f in findings(result.stdout) if f["code"] == "SB303"]
    joints = ET.parse(TUTORIAL / "urdf" / "06-flexible.urdf").getroot().iter("joint")
    assert len(moving) == sum(j.get("type") != "fixed" for j in joints) == 8
    assert all(f["severity"] == "warning" for f in moving)


def test_a_joint_written_the_wrong_way_round_is_named_with_the_swap(run, tmp_path):
    """06-flexible with tobox's <parent> and <child> swapped: SB106's fix said to remove the
    joint or give it a child link of its own, never that it was the wrong way round."""
    source = (REPO / "tests" / "realworld" / "ws" / "src" / "urdf_tutorial" / "urdf"
              / "06-flexible.urdf").read_text()
    written = '<parent link="head"/>\n    <child link="box"/>'
    assert written in source
    path = tmp_path / "06-flexible.urdf"
    path.write_text(source.replace(written, '<parent link="box"/>\n    <child link="head"/>'))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB106")
    (found,) = findings(result.stdout)
    assert found["fix"] == ("swap <parent> and <child> of joint 'tobox' ('box' then hangs from "
                            "'head'), or remove joint 'tobox'")
