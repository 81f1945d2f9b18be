"""A <gazebo reference> to a link only an optional part creates: a warning, not an error.

unitree's a1 creates ``stick_link`` under ``<xacro:if value="${rolloverProtection == 'true'}">``
(off by default) and gives it a ``<gazebo>`` block in any case; warthog's accessories add
``bulkhead_link`` through an include its environment switches on. Gazebo ignores the block
when the part is off, as its authors meant. A name no source defines stays an error, with
its suggestion.
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.helpers import findings

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
ROBOT = f"""<?xml version="1.0"?>
<robot name="dog" {XACRO}>
  <xacro:property name="rollover" value="false"/>
  <xacro:arg name="bulkhead" default="false"/>
  <link name="base_link"/>
  <link name="imu_link"/>
  <joint name="imu_joint" type="fixed"><parent link="base_link"/><child link="imu_link"/></joint>
  <xacro:if value="${{rollover == 'true'}}">
    <link name="stick_link"/>
    <joint name="stick_joint" type="fixed">
      <parent link="base_link"/><child link="stick_link"/>
    </joint>
  </xacro:if>
  <xacro:if value="$(arg bulkhead)">
    <xacro:include filename="accessories/bulkhead.urdf.xacro"/>
  </xacro:if>
  <gazebo reference="stick_link"><mu1>0.2</mu1></gazebo>
  <gazebo reference="bulkhead_link"><material>Gazebo/Grey</material></gazebo>
  <gazebo reference="imu_lnk"><gravity>true</gravity></gazebo>
</robot>
"""
BULKHEAD = f"""<?xml version="1.0"?>
<robot {XACRO}>
  <link name="bulkhead_link"/>
  <joint name="bulkhead_joint" type="fixed">
    <parent link="base_link"/><child link="bulkhead_link"/>
  </joint>
</robot>
"""


def _package(root: Path) -> Path:
    package = root / "dog_description"
    (package / "urdf" / "accessories").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>dog_description</name></package>\n")
    (package / "urdf" / "accessories" / "bulkhead.urdf.xacro").write_text(BULKHEAD)
    robot = package / "urdf" / "dog.urdf.xacro"
    robot.write_text(ROBOT)
    return robot


def _sb501(run, *args: object) -> tuple[int, dict[str, dict]]:
    result = run("check", *args, "--select", "SB501", "--format", "json", "--isolated")
    found = [f for f in findings(result.stdout) if f["code"] == "SB501"]
    json.loads(result.stdout)
    return result.exit_code, {f["message"].split('"')[1]: f for f in found}


def test_a_link_of_a_part_left_out_is_a_warning_naming_where_it_is_defined(run, tmp_path):
    exit_code, found = _sb501(run, _package(tmp_path))
    assert exit_code == 1  # the typo stays an error
    assert found["imu_lnk"]["severity"] == "error"
    assert "did you mean 'imu_link'" in found["imu_lnk"]["message"]
    stick, bulkhead = found["stick_link"], found["bulkhead_link"]
    assert (stick["severity"], bulkhead["severity"]) == ("warning", "warning")
    assert "dog.urdf.xacro:9 defines link 'stick_link' in a part it leaves out" \
        in stick["message"]
    assert "accessories/bulkhead.urdf.xacro:3 defines link 'bulkhead_link'" \
        in bulkhead["message"]
    assert "did you mean" not in stick["message"] + bulkhead["message"]


def test_with_the_part_switched_on_the_reference_holds(run, tmp_path):
    exit_code, found = _sb501(run, _package(tmp_path), "bulkhead:=true")
    assert set(found) == {"stick_link", "imu_lnk"}
    assert exit_code == 1


def test_a_plain_urdf_has_no_parts_left_out(run, tmp_path):
    """Expanded to a .urdf, the sources are gone: the reference is an error again."""
    expanded = tmp_path / "dog.urdf"
    result = run("expand", _package(tmp_path), "-o", expanded)
    assert result.exit_code == 0, result.stderr
    exit_code, found = _sb501(run, expanded)
    assert {name: f["severity"] for name, f in found.items()} == {
        "stick_link": "error", "bulkhead_link": "error", "imu_lnk": "error"}


EXTRA_REFERENCES = """  <gazebo reference="lidar_link"><mu1>1</mu1></gazebo>
  <gazebo reference="wheel_joint"><implicitSpringDamper>1</implicitSpringDamper></gazebo>
  <gazebo reference="sonar_link"><material>Gazebo/Grey</material></gazebo>
