"""SB301 where the geometry is an open mesh: no mass has a moment beyond m R^2 within it.

neuronbot2's laser_frame: 0.362 kg, a lidar mesh 0.1 m across that is not closed, and an
inertia of 6e7 kg m^2 (a radius of gyration of 13 km). With a box or a closed mesh SB301
said 1.5e11 times too large; with the open mesh, nothing. pybullet_data's mug.urdf and
r2d2.urdf give 1 kg m^2 to a 1 kg mug and 50 g grippers the same way.
"""

from __future__ import annotations

import struct

import pytest

from tests.check.helpers import findings, tetrahedron_stl
from tests.conftest import run_servicebot

MASS_KG = 0.362


def _open_box_stl(size: float) -> bytes:
    """A binary STL of a cube of ``size`` with its top left open: no volume to compare."""
    h = size / 2
    corners = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4)]  # no +x top
    data = b"\0" * 80 + struct.pack("<I", 2 * len(quads))
    for a, b, c, d in quads:
        for tri in ((a, b, c), (a, c, d)):
            data += struct.pack("<3f", 0, 0, 0)
            data += b"".join(struct.pack("<3f", *corners[i]) for i in tri) + b"\0\0"
    return data


def _sb301(tmp_path, inertia: float, mesh: bytes, visual: bool = False) -> list[str]:
    (tmp_path / "part.stl").write_bytes(mesh)
    shape = '<geometry><mesh filename="part.stl"/></geometry>'
    body = f"<visual>{shape}</visual>" if visual else f"<collision>{shape}</collision>"
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="base"/><link name="laser_frame"><inertial>'
                    f'<mass value="{MASS_KG}"/><inertia ixx="{inertia}" iyy="{inertia}" '
                    f'izz="{inertia}" ixy="0" ixz="0" iyz="0"/></inertial>{body}</link><joint '
                    'name="j" type="fixed"><parent link="base"/><child link="laser_frame"/>'
                    '</joint></robot>')
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json",
                            "--select", "SB301")
    return [f["message"] for f in findings(result.stdout)]


def test_an_inertia_no_mass_can_have_within_an_open_mesh_is_found(tmp_path):
    (message,) = _sb301(tmp_path, 6e7, _open_box_stl(0.1))
    # the farthest corner is 0.0866 m out: 0.362 kg has at most 0.362 * 0.0075 kg m^2
    assert "is more than 0.362 kg can have within its shapes" in message
    assert "over 0.0866 m from its centre of mass" in message
    assert "no moment exceeds 0.0027" in message and "2.21e+10 times" in message


@pytest.mark.parametrize("inertia", [1e-4, 0.01])  # real, and under ten times the bound
def test_an_inertia_the_mass_can_have_is_not_judged(tmp_path, inertia):
    assert _sb301(tmp_path, inertia, _open_box_stl(0.1)) == []


def test_a_visual_alone_may_be_a_marker(tmp_path):
    """PR2's 1 mm sensor boxes are visuals only: they say nothing of the body."""
    assert _sb301(tmp_path, 6e7, _open_box_stl(0.1), visual=True) == []


def test_a_closed_mesh_is_compared_as_before(tmp_path):
    (message,) = _sb301(tmp_path, 6e7, tetrahedron_stl(0.1))
    assert "does not match a 0.362 kg closed mesh 'part.stl'" in message


def test_a_mass_in_grams_with_the_inertia_made_from_it_is_found(tmp_path):
    """articubot_one's wheel of 0.05 kg written 50, its inertia from the usual cylinder macro
    for 50 kg: mass and inertia agree, so nothing was said, at 25 times osmium's density."""
    radius, length, mass = 0.033, 0.026, 50.0
    ixx = mass * (3 * radius**2 + length**2) / 12
    izz = mass * radius**2 / 2
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="base"/><link name="wheel"><inertial><mass '
                    f'value="{mass}"/><inertia ixx="{ixx}" iyy="{ixx}" izz="{izz}" ixy="0" '
                    f'ixz="0" iyz="0"/></inertial><collision><geometry><cylinder '
                    f'radius="{radius}" length="{length}"/></geometry></collision></link><joint '
                    'name="j" type="continuous"><parent link="base"/><child link="wheel"/>'
                    '<axis xyz="0 0 1"/></joint></robot>')
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json",
                            "--select", "SB301")
    (found,) = findings(result.stdout)
    assert "mass 50 kg makes its solid cylinder r=0.033 m, length 0.026 m 5.62e+05 kg/m^3, " \
        "denser than any metal, and its inertia fits that mass" in found["message"]
    assert found["fix"].startswith('mass value="0.05"')
