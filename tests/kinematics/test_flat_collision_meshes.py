"""A collision mesh with no volume (a flat plate, a lone triangle) meets the floor as it is.

ik and simulate take each mesh's convex hull to place it against the floor of a wheeled
robot. qhull cannot build the hull of coplanar points: a plate crashed the process
(SIGSEGV, nothing said) and a triangle ended it with an internal error. check passes such
meshes, which are valid.
"""

from __future__ import annotations

import pytest

from tests.conftest import run_servicebot

WHEEL = """  <link name="{side}_wheel"><collision><origin rpy="1.5708 0 0"/>
    <geometry><cylinder radius="0.05" length="0.02"/></geometry></collision></link>
  <joint name="{side}_wheel_joint" type="continuous"><parent link="base_link"/>
    <child link="{side}_wheel"/><origin xyz="0 {y} -0.05"/><axis xyz="0 1 0"/></joint>
"""
ROBOT = ("""<robot name="plate_arm">
  <link name="base_link"><collision><geometry><box size="0.4 0.4 0.1"/></geometry></collision>
  </link>
""" + WHEEL.format(side="left", y="0.25") + WHEEL.format(side="right", y="-0.25") + """
  <link name="plate"><collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <joint name="arm_joint" type="revolute"><parent link="base_link"/><child link="plate"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <link name="tip"/>
  <joint name="tip_joint" type="fixed"><parent link="plate"/><child link="tip"/>
    <origin xyz="0.3 0 0"/></joint>
</robot>
""")
MESHES = {
    "plate.obj": "v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nf 1 2 3\nf 1 3 4\n",
    "triangle.obj": "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n",
    "box.obj": "v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nv 0 0 0.1\nv 0.1 0 0.1\n"
               "v 0.1 0.1 0.1\nv 0 0.1 0.1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\n"
               "f 3 4 8 7\nf 4 1 5 8\n",
}


@pytest.mark.parametrize("mesh", MESHES)
def test_ik_places_any_mesh_against_the_floor(tmp_path, mesh):
    (tmp_path / mesh).write_text(MESHES[mesh])
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(mesh=mesh))
    result = run_servicebot("ik", path, "--frame", "tip", "--position", "0.3", "0", "0.3",
                            "--seed", "1")
    assert result.returncode == 0, (result.returncode, result.stderr)


@pytest.mark.parametrize("limit", ["1e308", "1e200"])
def test_limits_that_bound_nothing_are_no_internal_error(tmp_path, limit):
    """Limits of +-1e308: numpy refused the span of a sample ('high - low range exceeds
    valid bounds', exit 3) and the random starts overflowed (a RuntimeWarning)."""
    path = tmp_path / "arm.urdf"
    path.write_text(f"""<robot name="arm">
  <link name="base"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
  <link name="l1"><collision><origin xyz="0.15 0 0"/><geometry><box size="0.3 0.05 0.05"/>
    </geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
    <limit lower="-{limit}" upper="{limit}" effort="1" velocity="1"/></joint>
  <link name="tip"/>
  <joint name="t" type="fixed"><parent link="l1"/><child link="tip"/><origin xyz="0.3 0 0"/>
  </joint>
</robot>
""")
    result = run_servicebot("ik", path, "--frame", "tip", "--position", "0", "0.3", "0.1",
                            "--seed", "1")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
