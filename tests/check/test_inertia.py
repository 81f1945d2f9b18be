"""Inertia against geometry: frame-invariant, several shapes, meshes; the fix is usable."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from servicebot_cli.kinematics.transforms import rpy_matrix
from tests.check.corpus import erd_root
from tests.check.helpers import FIXTURES, findings

WHEEL = np.diag([0.00135833333, 0.00245, 0.00135833333])  # 1 kg, r 0.07, l 0.04, axle along y


def _robot(tmp_path, inertial_rpy, tensor, collisions, mass=1.0):
    ixx, ixy, ixz, iyy, iyz, izz = (float(tensor[i, j]) for i, j in
                                    ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)))
    path = tmp_path / "wheel.urdf"
    path.write_text(f"""<robot name="r">
  <link name="base"/>
  <link name="wheel">
    <inertial>
      <origin xyz="0 0 0" rpy="{' '.join(repr(float(a)) for a in inertial_rpy)}"/>
      <mass value="{mass}"/>
      <inertia ixx="{ixx!r}" ixy="{ixy!r}" ixz="{ixz!r}" iyy="{iyy!r}" iyz="{iyz!r}" izz="{izz!r}"/>
    </inertial>
    {collisions}
  </link>
  <joint name="axle" type="continuous"><parent link="base"/><child link="wheel"/>
    <axis xyz="0 1 0"/></joint>
</robot>""")
    return path


CYLINDER_ALONG_Y = """<collision><origin rpy="1.5707963267948966 0 0"/>
      <geometry><cylinder radius="0.07" length="0.04"/></geometry></collision>"""


@pytest.mark.parametrize("rpy", [(0.0, 0.0, 0.0), (0.3, -1.1, 2.0), (np.pi / 2, 0.0, 0.0)])
def test_a_correct_inertia_passes_in_any_inertial_frame(run, tmp_path, rpy):
    rotation = rpy_matrix(*rpy)
    tensor = rotation.T @ WHEEL @ rotation  # the same body, written in rotated axes
    path = _robot(tmp_path, rpy, tensor, CYLINDER_ALONG_Y)
    result = run("check", path, "--format", "json", "--strict")
    assert result.exit_code == 0, result.stdout


def test_the_fix_is_written_in_the_inertial_frame_and_then_passes(run, tmp_path):
    rpy = (0.3, -1.1, 2.0)
    path = _robot(tmp_path, rpy, np.eye(3) * 0.2, CYLINDER_ALONG_Y)
    (finding,) = [f for f in findings(run("check", path, "--format", "json").stdout)
                  if f["code"] == "SB301"]
    values = dict(re.findall(r"(i[xyz]{2})=(\S+)", finding["fix"]))
    fixed = np.array([[values["ixx"], values.get("ixy", 0), values.get("ixz", 0)],
                      [values.get("ixy", 0), values["iyy"], values.get("iyz", 0)],
                      [values.get("ixz", 0), values.get("iyz", 0), values["izz"]]], dtype=float)
    rotation = rpy_matrix(*rpy)
    assert np.allclose(rotation @ fixed @ rotation.T, WHEEL, atol=1e-6)


def test_several_shapes_are_one_solid(run, tmp_path):
    two_boxes = """<collision><origin xyz="0 0 0.05"/><geometry><box size="0.1 0.1 0.1"/></geometry>
    </collision><collision><origin xyz="0 0 -0.05"/><geometry><box size="0.1 0.1 0.1"/>
    </geometry></collision>"""
    tall = np.diag([2 / 12 * 0.05, 2 / 12 * 0.05, 2 / 12 * 0.02])  # 2 kg, 0.1 x 0.1 x 0.2
    path = _robot(tmp_path, (0, 0, 0), tall, two_boxes, mass=2.0)
    assert run("check", path, "--strict").exit_code == 0


def test_a_closed_mesh_is_a_solid_too(run, tmp_path):
    mesh = f'<collision><geometry><mesh filename="{FIXTURES / "meshes" / "cube.stl"}"/>' \
           "</geometry></collision>"
    right = np.eye(3) * (1.0 * 0.02 / 12)  # 1 kg cube, 0.1 m
    assert run("check", _robot(tmp_path, (0, 0, 0), right, mesh), "--strict").exit_code == 0
    wrong = _robot(tmp_path, (0, 0, 0), np.eye(3), mesh)
    (finding,) = [f for f in findings(run("check", wrong, "--format", "json").stdout)
                  if f["code"] == "SB301"]
    assert "closed mesh" in finding["message"] and "ixx=0.00166667" in finding["fix"]



def test_a_product_of_inertia_that_is_only_rounding_is_written_as_0(run):
    # alex's nub.obj: a closed mesh whose sums leave products such as 1.3e-21 beside 1e-4
    robot = erd_root() / "robots" / "alex_description" / "urdf" / "alex_nub_hands.urdf"
    result = run("check", robot, "--format", "json", "--package",
                 f"example-robot-data={erd_root()}")
    fixes = [f["fix"] for f in findings(result.stdout) if f["code"] == "SB301"]
    assert fixes
    for fix in fixes:
        values = {k: float(v) for k, v in re.findall(r"(i[xyz]{2})=([-+.\deE]+)", fix)}
        largest = max(abs(values[k]) for k in ("ixx", "iyy", "izz"))
        products = [values.get(k, 0.0) for k in ("ixy", "ixz", "iyz")]
        assert all(v == 0 or abs(v) > 1e-9 * largest for v in products), fix


def test_a_product_of_inertia_from_a_rounded_right_angle_is_written_as_0(run, tmp_path):
    # rpy="1.5708 0 0" is a right angle to five digits: the cylinder's products of inertia
    # (4e-8 beside 2e-3) are that rounding, not a tilt anyone means
    rounded = CYLINDER_ALONG_Y.replace("1.5707963267948966", "1.5708")
    path = _robot(tmp_path, (0, 0, 0), np.eye(3) * 0.2, rounded)
    (finding,) = [f for f in findings(run("check", path, "--format", "json").stdout)
                  if f["code"] == "SB301"]
    assert finding["fix"] == "use ixx=0.00135833 iyy=0.00245 izz=0.00135833 (ixy=ixz=iyz=0)"


def test_a_massless_root_with_inertia_is_pybullets_fixed_base_a_warning(run):
    """pybullet's own cartpole.urdf and kuka_iiwa/model.urdf give the root link mass 0 and
    an inertia (pybullet: a base fixed to the world); check_urdf and Pinocchio load them.
    A moving link so written is still an error."""
    import pybullet_data

    path = Path(pybullet_data.getDataPath()) / "cartpole.urdf"
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB310")
    (found,) = findings(result.stdout)
    assert (found["severity"], result.exit_code) == ("warning", 0)
    assert found["message"].startswith("root link 'slideBar' has mass 0")


@pytest.mark.parametrize("exponent", [-200, -160, -60, -9, -3, 0, 4, 12, 60, 160, 200])
def test_principal_moments_of_a_diagonal_are_lapacks_bits(exponent):
    """The sorted diagonal stands for LAPACK's eigenvalues only where it gives the same bits."""
    from servicebot_cli.check.solids import principal_moments, tensor

    rng = np.random.default_rng(exponent + 1000)
    for _ in range(300):
        diagonal = rng.uniform(-1, 1, 3) * 10.0 ** exponent * rng.choice([1.0, 0.0, -0.0], 3)
        values = (diagonal[0], 0.0, 0.0, diagonal[1], 0.0, diagonal[2])
        lapack = np.linalg.eigvalsh(tensor(values))
        assert principal_moments(values).tobytes() == lapack.tobytes(), values
    turned = (1.0, 0.2, 0.0, 2.0, 0.0, 3.0)  # not diagonal: LAPACK's own answer
    assert principal_moments(turned).tobytes() == np.linalg.eigvalsh(tensor(turned)).tobytes()


