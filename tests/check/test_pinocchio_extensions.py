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


HEAD = """<robot name="r"><link name="head">
  <inertial><mass value="0.547767"/>
    <inertia ixx="{i}" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="{i}"/></inertial>
  {visual}
  <collision><geometry><sphere radius="0.001"/></geometry></collision>
</link></robot>"""


def _sb301(run, tmp_path, inertia: str, visual: str) -> list[dict[str, object]]:
    path = tmp_path / "head.urdf"
    path.write_text(HEAD.format(i=inertia, visual=visual))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB301")
    return findings(result.stdout)


def test_a_placeholder_collision_gives_way_to_the_visual(run, tmp_path):
    """pinocchio's baxter_simple.urdf: 1 mm collision spheres ('no collision') on links of
    half a kilo; SB301 told the head's inertia to shrink 21,600 times."""
    box = '<visual><geometry><box size="0.15 0.15 0.15"/></geometry></visual>'
    assert _sb301(run, tmp_path, "0.002", box) == []  # what a 15 cm box of 0.55 kg has
    (found,) = _sb301(run, tmp_path, "0.2", box)  # a hundred times that
    assert "solid box 0.15 x 0.15 x 0.15 m (the visual geometry; the collision geometry, " \
        "solid sphere r=0.001 m, is a placeholder)" in str(found["message"])
    assert found["fix"] == "use ixx=0.00205413 iyy=0.00205413 izz=0.00205413 (ixy=ixz=iyz=0)"


def test_a_small_body_is_still_compared_with_its_only_shape(run, tmp_path):
    """pybullet_data's sphere_1cm.urdf: no visual, the collision is the body, and its
    inertia of 1 kg m^2 is a million times too large."""
    (found,) = _sb301(run, tmp_path, "1", "")
    assert "solid sphere r=0.001 m (" in str(found["message"])
    drawn_as_small = '<visual><geometry><sphere radius="0.001"/></geometry></visual>'
    (found,) = _sb301(run, tmp_path, "1", drawn_as_small)
    assert "placeholder" not in str(found["message"])


def test_a_urdf_world_is_named_as_one_and_sdf_pointed_to_gz(run, tmp_path):
    """DART's testWorld.urdf (its parseWorld reads it) got 'for SDF use gz sdf --check', and
    failed a directory run as an error."""
    world = tmp_path / "world.urdf"
    world.write_text('<world name="w"><include filename="r.urdf" model_name="r"/></world>')
    sdf = tmp_path / "model.urdf"
    sdf.write_text('<sdf version="1.6"><model name="m"/></sdf>')
    result = run("check", world, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert result.exit_code == 0 and found["severity"] == "warning"
    assert "a URDF world (DART's)" in found["message"] and "gz sdf" not in str(found["fix"])
    (found,) = findings(run("check", sdf, "--format", "json", "--isolated").stdout)
    assert (found["severity"], found["fix"]) == ("error", "for SDF use gz sdf --check")