</robot>"""


def test_only_this_robots_own_sources_count_and_only_definitions(run, tmp_path):
    """Another robot of the package, a <ros2_control> or <transmission> joint and a name in
    a comment define nothing here: those stay errors. Lines count as the file has them."""
    robot = _package(tmp_path)
    urdf = robot.parent
    (urdf / "other.urdf.xacro").write_text(
        f'<robot name="other" {XACRO}><link name="lidar_link"/></robot>')
    (urdf / "control.xacro").write_text(
        f'<robot {XACRO}><ros2_control name="c" type="system"><joint name="wheel_joint">'
        '<state_interface name="position"/></joint></ros2_control></robot>')
    robot.write_text(ROBOT.replace("<link name=\"base_link\"/>", """<!-- an old sensor:
       <link name="sonar_link"/>
  -->
  <link name="base_link"/>
  <xacro:include filename="control.xacro"/>""").replace("</robot>", EXTRA_REFERENCES))
    _, found = _sb501(run, robot)
    assert {name: f["severity"] for name, f in found.items()} == {
        "stick_link": "warning", "bulkhead_link": "warning", "imu_lnk": "error",
        "lidar_link": "error", "wheel_joint": "error", "sonar_link": "error"}
    assert "dog.urdf.xacro:13 defines link 'stick_link'" in found["stick_link"]["message"]


FINGERS = f"""<?xml version="1.0"?>
<robot name="arm" {XACRO}>
  <xacro:arg name="hand" default="false"/>
  <xacro:property name="arm_id" value="fr3"/>
  <xacro:macro name="hand" params="arm_id">
    <link name="${{arm_id}}_leftfinger"/>
    <joint name="${{arm_id}}_finger_joint1" type="prismatic">
      <parent link="base_link"/><child link="${{arm_id}}_leftfinger"/>
      <limit lower="0" upper="0.04" effort="1" velocity="1"/>
    </joint>
    <link name="${{name}}"/>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:if value="$(arg hand)"><xacro:hand arm_id="${{arm_id}}"/></xacro:if>
  <gazebo reference="${{arm_id}}_leftfinger"><mu1>1.13</mu1></gazebo>
  <gazebo reference="fr3_rightfinger"><mu1>1.13</mu1></gazebo>
</robot>
"""


def test_a_name_written_with_expressions_defines_the_names_it_expands_to(run, tmp_path):
    """franka_description with hand:=false gazebo:=true: the fingers' <gazebo> blocks stay,
    and the fingers are made by a macro under a condition not taken, their names written
    ${arm_id}_leftfinger. A template of no literal text (${name}) defines nothing."""
    robot = tmp_path / "arm.urdf.xacro"
    robot.write_text(FINGERS)
    _, found = _sb501(run, robot)
    left, right = found["fr3_leftfinger"], found["fr3_rightfinger"]
    assert left["severity"] == "warning"
    assert "defines link '${arm_id}_leftfinger' (here 'fr3_leftfinger') in macro 'hand', and " \
        "no call of it in this expansion makes it (a call in a part left out" in left["message"]
    assert right["severity"] == "error"


def _wheel_macro(param: str, part: str, kind: str) -> str:
    """A macro ``wheel`` making link ``${PARAM}PART_link`` on a ``kind`` joint to base_link."""
    name = "${" + param + "}" + part
    return (f'<xacro:macro name="wheel" params="{param}"><link name="{name}_link"/>'
            f'<joint name="{name}_joint" type="{kind}"><parent link="base_link"/>'
            f'<child link="{name}_link"/></joint></xacro:macro>')


def test_a_name_template_that_says_nothing_hides_no_typo(run, tmp_path):
    """A used macro writing ${name}_link would match any *_link, so a typo in a <gazebo
    reference> became a warning; an empty ${prefix} before tool0 matched nothing."""
    robot = tmp_path / "arm.urdf.xacro"
    robot.write_text(f"""<?xml version="1.0"?>
