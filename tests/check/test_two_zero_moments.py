"""Two zero principal moments (0, 0, I) on a link a joint moves: no body, an error (SB308).

fetch's gripper fingers (fetch_ros) give ``ixx="0.002" iyy="0" izz="0"`` on a prismatic
joint: the triangle inequality (0 + 0 >= 0.002) fails, which no mass distribution can do,
and MuJoCo refuses the robot. It was only SB307 (a zero moment), because the zero test came
first. One zero moment (a thin rod) stays a warning, as does (0, 0, I) on a link fixed to
another, which consumers lump into it (anymal's and go1's dummy ``base`` links).
"""

from __future__ import annotations

import mujoco
import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="gripper">
  <link name="palm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="finger"><inertial><mass value="0.1"/>
    <inertia ixx="{ixx}" iyy="{iyy}" izz="0" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="tip"><inertial><mass value="0.1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="slide" type="{joint}"><parent link="palm"/><child link="finger"/>
    <axis xyz="0 1 0"/><limit lower="0" upper="0.05" effort="1" velocity="1"/></joint>
  <joint name="tip_slide" type="prismatic"><parent link="finger"/><child link="tip"/>
    <axis xyz="0 1 0"/><limit lower="0" upper="0.05" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize(("joint", "ixx", "iyy", "expected"), [
    ("prismatic", "0.002", "0", ("SB308", "error")),
    ("prismatic", "0.002", "0.002", ("SB307", "warning")),  # a thin rod along z
    ("fixed", "0.002", "0", ("SB307", "warning")),
])
def test_no_body_on_a_moving_link_is_an_error(tmp_path, joint, ixx, iyy, expected):
    text = ROBOT.format(joint=joint, ixx=ixx, iyy=iyy)
    robot = tmp_path / "gripper.urdf"
    robot.write_text(text)
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB307,SB308")
    (found,) = findings(result.stdout)
    assert (found["code"], found["severity"]) == expected
    assert "'finger'" in found["message"]
    if expected[0] == "SB308":
        with pytest.raises(ValueError, match="inertia must have positive eigenvalues"):
            mujoco.MjModel.from_xml_string(text)
