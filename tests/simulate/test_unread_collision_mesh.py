"""A collision mesh simulate cannot read is left out of the self-contact check too.

The arm's shape left the missing gripper mesh out with a note, but the self-contact check,
built when the arm first came near the base, read every mesh and stopped the run with exit 2
and 'use --allow-collisions', which was given: whether a run finished depended on its path.
"""

from __future__ import annotations

import json

_ROBOT = """<robot name="mm">
  <link name="base_link"><collision><origin xyz="0 0 0.05"/><geometry>
    <box size="0.3 0.2 0.05"/></geometry></collision></link>
  <link name="left_wheel"><collision><origin rpy="1.5707963 0 0"/><geometry>
    <cylinder radius="0.05" length="0.02"/></geometry></collision></link>
  <link name="right_wheel"><collision><origin rpy="1.5707963 0 0"/><geometry>
    <cylinder radius="0.05" length="0.02"/></geometry></collision></link>
  <joint name="left_wheel_joint" type="continuous"><parent link="base_link"/>
    <child link="left_wheel"/><origin xyz="0 0.15 0.05"/><axis xyz="0 1 0"/></joint>
  <joint name="right_wheel_joint" type="continuous"><parent link="base_link"/>
    <child link="right_wheel"/><origin xyz="0 -0.15 0.05"/><axis xyz="0 1 0"/></joint>
  <link name="link1"><collision><origin xyz="0 0 0.1"/><geometry>
    <cylinder radius="0.03" length="0.2"/></geometry></collision></link>
  <link name="link2"><collision><origin xyz="0.15 0 0"/><geometry>
    <box size="0.3 0.04 0.04"/></geometry></collision></link>
  <link name="link3"><collision><geometry><mesh filename="meshes/gripper.stl"/></geometry>
    </collision></link>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="link1"/>
    <origin xyz="0 0 0.08"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j3" type="revolute"><parent link="link2"/><child link="link3"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>"""


def test_the_arm_folding_onto_the_base_is_a_self_contact_not_an_error(run, tmp_path):
    robot = tmp_path / "mm.urdf"
    robot.write_text(_ROBOT)
    scenario = tmp_path / "arm.yaml"
    scenario.write_text("duration_s: 4\ncmd_vel:\n  - {duration_s: 4, linear_m_s: 0.1}\n"
                        "arm:\n  joint_names: [j1, j2, j3]\n  points:\n"
                        "    - {time_from_start_s: 2, positions: [0.0, 1.8, 0.0]}\n")
    result = run("simulate", robot, "--headless", "-s", scenario, "--allow-collisions",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    assert "mesh 'meshes/gripper.stl' left out" in result.stderr
    assert "--allow-collisions" not in result.stderr
    contacts = json.loads(result.stdout)["self_collisions"]
    assert [{c["first"], c["second"]} for c in contacts] == [{"base_link", "link2"}]
