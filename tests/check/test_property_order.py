"""SB006 for a property used above the line that defines it says where it is defined.

xacro knows a property only from its definition on: a wheel radius defined at line 10 and
used at line 7 failed with "name 'wheel_rad' is not defined" and the fix "define it before
this line, or include the file that defines it", sending the user after a missing include
where the file defines it three lines below.
"""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  <link name="wheel">
    <collision>
      <geometry>
        <!-- wheel_rad: defined below -->
        <cylinder radius="${wheel_rad}" length="0.02"/>
      </geometry>
    </collision>
  </link>
  <xacro:property name="wheel_rad" value="0.05"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="wheel"/></joint>
</robot>
"""


def test_a_property_defined_below_its_use_is_said_so(tmp_path):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(ROBOT)
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json")
    (found,) = findings(result.stdout)
    assert found["code"] == "SB006" and found["line"] == 7
    assert found["message"].endswith("robot.urdf.xacro:11 defines it, after this line")
    assert found["fix"] == ("move the definition of 'wheel_rad' (line 11) above line 7: xacro "
                            "knows a property only from where it is defined on")


def test_a_property_defined_nowhere_keeps_its_fix(tmp_path):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(ROBOT.replace('  <xacro:property name="wheel_rad" value="0.05"/>\n', ""))
    (found,) = findings(run_servicebot("check", "urdf", path, "--isolated", "--format",
                                       "json").stdout)
    assert found["fix"].startswith("define 'wheel_rad' (<xacro:property")


_ROOT_ARG = """<?xml version="1.0"?>
<robot xmlns:xacro="http://ros.org/wiki/xacro" name="xarm$(arg dof)">
  <xacro:arg name="dof" default="7"/>
  <link name="base_link"/>
</robot>
"""
_LATE_ARG = """<?xml version="1.0"?>
<robot xmlns:xacro="http://ros.org/wiki/xacro" name="r">
  <link name="link$(arg dof)"/>
  <xacro:arg name="dof" default="7"/>
</robot>
"""


def _sb006(path, *args):
    result = run_servicebot("check", "urdf", *args, "--isolated", "--format", "json")
    return [f for f in findings(result.stdout) if f["code"] == "SB006"]


def test_an_argument_read_by_the_robot_tag_is_no_missing_default(tmp_path):
    """xarm_ros2's xarm_device.urdf.xacro: name="xarm$(arg dof)" and <xacro:arg name="dof"
    default="7"/> below it; real xacro fails without dof:=, and the argument has a default.
    """  # noqa: D205
    path = tmp_path / "xarm_device.urdf.xacro"
    path.write_text(_ROOT_ARG)
    (named,) = _sb006(path, path)
    assert named["severity"] == "error" and named["line"] == 2
    assert "declares it inside <robot>, whose own attributes xacro expands first" in \
        named["message"]
    assert named["fix"] == ("pass dof:=VALUE (as a launch file does), or write the <robot> "
                            "name without $(arg dof)")
    (walked,) = _sb006(path, tmp_path)  # a walk passes no arguments: a warning
    assert walked["severity"] == "warning" and "with no default" not in walked["message"]
    assert _sb006(path, path, "dof:=6") == []


def test_an_argument_declared_below_its_use_is_said_so(tmp_path):
    path = tmp_path / "late.urdf.xacro"
    path.write_text(_LATE_ARG)
    (found,) = _sb006(path, path)
    assert found["line"] == 3 and "late.urdf.xacro:4 declares it, after this line" in \
        found["message"]
    assert found["fix"] == 'move <xacro:arg name="dof"> (line 4) above line 3, or pass dof:=VALUE'


def test_an_argument_an_include_reads_before_its_includer_declares_it(tmp_path):
    (tmp_path / "part.xacro").write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <link name="$(arg prefix)base_link"/>\n</robot>\n')
    main = tmp_path / "main.urdf.xacro"
    main.write_text('<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro" '
                    'name="r">\n  <xacro:include filename="part.xacro"/>\n'
                    '  <xacro:arg name="prefix" default=""/>\n</robot>\n')
    (found,) = _sb006(main, main)
    assert found["file"].endswith("part.xacro") and found["line"] == 3
    assert f"{main}:4 declares it, after the include that reads it" in found["message"]
    assert found["fix"] == (f'move <xacro:arg name="prefix"> ({main}:4) above the '
                            "<xacro:include> of part.xacro")


def test_an_argument_declared_on_the_robot_tags_own_line(tmp_path):
    path = tmp_path / "same.urdf.xacro"
    path.write_text('<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro" '
                    'name="bot_$(arg dof)"><xacro:arg name="dof" default="6"/>\n'
                    '  <link name="base_link"/>\n</robot>\n')
    (found,) = _sb006(path, path)
    assert "declares it inside <robot>, whose own attributes xacro expands first" in \
        found["message"]
