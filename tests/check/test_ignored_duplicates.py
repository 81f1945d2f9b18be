"""A second <origin>, <limit> or <mass> where urdfdom reads one: not judged, and an error
where MuJoCo refuses the file for it, else a warning.

urdfdom takes the first (FirstChildElement); a user who adds a second as an override sees
nothing change. MuJoCo's URDF import refuses most of them ('repeated element'): it passed
as a warning. pybullet's spirit40newer.urdf writes RL_lower_joint's <axis> twice.
"""

from __future__ import annotations

from pathlib import Path

import pinocchio as pin

from tests.check.helpers import findings

ROBOT = """<robot name="r">
  <link name="a"/>
  <link name="b"><inertial><mass value="2"/><mass value="oops"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
    <origin xyz="0.1 0 0"/>
    <origin xyz="0.5 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_the_second_is_named_and_the_first_is_what_loads(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT)
    model = pin.buildModelFromUrdf(str(path))
    assert model.jointPlacements[1].translation[0] == 0.1  # the first origin
    assert model.inertias[1].mass == 2.0  # the first mass
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB0")
    found = [(f["code"], f["line"], f["severity"]) for f in findings(result.stdout)]
    # no SB013 for the mass nothing reads
    assert found == [("SB020", 3, "error"), ("SB020", 7, "error")]
    assert all("MuJoCo refuses the file ('repeated element')" in f["message"]
               for f in findings(result.stdout))
    assert result.exit_code == 1


def test_a_second_element_mujoco_takes_is_a_warning(run, tmp_path):
    """MuJoCo drops visuals, and reads a joint's first <safety_controller> only."""
    import mujoco

    text = ROBOT.replace('<mass value="oops"/>', "").replace(
        '<origin xyz="0.5 0 0"/>', '<safety_controller k_velocity="1"/><safety_controller '
        'k_velocity="2"/>').replace('<link name="a"/>', '<link name="a"><visual><origin/>'
                                    '<origin/><geometry><box size="1 1 1"/></geometry></visual>'
                                    "</link>")
    mujoco.MjModel.from_xml_string(text)  # loads
    path = tmp_path / "r.urdf"
    path.write_text(text)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB020")
    assert [(f["line"], f["severity"]) for f in findings(result.stdout)] == [
        (2, "warning"), (7, "warning")]
    assert result.exit_code == 0


def test_pybullets_doubled_axis_is_found(run):
    import pybullet_data

    path = Path(pybullet_data.getDataPath()) / "quadruped" / "spirit40newer.urdf"
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB020")
    (found,) = findings(result.stdout)
    assert found["line"] == 550 and "'RL_lower_joint' has a second <axis>" in found["message"]


def test_a_materials_second_color_is_an_error(run, tmp_path):
    """MuJoCo refuses it ('repeated element: color'); a second <texture> it takes."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><material name="m"><color rgba="1 0 0 1"/><color '
                    'rgba="0 1 0 1"/></material><link name="a"/></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB020")
    assert [f["severity"] for f in findings(result.stdout)] == ["error"]
