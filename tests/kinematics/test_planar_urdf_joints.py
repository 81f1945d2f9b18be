"""A URDF ``planar`` or ``floating`` joint: no value a user gives, so it stands at identity.

fk took zeros for its configuration, which is no rotation at all (a zero matrix block:
the tool at (0, 0, 0.4) where yourdfpy puts it at (0.3, 0, 0.4)); ik moved it and then
reported only the other joints, an answer fk did not reproduce.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import yourdfpy

from tests.conftest import run_servicebot

ROBOT = """<robot name="r">
  <link name="world"/>
  <joint name="base_joint" type="{kind}"><parent link="world"/><child link="base"/>
    <axis xyz="0 0 1"/></joint>
  <link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.4"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="arm"/>
  <joint name="t" type="fixed"><parent link="arm"/><child link="tool"/>
    <origin xyz="0.3 0 0"/></joint>
  <link name="tool"/>
</robot>
"""


@pytest.mark.parametrize("kind", ["planar", "floating"])
def test_fk_and_ik_keep_it_at_identity(tmp_path, kind):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(kind=kind))
    fk = run_servicebot("fk", path, "-j", "j1=0.5", "-f", "tool", "--format", "json")
    assert fk.returncode == 0, fk.stderr
    pose = json.loads(fk.stdout)["poses"][0]
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    urdf.update_cfg({"j1": 0.5})
    theirs = urdf.get_transform("tool", "world")
    assert np.array(pose["matrix"]) == pytest.approx(theirs, abs=1e-12)
    # out of the arm's reach unless the hidden joint moves: not reached, nothing hidden moved
    ik = run_servicebot("ik", path, "-f", "tool", "--position", "1", "1", "0.4", "--format",
                        "json", "--seed", "1")
    answer = json.loads(ik.stdout)
    assert ik.returncode == 1 and not answer["success"]
    assert set(answer["joints"]) == {"j1"}


@pytest.mark.parametrize("command", [("fk", "-f", "tool"), ("ik", "-f", "tool", "--position",
                                                             "0.3", "0", "0.4")])
def test_a_moving_joint_with_a_zero_axis_is_one_line(tmp_path, command):
    """Pinocchio builds <axis xyz="0 0 0"> and places the child with cos(q) times the
    identity: fk printed that as a pose. check reports it as SB207."""
    from tests.conftest import assert_one_line_error

    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(kind="fixed").replace(
        '<origin xyz="0 0 0.4"/><axis xyz="0 0 1"/>', '<origin xyz="0 0 0.4"/><axis xyz="0 0 0"/>'))
    result = run_servicebot(command[0], path, *command[1:])
    assert_one_line_error(result, 2, "joint 'j1' has <axis xyz=\"0 0 0\">")
