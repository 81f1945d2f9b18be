"""Materials as urdfdom defines them: at the top level, or named with a colour in a visual.

Motoman's arms (mh5, sia, gp) give the first link's visual <material name="blue"><color
.../></material> and the later links <material name="blue"/>: urdfdom keeps the first for
the others, and check_urdf accepts the file. SB112 said "not defined at the top level".
"""

from __future__ import annotations

import subprocess

import pytest

from tests.check.corpus import check_urdf_commands
from tests.check.helpers import findings

LINK = """  <link name="{name}">
    <visual><geometry><box size="0.1 0.1 0.1"/></geometry>{material}</visual>
  </link>
"""
DEFINING = '<material name="blue"><color rgba="0 0 1 1"/></material>'
USING = '<material name="blue"/>'


def _robot(*materials: str) -> str:
    links = "".join(LINK.format(name=f"l{k}", material=m) for k, m in enumerate(materials))
    joints = "".join(f'  <joint name="j{k}" type="fixed"><parent link="l{k - 1}"/>'
                     f'<child link="l{k}"/></joint>\n' for k in range(1, len(materials)))
    return f'<?xml version="1.0"?>\n<robot name="r">\n{links}{joints}</robot>\n'


@pytest.mark.parametrize(("materials", "undefined"), [
    ((DEFINING, USING, USING), 0),  # motoman: defined in the first link, used after
    ((USING, DEFINING), 1),  # used before the link that defines it: urdfdom warns
    ((USING, USING), 2),
])
def test_a_colour_in_an_earlier_visual_defines_the_material(run, tmp_path, materials,
                                                            undefined):
    import subprocess

    path = tmp_path / "r.urdf"
    path.write_text(_robot(*materials))
    result = run("check", path, "--format", "json", "--isolated")
    assert len([f for f in findings(result.stdout) if f["code"] == "SB112"]) == undefined
    _, native, env = check_urdf_commands()
    said = subprocess.run([*native, str(path)], capture_output=True, text=True, env=env)
    assert said.stdout.count("material 'blue' undefined") + said.stderr.count(
        "material 'blue' undefined") == 2 * undefined  # urdfdom prints each warning twice


@pytest.mark.parametrize(("rgba", "dropped"), [("255 128 0 1", True), ("1.0000001 0 0 1", True),
                                               ("-0.1 0 0 1", True), ("0.5 0.5 0.5 1", False)])
def test_a_colour_outside_zero_to_one_is_an_error_as_urdfdom_drops_it(run, tmp_path, rgba,
                                                                      dropped):
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><material name="m"><color rgba="{rgba}"/></material>'
                    '<link name="a"><visual><geometry><sphere radius="1"/></geometry>'
                    '<material name="m"/></visual></link></robot>')
    _, native, env = check_urdf_commands()
    said = subprocess.run([*native, str(path)], capture_output=True, text=True, env=env)
    assert ("Material [m] not defined" in said.stderr) is dropped
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB113")
    assert [f["severity"] for f in findings(result.stdout)] == (["error"] if dropped else [])


@pytest.mark.parametrize(("rgba", "fix"), [("255 128 0 1", 'rgba="1 0.502 0 1"'),
                                           ("1 1 1 1.0000000001", 'rgba="1 1 1 1"'),
                                           ("-0.1 0 0 1", 'rgba="0 0 0 1"')])
def test_a_colour_outside_zero_to_one_is_fixed_by_its_kind(run, tmp_path, rgba, fix):
    """A rounding past 1 is clamped, not divided by 255 into a near-transparent alpha."""
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><material name="m"><color rgba="{rgba}"/></material>'
                    '<link name="a"/></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB113")
    (found,) = findings(result.stdout)
    assert found["fix"] == fix


def test_a_nan_colour_is_said_once_as_not_a_number(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><material name="m"><color rgba="0 0 nan 1"/></material>'
                    '<link name="a"><visual><geometry><sphere radius="1"/></geometry>'
                    '<material name="m"/></visual></link></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB113,SB014")
    assert [f["code"] for f in findings(result.stdout)] == ["SB014"]
