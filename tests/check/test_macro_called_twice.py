"""A macro called twice writes its link and joint twice: one cause, said once, with its fix.

linorobot2's 2wd.urdf.xacro with its IMU macro called a second time gave SB101, SB102 and an
SB106 naming the same joint twice, each fixed by 'rename one of the two'; the calls are the
cause. Real xacro expands the files.
"""

from __future__ import annotations

from tests.check.helpers import findings

_IMU = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="imu">
    <link name="imu_link"/>
    <joint name="imu_to_base_link" type="fixed">
      <parent link="base_link"/>
      <child link="imu_link"/>
    </joint>
  </xacro:macro>
</robot>
"""
_ROBOT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="imu.urdf.xacro"/>
  <link name="base_link"/>
  <xacro:imu/>
  <xacro:imu/>
</robot>
"""


def test_a_macro_called_twice_is_named_as_the_cause(run, tmp_path):
    (tmp_path / "imu.urdf.xacro").write_text(_IMU)
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text(_ROBOT)
    result = run("check", "urdf", robot, "--format", "json", "--select", "SB1")
    found = findings(result.stdout)
    assert sorted(f["code"] for f in found) == ["SB101", "SB102"]  # no SB106 besides
    for finding in found:
        assert finding["fix"] == (f"the same macro is called twice ({robot}:5:3 and "
                                  f"{robot}:6:3): remove one call, or give each call its own "
                                  "name prefix")


def test_a_joint_written_twice_by_hand_is_renamed(run, tmp_path):
    robot = tmp_path / "r.urdf"
    joint = ('<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>')
    robot.write_text(f'<robot name="r"><link name="a"/><link name="b"/>{joint}{joint}</robot>')
    result = run("check", "urdf", robot, "--format", "json", "--select", "SB1")
    [found] = findings(result.stdout)
    assert found["code"] == "SB102" and found["fix"] == "rename one of the two joints"