def test_a_mass_in_grams_is_named_as_the_mistake_not_the_inertia(run, tmp_path):
    """A wheel 8 cm in radius of 1823.62 kg: SB301 said the inertia was 790 times too small,
    and its fix multiplied the right inertia by 790. The inertia fits 1.82362 kg."""
    path = tmp_path / "wheel.urdf"
    path.write_text(
        '<robot name="w"><link name="base"/><joint name="j" type="continuous"><parent '
        'link="base"/><child link="wheel"/><axis xyz="0 0 1"/></joint><link name="wheel">'
        '<inertial><mass value="1823.62"/><inertia ixx="0.004" iyy="0.004" izz="0.0074" '
        'ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry><cylinder radius="0.08" '
        'length="0.04"/></geometry></collision></link></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB301")
    (found,) = findings(result.stdout)
    assert found["message"].endswith("denser than any metal, and its inertia fits 1.82362 kg: "
                                     "is the mass in grams?")
    assert found["fix"] == 'mass value="1.82362"'
    heavy = path.read_text().replace('ixx="0.004" iyy="0.004"', 'ixx="4" iyy="4"')
    path.write_text(heavy)  # an inertia that fits no thousandth: the inertia is named
    (found,) = findings(run("check", path, "--format", "json", "--isolated", "--select",
                            "SB301").stdout)
    assert "does not match a 1823.62 kg solid cylinder" in found["message"]


def test_a_mesh_in_millimetres_leaves_the_inertia_to_sb404(run, tmp_path):
    """A 100 mm cube exported in millimetres, unscaled (Fusion, SolidWorks): SB301's fix
    made the inertia a million times the right one, beside SB404's scale fix."""
    mesh = f'<collision><geometry><mesh filename="{FIXTURES / "meshes" / "cube_mm.stl"}"/>' \
           "</geometry></collision>"
    right = np.eye(3) * (1.0 * 0.02 / 12)  # 1 kg cube, 0.1 m
    result = run("check", _robot(tmp_path, (0, 0, 0), right, mesh), "--format", "json")
    assert [f["code"] for f in findings(result.stdout)] == ["SB404"]