<robot name="arm" {XACRO}>
  <xacro:arg name="tool" default="false"/>
  <xacro:property name="prefix" value=""/>
  {_wheel_macro("name", "", "fixed")}
  <link name="base_link"/>
  <xacro:wheel name="lidar"/>
  <xacro:if value="$(arg tool)"><link name="${{prefix}}tool0"/></xacro:if>
  <gazebo reference="lidr_link"><sensor name="s" type="ray"/></gazebo>
  <gazebo reference="tool0"><mu1>1</mu1></gazebo>
</robot>
""")
    _, found = _sb501(run, robot)
    assert found["lidr_link"]["severity"] == "error"
    assert "did you mean 'lidar_link'" in found["lidr_link"]["message"]
    assert found["tool0"]["severity"] == "warning"


def test_a_template_stands_for_a_part_only_where_its_argument_is_written(run, tmp_path):
    """create_robot: create_wheel (${prefix}_wheel_link) is called with left and right; the
    rear wheel is in a comment, and <gazebo reference="rear_wheel_link"> was 'a part it
    leaves out', a warning. Called under a condition not taken, it is one."""
    calls = {"commented": '<!-- <xacro:wheel prefix="rear"/> -->',
             "conditional": '<xacro:if value="$(arg back)"><xacro:wheel prefix="rear"/>'
                            '</xacro:if>'}
    severity = {}
    for kind, call in calls.items():
        robot = tmp_path / f"{kind}.urdf.xacro"
        robot.write_text(f"""<robot name="r" {XACRO}>
  <xacro:arg name="back" default="false"/>
  {_wheel_macro("prefix", "_wheel", "continuous")}
  <link name="base_link"/>
  <xacro:wheel prefix="left"/>
  <xacro:wheel prefix="right"/>
  {call}
  <gazebo reference="rear_wheel_link"><mu1>1</mu1></gazebo>
</robot>""")
        severity[kind] = _sb501(run, robot)[1]["rear_wheel_link"]["severity"]
    assert severity == {"commented": "error", "conditional": "warning"}


def test_an_sdf_link_inside_a_gazebo_block_is_no_part_left_out(run, tmp_path):
    """PR2's gripper.gazebo.xacro adds ``parallel_link`` to the model as SDF inside a
    ``<gazebo>`` block; a ``<gazebo reference>`` to it names no URDF link, as in the .urdf."""
    for suffix in ("urdf", "urdf.xacro"):
        path = tmp_path / f"gripper.{suffix}"
        path.write_text(f'<robot name="r" {XACRO}><link name="base_link"/>\n'
                        '<gazebo>\n  <link name="parallel_link"/>\n</gazebo>\n'
                        '<gazebo reference="parallel_link"><turnGravityOff>true</turnGravityOff>'
                        '</gazebo></robot>')
        result = run("check", path, "--format", "json", "--isolated", "--select", "SB501")
        (found,) = findings(result.stdout)
        assert (found["severity"], found["line"]) == ("error", 5), suffix


