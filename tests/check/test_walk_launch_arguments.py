"""A xacro file that reads an argument it gives no default, as launch files call it.

universal_robot's ROS 1 ``ur_description/urdf/ur.xacro`` opens with
``<robot name="$(arg robot_model)_robot">``; its ``load_ur.launch`` passes
``robot_model:=...``, and so do talos_description's launch files for ``enable_crane``.
Named on the command line without the argument, xacro refuses it: an error (SB006). Found
in a directory walk, which passes no argument, it cannot be checked: a warning, so that a
walk of such a package is not failed by files its users always expand with arguments.
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.helpers import findings

NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}
TEMPLATE = """<?xml version="1.0"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="$(arg robot_model)_robot">
  <xacro:arg name="safety_limits" default="false"/>
  <link name="base_link"/>
</robot>
"""
BROKEN = """<?xml version="1.0"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="arm">
  <link name="${base}_link"/>
</robot>
"""


def _package(root: Path) -> Path:
    urdf = root / "ur_description" / "urdf"
    urdf.mkdir(parents=True)
    (root / "ur_description" / "package.xml").write_text(
        "<package><name>ur_description</name><version>1.0.0</version></package>\n")
    (urdf / "ur.xacro").write_text(TEMPLATE)
    return urdf / "ur.xacro"


def _sb006(run, *args: object) -> tuple[int, list[dict]]:
    result = run("check", *args, "--format", "json", "--isolated", env=NO_ROS)
    json.loads(result.stdout)
    return result.exit_code, [f for f in findings(result.stdout) if f["code"] == "SB006"]


def test_in_a_walk_a_missing_launch_argument_is_a_warning(run, tmp_path):
    _package(tmp_path)
    exit_code, found = _sb006(run, tmp_path)
    assert exit_code == 0
    assert [f["severity"] for f in found] == ["warning"]
    assert "robot_model" in found[0]["message"] and found[0]["line"] == 2
    assert "robot_model:=VALUE" in found[0]["fix"]


def test_named_without_the_argument_it_is_an_error(run, tmp_path):
    exit_code, found = _sb006(run, _package(tmp_path))
    assert exit_code == 1
    assert [f["severity"] for f in found] == ["error"]


def test_named_with_the_argument_it_is_checked(run, tmp_path):
    exit_code, found = _sb006(run, _package(tmp_path), "robot_model:=ur5")
    assert (exit_code, found) == (0, [])


def test_in_a_walk_other_xacro_failures_stay_errors(run, tmp_path):
    _package(tmp_path)
    (tmp_path / "ur_description" / "urdf" / "broken.urdf.xacro").write_text(BROKEN)
    exit_code, found = _sb006(run, tmp_path)
    assert exit_code == 1
    assert sorted(f["severity"] for f in found) == ["error", "warning"]


LAZY = """<?xml version="1.0"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="mav">
  <xacro:property name="namespace" value="$(arg namespace)"/>
  <link name="${namespace}/base_link"/>
</robot>
"""


def test_an_argument_a_property_reads_is_a_launch_argument_too(run, tmp_path):
    """rotors_simulator's MAVs read $(arg namespace) through a property: xacro's message then
    ends "when evaluating expression 'namespace'", and the walk's verdict is the same."""
    (tmp_path / "mav.xacro").write_text(LAZY)
    exit_code, found = _sb006(run, tmp_path)
    assert exit_code == 0
    assert [f["severity"] for f in found] == ["warning"]
    assert "when evaluating expression 'namespace'" in found[0]["message"]
    assert "namespace:=VALUE" in found[0]["fix"]
    exit_code, found = _sb006(run, tmp_path / "mav.xacro")
    assert exit_code == 1 and [f["severity"] for f in found] == ["error"]


EMPTY_DEFAULTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="dual">
  <xacro:arg name="arm" default=""/>
  <xacro:arg name="dof" default=""/>
  <link name="world"/>
  <xacro:include filename="arms/$(arg arm)/$(arg dof)dof/urdf/$(arg arm)_macro.xacro"/>
