"""SB017: each warning xacro gives comes with what to change (the real xacro, in-process)."""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
LINK = '<link name="a"/>'


@pytest.mark.parametrize(("body", "args", "message", "fix"), [
    ('<xacro:property name="pi" value="3"/>', [], "redefining global symbol: pi",
     "define 'pi' once, or rename it"),
    ('<xacro:include filename="parts/*.xacro"/>', [], 'matched no files',
     "fix the pattern '"),  # the pattern as xacro resolved it: from the file's directory
    ('<xacro:macro name="m" params="" colour="red"/>', [], "unknown attribute(s): colour",
     "remove colour from <xacro:macro>"),
    ('<xacro:property name="n" value="${len(range(2))}"/><link name="b${n}"/>', [],
     "Using range() directly is deprecated", "write python.range()"),
    ("", ["speed:=2"], "xacro argument 'speed' is not declared",
     "drop speed:=VALUE, or declare it"),
    ('<xacro:include filename="parts/*.xacro"><xacro:arg name="g" default="1"/>'
     '</xacro:include>', [], "Child elements of a <xacro:include> tag are ignored",
     "remove them: the included file already sees"),
    ('<xacro:macro name="wheel" params=""><link name="w"/></xacro:macro><wheel/>', [],
     "<wheel> is not a macro call", "write <xacro:wheel .../>"),
])
def test_each_xacro_warning_says_what_to_change(run, tmp_path, body, args, message, fix):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f"{HEAD}{body}{LINK}</robot>")
    result = run("check", "urdf", path, *args, "--format", "json", "--isolated",
                 "--select", "SB017")
    (found,) = [f for f in findings(result.stdout) if message in f["message"]]
    assert found["fix"].startswith(fix), found["fix"]


def test_a_urdf_that_xacro_must_expand_says_to_name_it_xacro(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(f'{HEAD}<xacro:property name="l" value="a"/><link name="${{l}}"/></robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    (found,) = findings(result.stdout)
    assert found["fix"] == "name it .urdf.xacro"