def test_a_reference_whose_expression_lost_its_dollar_is_a_typo(run, tmp_path):
    """pmb2_robot's caster.gazebo.xacro: reference="caster_{side}_joint" beside a joint
    named caster_${side}_joint was called an optional part left out, a warning."""
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(
        f'<robot name="r" {XACRO}><link name="base_link"/>\n'
        '<xacro:macro name="caster" params="side">\n'
        '  <joint name="caster_${side}_joint" type="continuous"><parent link="base_link"/>'
        '<child link="caster_${side}_link"/></joint><link name="caster_${side}_link"/>\n'
        '  <gazebo reference="caster_{side}_joint"><mu1>1</mu1></gazebo>\n'
        '</xacro:macro>\n<xacro:caster side="left"/></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB501")
    (found,) = findings(result.stdout)
    assert found["severity"] == "error"
    assert found["message"] == (
        "<gazebo reference=\"caster_{side}_joint\"> names no link or joint; '{side}' has no "
        "'$' before it, so xacro left it as written; did you mean 'caster_left_joint' or "
        "'caster_left_link'?")
    assert found["fix"] == "write '${side}'"


def test_a_definition_this_expansion_expanded_with_a_prefix_leaves_nothing_out(run, tmp_path):
    """summit_xl's <gazebo reference="base_footprint"> beside ``${prefix}base_footprint``,
    expanded as robot_base_footprint: a warning about a part left out (no part is) where the
    expanded URDF gets an error. Expanded with the empty prefix, the reference holds."""
    (tmp_path / "base.xacro").write_text(
        f'<robot {XACRO}>\n  <gazebo reference="base_footprint"><mu1>1</mu1></gazebo>\n'
        '  <xacro:macro name="base" params="prefix">\n'
        '    <link name="${prefix}base_footprint"/>\n'
        '    <joint name="${prefix}base_joint" type="fixed">\n'
        '      <parent link="${prefix}base_footprint"/><child link="${prefix}base_link"/>\n'
        '    </joint>\n    <link name="${prefix}base_link"/>\n  </xacro:macro>\n</robot>\n')
    robot = tmp_path / "r.urdf.xacro"
    robot.write_text(f'<robot name="r" {XACRO}><xacro:arg name="prefix" default=""/>'
                     '<xacro:include filename="base.xacro"/>'
                     '<xacro:base prefix="$(arg prefix)"/></robot>')
    exit_code, found = _sb501(run, robot, "prefix:=robot_")
    assert exit_code == 1 and found["base_footprint"]["severity"] == "error"
    assert "did you mean 'robot_base_footprint'" in found["base_footprint"]["message"]
    assert _sb501(run, robot) == (0, {})


def test_a_link_of_a_macro_no_call_makes_names_the_macro(run, tmp_path):
    """Curiosity's mast is defined in <xacro:macro name="mast">, called as a bare <mast/>
    that today's xacro leaves as written: SB501 spoke of a condition not taken, or an
    include left out, and said to check the xacro arguments, which switch on nothing."""
    robot = tmp_path / "rover.urdf.xacro"
    robot.write_text(f'<robot name="rover" {XACRO}><link name="base_link"/>\n'
                     '<xacro:macro name="mast">\n<link name="camera_link"/>\n<joint '
                     'name="camera_joint" type="fixed"><parent link="base_link"/><child '
                     'link="camera_link"/></joint></xacro:macro>\n<xacro:macro name="wheel" '
                     'params="side"><link name="${side}_wheel_link"/></xacro:macro>\n'
                     '<xacro:wheel side="left"/>\n<gazebo reference="camera_link"><material>'
                     'Gazebo/Red</material></gazebo>\n<gazebo reference="right_wheel_link">'
                     '<mu1>1</mu1></gazebo></robot>')
    _, found = _sb501(run, robot)
    camera = found["camera_link"]["message"]
    assert camera.endswith("rover.urdf.xacro:3 defines link 'camera_link' in macro 'mast', and "
                           "no call of it in this expansion makes it (a call in a part left "
                           "out, or none at all), so Gazebo ignores the block")
    assert found["camera_link"]["fix"].startswith("call macro 'mast' where the robot needs")
    assert found["camera_link"]["severity"] == "warning"
    # a stale name no call could make stays an error, with its suggestion
    assert found["right_wheel_link"]["severity"] == "error"
