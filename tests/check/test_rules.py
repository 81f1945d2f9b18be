"""Every rule of the catalogue fires on its own fixture, at a source position."""

from __future__ import annotations

import pytest

from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.findings import Severity
from tests.check.helpers import FIXTURES, findings, fixture

FILE_LEVEL = {"SB002", "SB017", "SB018", "SB702"}  # about the whole file: no line to point at
# Defects that imply another: a loop gives a link two parents, a negative mass leaves the
# moving link massless, a mesh in millimetres has an inertia 10^6 too small for its size.
COMPANIONS = {"SB104": {"SB107"}, "SB107": {"SB106"}, "SB302": {"SB303"}, "SB404": {"SB301"},
              "SB702": {"SB108"}}


def test_every_rule_has_one_fixture_and_every_fixture_a_rule():
    fixtures = {p.name[:5] for p in FIXTURES.iterdir() if p.is_file()}
    assert fixtures == set(RULES)
    for code in RULES:
        fixture(code)  # exactly one


@pytest.mark.parametrize("code", list(RULES))
def test_rule_fires_on_its_fixture(run, code):
    path = fixture(code)
    if code.startswith("SB6"):
        result = run("check", "controllers", path, "--robot", "sim", "--format", "json",
                     "--isolated")
    else:
        result = run("check", "urdf", path, "--format", "json", "--isolated")
    found = [f for f in findings(result.stdout) if f["code"] == code]
    assert found, result.stdout
    rule = RULES[code]
    assert all(f["severity"] == rule.severity.value for f in found)
    assert all(f["name"] == rule.name and f["message"] for f in found)
    failing = rule.severity is Severity.ERROR or code == "SB702"  # SB702 follows an error
    assert result.exit_code == (1 if failing else 0), result.stdout
    for finding in found:
        assert finding["file"].endswith(path.name) or finding["file"].endswith(".xacro")
        if code not in FILE_LEVEL:
            assert finding["line"] > 0 and finding["column"] > 0, finding


@pytest.mark.parametrize("code", [c for c in RULES if not c.startswith(("SB6", "SB70"))])
def test_rule_fires_when_it_alone_is_selected(run, code):
    """--select CODE runs the family that holds CODE: SB513 sat outside gazebo's 'SB50'."""
    result = run("check", "urdf", fixture(code), "--format", "json", "--isolated",
                 "--select", code)
    assert {f["code"] for f in findings(result.stdout)} == {code}, result.stdout


@pytest.mark.parametrize("code", [c for c in RULES if not c.startswith("SB6")])
def test_fixture_has_no_other_defect(run, code):
    """Fixtures show one defect each (the root link's inertia note aside)."""
    result = run("check", "urdf", fixture(code), "--format", "json", "--isolated")
    others = {f["code"] for f in findings(result.stdout)} - {code, "SB309", "SB702"}
    others -= COMPANIONS.get(code, set())
    assert not others, others


def test_a_zero_velocity_limit_prints_as_0_not_minus_0(run, tmp_path):
    """SB508's bounds come from the URDF's limit: a limit of 0 is [0, 0]."""
    from tests.conftest import SIM_URDF

    robot = tmp_path / "r.urdf"
    robot.write_text(SIM_URDF.read_text().replace('velocity="0.44"', 'velocity="0"'))
    done = run("check", "urdf", str(robot), "--format", "json")
    messages = [f["message"] for f in findings(done.stdout) if f["code"] == "SB508"]
    assert messages and all("< 0;" in m and "-0;" not in m for m in messages)


def _arm_with_command_limits(tmp_path, low: str, high: str):
    robot = tmp_path / "arm.urdf"
    robot.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><joint name="j1" type="revolute">'
        '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit '
        'lower="-2.61799387799149" upper="2.61799387799149" effort="1" velocity="1"/></joint>'
        '<ros2_control name="s" type="system"><hardware><plugin>mock_components/GenericSystem'
        '</plugin></hardware><joint name="j1"><command_interface name="position">'
        f'<param name="min">{low}</param><param name="max">{high}</param></command_interface>'
        '<state_interface name="position"/></joint></ros2_control></robot>')
    return robot


def test_command_limits_that_round_the_urdfs_are_within_them(run, tmp_path):
    """DENSO's descriptions give the limits to six decimals: 'min -2.61799 < -2.61799' on
    ten joints, with the fix to write what was written."""
    robot = _arm_with_command_limits(tmp_path, "-2.617994", "2.617994")
    done = run("check", "urdf", robot, "--format", "json", "--isolated", "--select", "SB508")
    assert findings(done.stdout) == []


def test_command_limits_just_beyond_the_urdfs_show_the_digits_that_differ(run, tmp_path):
    robot = _arm_with_command_limits(tmp_path, "-2.617997", "2.61799387799149")
    done = run("check", "urdf", robot, "--format", "json", "--isolated", "--select", "SB508")
    (found,) = findings(done.stdout)
    assert found["message"].endswith("URDF: min -2.618 < -2.61799")


def test_a_joint_to_a_missing_link_is_one_finding_not_two(run, tmp_path):
    """drake's strandbeest: joint floor_weld joins 'floor' to a 'world' the file lacks. That
    is SB103 on the joint; 'floor' is not also 'connected to nothing' (a joint names it)."""
    robot = tmp_path / "welded.urdf"
    robot.write_text('<robot name="r"><link name="floor"/><link name="base"/><link name="arm"/>'
                     '<joint name="floor_weld" type="fixed"><parent link="world"/>'
                     '<child link="floor"/></joint><joint name="j" type="fixed">'
                     '<parent link="base"/><child link="arm"/></joint></robot>')
    result = run("check", robot, "--format", "json", "--isolated")
    codes = [f["code"] for f in findings(result.stdout) if f["severity"] == "error"]
    assert codes == ["SB103"]
    assert "parent link 'world', which does not exist" in findings(result.stdout)[0]["message"]


@pytest.mark.parametrize(("axis", "message"), [
    ("0.041054 0 -0.99916", None),  # ugv_gazebo_sim's ranger_mini: a CAD export, 1.0000031
    ("0.7071 0 0.7071", None),  # 45 degrees with four digits: 0.99999
    ("0 0 1.001", "axis has length 1.001, not 1"),
    ("0.6 0 0.8002", "axis has length 1.00016, not 1"),  # shown with the digits that differ
])
def test_an_axis_is_a_unit_vector_up_to_its_written_digits(run, tmp_path, axis, message):
    from tests.conftest import SIM_URDF

    robot = tmp_path / "r.urdf"
    text = SIM_URDF.read_text()
    assert '<axis xyz="0 0 1"/>' in text
    robot.write_text(text.replace('<axis xyz="0 0 1"/>', f'<axis xyz="{axis}"/>', 1))
    done = run("check", "urdf", str(robot), "--format", "json", "--isolated")
    found = [f["message"] for f in findings(done.stdout) if f["code"] == "SB208"]
    assert found == ([] if message is None else [found[0]])
    if message is not None:
        assert found[0].endswith(message)
