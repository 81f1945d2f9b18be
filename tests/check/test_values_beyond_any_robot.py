"""Values beyond what the computing rules use are reported, not passed in silence.

A mass or an inertia over 1e12 (SB311) and a mesh scale over 1e6 or under 1e-6 (SB404)
were skipped by the rules that compute with them, and no other rule said a word: two links
of 1e308 kg passed, as did an ixx of 1e13 beside 1 that MuJoCo refuses.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings, tetrahedron_stl

LINK = ('<link name="{name}"><inertial><mass value="{mass}"/><inertia ixx="{ixx}" ixy="0" '
        'ixz="0" iyy="1" iyz="0" izz="1"/></inertial>{visual}</link>')
JOINT = ('<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
         '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')


def _codes(run, tmp_path, *, mass="1", ixx="1", scale="1"):
    (tmp_path / "part.stl").write_bytes(tetrahedron_stl(1.0))
    visual = (f'<visual><geometry><mesh filename="part.stl" scale="{scale} {scale} {scale}"/>'
              '</geometry></visual>')
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r">' + LINK.format(name="a", mass=1, ixx=1, visual="")
                    + LINK.format(name="b", mass=mass, ixx=ixx, visual=visual) + JOINT
                    + "</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    return {f["code"]: f for f in findings(result.stdout)}


@pytest.mark.parametrize(("mass", "ixx", "said"), [
    ("1e308", "1", "mass 1e+308 kg"), ("1e15", "1", "mass 1e+15 kg"),
    ("1", "1e13", "ixx 1e+13 kg m^2"), ("1", "-1e20", "ixx -1e+20 kg m^2"),
])
def test_a_mass_or_inertia_no_robot_has_is_an_error(run, tmp_path, mass, ixx, said):
    found = _codes(run, tmp_path, mass=mass, ixx=ixx)
    assert found["SB311"]["severity"] == "error"
    assert f"link 'b' has {said}, beyond the 1e+12 of any robot" in found["SB311"]["message"]


def test_a_mass_within_bounds_is_not_reported(run, tmp_path):
    assert "SB311" not in _codes(run, tmp_path, mass="1e11")


@pytest.mark.parametrize(("scale", "across"), [("1e7", "1e+07"), ("1e-7", "1e-07")])
def test_a_scale_beyond_the_computed_bounds_still_gets_its_size_warning(run, tmp_path, scale,
                                                                        across):
    """The tetrahedron is 1 m across: scaled, 1e7 m or 1e-7 m."""
    found = _codes(run, tmp_path, scale=scale)
    assert f"mesh 'part.stl' is {across} m across" in found["SB404"]["message"]


def test_a_tiny_unscaled_mesh_is_not_told_to_undo_a_scale_it_has_not(run, tmp_path):
    """unitree's g1 fingertips are 0.5 mm marks with no scale: the fix was scale 1000."""
    (tmp_path / "tip.stl").write_bytes(tetrahedron_stl(0.0005))
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r">' + LINK.format(name="a", mass=1, ixx=1, visual="")
                    + LINK.format(name="b", mass=1, ixx=1, visual='<visual><geometry><mesh '
                                  'filename="tip.stl"/></geometry></visual>') + JOINT
                    + "</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB404")
    (found,) = findings(result.stdout)
    assert "0.0005 m across, unscaled" in found["message"]
    assert "scale=" not in found["fix"]
