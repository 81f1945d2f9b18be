"""xacro directives written without ``xacro:``, as xacro before 1.14 and 2.0.8 took them.

youbot_description and amr-ros-config write ``<property>``, ``<macro>`` and ``<include>``:
today's xacro leaves them as they are. A bare include read no file and check passed (the
wheel it defined was missing); a bare property's name was undefined where used, and the fix
said to define the property that stood three lines above.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'


def test_a_bare_include_is_named_with_the_file_it_never_reads(run, tmp_path):
    (tmp_path / "wheel.xacro").write_text(
        f'{HEAD}<link name="wheel"/><joint name="w" type="continuous"><parent link="base"/>'
        '<child link="wheel"/></joint></robot>')
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<link name="base"/>\n<include filename="wheel.xacro"/>\n</robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert (found["code"], found["line"], found["fix"]) == (
        "SB017", 3, "write <xacro:include .../>")
    assert "'wheel.xacro' is never read" in found["message"]


@pytest.mark.parametrize(("definition", "use", "fix"), [
    ('<property name="mass" value="1"/>', '<link name="${mass}"/>',
     'write <xacro:property name="mass" .../>'),
    ('<macro name="part" params="name"><link name="${name}"/></macro>', "",
     'write <xacro:macro name="part" .../>'),
    ('<arg name="side" default="l"/>', '<link name="$(arg side)"/>',
     'write <xacro:arg name="side" .../>'),
])
def test_a_bare_definition_is_named_where_its_name_is_undefined(run, tmp_path, definition, use,
                                                                fix):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f"{HEAD}\n{definition}\n{use}\n</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert found["code"] == "SB006" and found["fix"] == fix
    assert f"at {path}:2:1 has no xacro: prefix" in found["message"]
