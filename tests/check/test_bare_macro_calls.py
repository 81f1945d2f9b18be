"""A macro called without ``xacro:`` (as xacro before 1.14 and 2.0.8 took it): xacro leaves it,
check says so.

ugv_gazebo_sim's steerbot.xacro and Robotnik's rbkairos call their wheel macros as
``<front_wheel .../>``. Noetic's and ROS 2's xacro expand only ``<xacro:front_wheel>``; the
bare element stays in the URDF, where every reader skips it, and the wheels are missing.
"""

from __future__ import annotations

from tests.check.helpers import findings

ROBOT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  {include}
  <xacro:macro name="wheel" params="side">
    <link name="${{side}}_wheel"/>
    <joint name="${{side}}_joint" type="continuous">
      <parent link="base_link"/><child link="${{side}}_wheel"/><axis xyz="0 1 0"/>
    </joint>
  </xacro:macro>
  <xacro:macro name="material" params="">
    <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  </xacro:macro>
  <link name="base_link"/>
  <material name="blue"><color rgba="0 0 1 1"/></material>
  {calls}
</robot>
"""


def _warnings(run, path) -> list[str]:
    """Each SB017 finding as ``file:line:column: message; fix``."""
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB017")
    assert result.exit_code == 0, result.output
    return [f"{f['file']}:{f['line']}:{f['column']}: {f['message']}; {f['fix']}"
            for f in findings(result.stdout)]


def test_a_bare_macro_call_is_one_warning_at_the_call(run, tmp_path):
    """Placed at the call, as a finding (SARIF, GitHub annotations); it had line 0."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text(ROBOT.format(include="", calls='<xacro:wheel side="right"/>\n'
                                 '  <wheel side="left"/>'))
    [message] = _warnings(run, path)
    assert message.startswith(f"{path}:16:3: <wheel> is not a macro call")
    assert "(xacro before 1.14 and 2.0.8 took the bare name)" in message  # not Melodic only
    assert f"macro 'wheel' of {path}:4:3" in message
    assert message.endswith("; write <xacro:wheel .../>")
    expanded = run("expand", path)  # as xacro does: the bare element is left as it is
    assert expanded.stderr.strip() == f"warning: {message}"
    expanded = expanded.stdout
    assert 'name="right_wheel"' in expanded and 'name="left_wheel"' not in expanded
    assert '<wheel side="left"/>' in expanded


def test_a_macro_named_like_a_urdf_element_is_not_confused_with_it(run, tmp_path):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(ROBOT.format(include="", calls='<xacro:wheel side="left"/>'))
    assert _warnings(run, path) == []  # the top-level <material> is URDF's, not the macro


def test_a_macro_of_an_included_file_called_bare_is_found_too(run, tmp_path):
    (tmp_path / "caster.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="caster" params=""><link name="caster"/></xacro:macro>\n'
        "</robot>\n")
    path = tmp_path / "r.urdf.xacro"
    path.write_text(ROBOT.format(include='<xacro:include filename="caster.xacro"/>',
                                 calls="<caster/>"))
    [message] = _warnings(run, path)
    assert "<caster> is not a macro call" in message
    assert f"macro 'caster' of {tmp_path / 'caster.xacro'}:2:3" in message
