"""Elements other URDF readers add, and sentences about several collision shapes."""

from __future__ import annotations

from tests.check.helpers import findings

LINK = """<robot name="r"><link name="base_link">
  <inertial><mass value="{mass}"/>
    <inertia ixx="{i}" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="{i}"/></inertial>
  <collision name="test"><geometry><cylinder radius="0.1" length="0.2"/></geometry></collision>
  {extra}
</link></robot>"""


def _found(run, tmp_path, **values: str) -> list[tuple[str, str, str]]:
    path = tmp_path / "r.urdf"
    path.write_text(LINK.format(**{"mass": "1", "i": "0.0042", "extra": "", **values}))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    return [(f["code"], f["message"], f["fix"]) for f in findings(result.stdout)]


def test_pinocchios_collision_checking_is_not_a_misspelt_collision(run, tmp_path):
    """Pinocchio's simple_humanoid.urdf: <collision_checking><capsule name="test"/> makes
    the cylinder a capsule. 'Rename it <collision>' broke the link (SB012, urdfdom stops)."""
    extra = '<collision_checking><capsule name="test"/></collision_checking>'
    assert _found(run, tmp_path, extra=extra) == []
    assert [c for c, _, _ in _found(run, tmp_path, extra="<colision/>")] == ["SB010"]


def test_an_inertia_against_two_collision_shapes_reads_as_a_sentence(run, tmp_path):
    extra = '<collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>'
    (found,) = [m for c, m, _ in _found(run, tmp_path, extra=extra, i="4.2") if c == "SB301"]
    assert "does not match a 1 kg solid of its 2 collision shapes (" in found


def test_a_transmission_joint_without_a_name_says_so(run, tmp_path):
    path = tmp_path / "t.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
                    'type="continuous"><parent link="a"/><child link="b"/></joint>'
                    '<transmission name="t"><type>transmission_interface/SimpleTransmission'
                    '</type><joint><hardwareInterface>hardware_interface/EffortJointInterface'
                    '</hardwareInterface></joint><actuator name="m"/></transmission></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB511")
    (found,) = findings(result.stdout)
    assert found["message"].startswith("transmission 't' has a <joint> without a name;")
