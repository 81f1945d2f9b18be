"""A finding in an element made by nested xacro macros names every call that made it.

spot_description's ros2_control macro is called by leg and arm macros, which the robot
file calls: each finding named only the robot file's call, so its 33 SB508 warnings all
pointed at the same two lines, while the values to fix were passed one call further in.
xacro's own errors name the whole chain ("instantiated from").
"""

from __future__ import annotations

import json

from tests.check.helpers import findings

NESTED = """<?xml version="1.0"?>
<robot name="nested" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="arm_joint" params="name parent child lower upper">
    <joint name="${name}" type="revolute">
      <parent link="${parent}"/><child link="${child}"/><axis xyz="0 0 1"/>
      <limit lower="${lower}" upper="${upper}" effort="10" velocity="1"/>
    </joint>
    <link name="${child}"/>
  </xacro:macro>
  <xacro:macro name="arm" params="prefix">
    <xacro:arm_joint name="${prefix}j1" parent="base" child="${prefix}l1" lower="-1" upper="1"/>
    <xacro:arm_joint name="${prefix}j2" parent="${prefix}l1" child="${prefix}l2"
                     lower="2" upper="1"/>
  </xacro:macro>
  <link name="base"/>
  <xacro:arm prefix="a_"/>
</robot>
"""
# a macro that calls itself: the joint at the bottom of six calls
RECURSIVE = """<?xml version="1.0"?>
<robot name="chain" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="segment" params="n">
    <xacro:if value="${n > 0}">
      <link name="l${n}"/>
      <joint name="j${n}" type="revolute">
        <parent link="${'base' if n == 5 else 'l' + str(n + 1)}"/><child link="l${n}"/>
        <axis xyz="0 0 1"/>
        <limit lower="${2 if n == 1 else -1}" upper="1" effort="10" velocity="1"/>
      </joint>
      <xacro:segment n="${n - 1}"/>
    </xacro:if>
  </xacro:macro>
  <link name="base"/>
  <xacro:segment n="5"/>
</robot>
"""


def _sb203(run, tmp_path, text: str, fmt: str = "json"):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(text)
    return run("check", path, "--format", fmt, "--isolated")


def test_every_call_from_the_innermost_out(run, tmp_path):
    result = _sb203(run, tmp_path, NESTED)
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB203"]
    assert found["line"] == 4  # the <joint> in arm_joint's body
    path = str(tmp_path / "robot.urdf.xacro")
    assert found["calls"] == [f"{path}:12:5", f"{path}:16:3"]  # the call passing 2 > 1 first
    assert found["via"] == f"{path}:16:3"
    text = _sb203(run, tmp_path, NESTED, "text").stdout.splitlines()
    at = next(i for i, line in enumerate(text) if "SB203" in line)
    assert text[at + 1:at + 3] == [f"    from the macro call at {path}:12:5",
                                   f"    within the macro call at {path}:16:3"]


def test_a_deep_nest_shows_its_innermost_calls_and_the_outermost(run, tmp_path):
    result = _sb203(run, tmp_path, RECURSIVE)
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB203"]
    path = str(tmp_path / "robot.urdf.xacro")
    assert found["calls"] == [f"{path}:11:7"] * 4 + [f"{path}:15:3"]  # four in the body
    text = _sb203(run, tmp_path, RECURSIVE, "text").stdout.splitlines()
    at = next(i for i, line in enumerate(text) if "SB203" in line)
    assert text[at + 1:at + 5] == [
        f"    from the macro call at {path}:11:7",
        f"    within the macro call at {path}:11:7",
        f"    within the macro call at {path}:11:7",
        f"    within 2 more macro calls, the outermost at {path}:15:3"]


def test_sarif_relates_every_call(run, tmp_path):
    sarif = json.loads(_sb203(run, tmp_path, NESTED, "sarif").stdout)
    (result,) = [r for r in sarif["runs"][0]["results"] if r["ruleId"] == "SB203"]
    lines = [r["physicalLocation"]["region"]["startLine"] for r in result["relatedLocations"]]
    assert lines == [12, 16]