</robot>
"""


def test_an_include_named_by_empty_default_arguments_is_a_walks_warning(run, tmp_path):
    """ros_kortex's kortex_dual_robots.xacro: every argument defaults to "", and its include
    becomes arms//dof/urdf/_macro.xacro in a walk. Named, or with a real gap, an error."""
    (tmp_path / "dual.xacro").write_text(EMPTY_DEFAULTS)
    result = run("check", tmp_path, "--format", "json", "--isolated", env=NO_ROS)
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
    assert result.exit_code == 0 and found["severity"] == "warning"
    assert "arms//dof/urdf/_macro.xacro" in found["message"]
    assert "launch arguments the file leaves empty" in found["message"]
    named = run("check", tmp_path / "dual.xacro", "--format", "json", "--isolated", env=NO_ROS)
    assert named.exit_code == 1
    (tmp_path / "dual.xacro").write_text(EMPTY_DEFAULTS.replace('default=""', 'default="gen3"'))
    walked = run("check", tmp_path, "--format", "json", "--isolated", env=NO_ROS)
    assert walked.exit_code == 1  # arms/gen3/gen3dof/...: a real missing file


def test_a_gap_that_no_empty_argument_explains_stays_an_error(run, tmp_path):
    """An unrelated prefix:="" argument, a typo'd double slash, or a default="" in a comment
    do not make a missing include a launch argument's doing."""
    cases = {
        "unrelated": '<xacro:arg name="prefix" default=""/><link name="$(arg prefix)base"/>'
                     '<xacro:include filename="inc/_materials.xacro"/>',
        "typo": '<xacro:arg name="arm" default=""/><xacro:include filename="urdf//arm.xacro"/>',
        "commented": '<!-- <xacro:arg name="arm" default=""/> --><xacro:arg name="arm" '
                     'default="gen3"/><xacro:include filename="arms/$(arg arm)/../x//a.xacro"/>',
        "order": '<xacro:arg default="" name="arm"/>'
                 '<xacro:include filename="arms/$(arg arm)/urdf/$(arg arm)_macro.xacro"/>',
    }
    for name, body in cases.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "r.xacro").write_text(
            f'<robot xmlns:xacro="http://wiki.ros.org/xacro" name="r"><link name="w"/>{body}'
            "</robot>")
        result = run("check", tmp_path / name, "--format", "json", "--isolated", env=NO_ROS)
        (found,) = [f for f in findings(result.stdout) if f["code"] == "SB001"]
        assert found["severity"] == ("warning" if name == "order" else "error"), name


def test_xacros_own_failures_read_as_reasons(run, tmp_path):
    """Not a class's repr with its message twice, not an expression with no reason, not
    Python's recursion limit."""
    cases = {
        "env": ('<link name="$(env NO_SUCH_VARIABLE_HERE)"/>',
                "xacro: environment variable 'NO_SUCH_VARIABLE_HERE' is not set"),
        "memory": ('<link name="${len(list(range(10**11)))}"/>',
                   "when evaluating expression 'len(list(range(10**11)))': out of memory"),
        "recursion": ('<xacro:macro name="m"><xacro:m/></xacro:macro><xacro:m/>',
                      "a macro that calls itself, or a file that includes itself"),
    }
    for name, (body, why) in cases.items():
        robot = tmp_path / f"{name}.urdf.xacro"
        robot.write_text(f'<robot xmlns:xacro="http://wiki.ros.org/xacro" name="r">{body}'
                         "</robot>")
        result = run("expand", robot, env={"NO_SUCH_VARIABLE_HERE": None})
        assert result.exit_code == 2, name
        assert result.stderr.strip().endswith(why), (name, result.stderr)


def test_an_argument_a_macro_body_reads_is_a_walk_warning_too(run, tmp_path):
    """talos_description's arm.urdf.xacro reads $(arg test) inside macro talos_arm; its
    launch file passes test:=; the walk gave an error there and a warning for the same
    argument read at the top level."""
    (tmp_path / "arm.urdf.xacro").write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://wiki.ros.org/xacro" name="arm">\n'
        '  <xacro:macro name="part">\n    <link name="part_$(arg test)"/>\n'
        '  </xacro:macro>\n  <link name="base_link"/>\n  <xacro:part/>\n</robot>\n')
    walked = run("check", "urdf", tmp_path, "--format", "json", "--isolated", env=NO_ROS)
    [found] = findings(walked.stdout)
    assert walked.exit_code == 0 and (found["code"], found["severity"]) == ("SB006", "warning")
    assert "(in macro 'part'" in found["message"] and "not checked here" in found["message"]
    named = run("check", "urdf", tmp_path / "arm.urdf.xacro", "--format", "json", "--isolated",
                env=NO_ROS)
    assert named.exit_code == 1 and findings(named.stdout)[0]["severity"] == "error"
