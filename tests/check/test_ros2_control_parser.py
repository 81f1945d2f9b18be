"""What ros2_control's component parser refuses in <ros2_control> (component_parser.cpp).

Every release throws 'invalid tag name' for an element it does not read (SB514). From Jazzy
on it also refuses fixed joints and mimic joints it cannot follow; Humble accepts them, so
those are warnings (SB506, SB515).
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

ROBOT = """<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="tool"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>{mimic}</joint>
  <joint name="tool_joint" type="fixed"><parent link="b"/><child link="tool"/></joint>
  <ros2_control name="S" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    {body}
  </ros2_control>{other}
</robot>"""
J1 = '<joint name="j1"><command_interface name="position"/><state_interface name="position"/>' \
     '</joint>'
J2_STATE = '<joint name="j2"{attr}><state_interface name="position"/></joint>'
J2_COMMAND = '<joint name="j2"><command_interface name="position"/>' \
             '<state_interface name="position"/></joint>'
MIMIC = '<mimic joint="j1" multiplier="-1"/>'


def _found(run, tmp_path, *, mimic="", body="", other=""):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(mimic=mimic, body=body, other=other))
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB5")
    return result.exit_code, [(f["code"], f["severity"], f["message"])
                              for f in findings(result.stdout)]


@pytest.mark.parametrize("tag", ["foo", "param", "parameters"])
def test_an_element_the_parser_does_not_read_is_an_error(run, tmp_path, tag):
    code, found = _found(run, tmp_path, body=J1 + f'<{tag} name="x">1</{tag}>')
    assert code == 1
    assert [(c, s) for c, s, _ in found] == [("SB514", "error")]
    assert f"<{tag}> in <ros2_control name=\"S\">" in found[0][2]


def test_every_element_the_parser_reads_passes(run, tmp_path):
    body = J1 + ('<sensor name="ft"><state_interface name="force.x"/></sensor>'
                 '<gpio name="io"><command_interface name="out"/></gpio>'
                 '<transmission name="t"><plugin>transmission_interface/SimpleTransmission'
                 '</plugin><joint name="j1" role="j"/></transmission><!-- a comment -->')
    assert _found(run, tmp_path, body=body) == (0, [])


@pytest.mark.parametrize(("mimic", "body", "says"), [
    (MIMIC, J1 + J2_COMMAND, "mimics 'j1' in the URDF and has a command interface"),
    ("", J1 + J2_STATE.format(attr=' mimic="true"'), "has mimic=\"true\", but no <mimic>"),
    (MIMIC, J2_STATE.format(attr=""), "mimics 'j1', which is not a joint of this"),
])
def test_a_mimic_joint_jazzy_refuses_is_a_warning(run, tmp_path, mimic, body, says):
    code, found = _found(run, tmp_path, mimic=mimic, body=body)
    assert code == 0
    (finding,) = [f for f in found if f[0] == "SB515"]
    assert finding[1] == "warning" and says in finding[2]


@pytest.mark.parametrize(("mimic", "body"), [
    (MIMIC, J1 + J2_STATE.format(attr="")),  # follows its leader in the same component
    (MIMIC, J1 + J2_COMMAND.replace('name="j2"', 'name="j2" mimic="false"')),  # driven alone
    ("", J1 + J2_COMMAND),
])
def test_mimic_joints_jazzy_follows_pass(run, tmp_path, mimic, body):
    assert _found(run, tmp_path, mimic=mimic, body=body) == (0, [])


def test_a_fixed_joint_with_states_only_is_a_warning(run, tmp_path):
    body = J1 + '<joint name="tool_joint"><state_interface name="position"/></joint>'
    code, found = _found(run, tmp_path, body=body)
    assert code == 0
    assert [(c, s) for c, s, _ in found] == [("SB506", "warning")]
    assert "from Jazzy on, ros2_control refuses the robot" in found[0][2]


def test_properties_is_read_from_jazzy_on_and_refused_by_humble(run, tmp_path):
    code, found = _found(run, tmp_path, body=J1 + "<properties><foo>1</foo></properties>")
    assert code == 0
    assert [(c, s) for c, s, _ in found] == [("SB514", "warning")]
    assert "Humble's parser refuses the robot" in found[0][2]
