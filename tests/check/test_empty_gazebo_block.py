"""An empty ``<gazebo reference>`` block for a link the robot lacks: nothing lost, a warning.

ROBOTIS's omy_l100 leaves ``<gazebo reference="end_effector_link"></gazebo>`` for a link it
no longer has. sdformat applies extension blocks to the links they name and drops the
others: an empty one takes nothing with it. A block that holds settings stays an error, as
they are lost.
"""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"/>
  <link name="link1"/>
  <joint name="joint1" type="fixed"><parent link="base_link"/><child link="link1"/></joint>
  <gazebo reference="end_effector_link">
  </gazebo>
  <gazebo reference="end_effector_lnk"><mu1>0.5</mu1></gazebo>
  <gazebo reference="link_tool"/>
</robot>
"""


def test_an_empty_block_is_a_warning_and_one_with_settings_an_error(tmp_path):
    robot = tmp_path / "arm.urdf"
    robot.write_text(ROBOT)
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB501")
    found = {f["line"]: (f["severity"], f["message"]) for f in findings(result.stdout)}
    assert found[6][0] == "warning" and "is empty: Gazebo drops it" in found[6][1]
    assert found[8][0] == "error" and "did you mean 'end_effector_link'" not in found[8][1]
    assert found[9][0] == "warning"
    assert result.returncode == 1  # the block with settings
