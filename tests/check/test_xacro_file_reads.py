"""A file xacro cannot read is named with what read it: an include or an expression."""

from __future__ import annotations

from tests.check.helpers import findings

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'


def _sb001(run, tmp_path, body: str, *args: str) -> list[str]:
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(f'{HEAD}{body}<link name="base"/></robot>')
    result = run("check", path, *args, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.output
    return [str(f["message"]) for f in findings(result.stdout) if f["code"] == "SB001"]


def test_load_yaml_of_an_argument_left_empty_names_the_expression(run, tmp_path):
    # motoman's es165.xacro: joint_velocities_file defaults to "", so load_yaml reads a directory
    body = ('<xacro:arg name="joint_velocities_file" default=""/>'
            '<xacro:property name="v" value="${xacro.load_yaml(\'$(arg joint_velocities_file)\')}"'
            '/><link name="l${v[\'a\']}"/>')
    (message,) = _sb001(run, tmp_path, body)
    assert "cannot read file" in message and "included" not in message
    assert "that 'xacro.load_yaml('$(arg joint_velocities_file)')' names: Is a directory" \
        in message, message
    (missing,) = _sb001(run, tmp_path, body, "joint_velocities_file:=no_such.yaml")
    assert "no_such.yaml" in missing and "No such file or directory" in missing


def test_an_include_that_is_missing_still_says_include(run, tmp_path):
    (message,) = _sb001(run, tmp_path, '<xacro:include filename="no_such.xacro"/>')
    assert message.startswith("cannot read included file") and "no_such.xacro" in message
