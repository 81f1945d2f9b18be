"""Origins farther than any robot reaches (1e308 m): named by check, refused by the moving
commands, shown by inspect, and never a library's warning on stderr."""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import assert_one_line_error, run_servicebot

ARM = """<robot name="far">
  <link name="base_link"/>
  <link name="link1"/>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <link name="tip"/>
  <joint name="tip_joint" type="fixed"><parent link="link1"/><child link="tip"/>
    <origin xyz="{x} 0 0" rpy="0 0.5 0"/></joint>
</robot>
"""


@pytest.mark.parametrize(("x", "severity"), [("1e308", "error"), ("2e7", "warning"),
                                             ("1e6", None)])
def test_check_names_an_origin_beyond_any_robot(run, tmp_path, x, severity):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(x=x))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB0")
    found = findings(result.stdout)
    if severity is None:
        assert found == []
        return
    (finding,) = found
    assert (finding["code"], finding["severity"], finding["line"]) == ("SB019", severity, 8)
    assert finding["message"].startswith(f'<origin xyz="{x} 0 0"> is {float(x):g} m from its '
                                         "frame, beyond the 1e+06 m of any robot")


@pytest.mark.parametrize("command", [
    ("fk",), ("ik", "--frame", "tip", "--position", "1", "0", "0"),
    ("simulate", "--headless", "--duration-s", "0.1"),
])
def test_moving_commands_refuse_it_in_one_line(tmp_path, command):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(x="1e308"))
    result = run_servicebot(command[0], path, *command[1:], "--out" if command[0] == "simulate"
                            else "--format", tmp_path / "out" if command[0] == "simulate"
                            else "text", cwd=tmp_path)
    assert_one_line_error(result, 2, "joint 'tip_joint' is placed 1e+308 m from link 'link1', "
                          "beyond the 1e+06 m of any robot; write its <origin xyz> in metres")
    assert not (tmp_path / "out").exists()


def test_inspect_shows_it_without_a_numpy_warning(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(x="1e308"))
    result = run_servicebot("inspect", path, "--section", "totals")
    assert result.returncode == 0 and result.stderr == ""
    assert "arm reach not shown: its joints' origins are too large to add up to a finite " \
        "length" in " ".join(result.stdout.split())
    assert "inf m" not in result.stdout


@pytest.mark.parametrize(("rpy", "said"), [
    ("0 0 90", True), ("90 0 0", True), ("0 -45 180", True), ("0 0 3.14159", False),
    ("0 0 10", False), ("0 0 1e9", False), ("0 0 7", False), ("0 0 0", False),
    ("1.5708 0 90", False),  # one radian value among them: not all degrees
])
def test_an_origin_rpy_in_degrees_is_a_warning(run, tmp_path, rpy, said):
    """rpy="0 0 90" is 90 rad, a turn of 116.6 degrees; check_urdf takes it (h5 hunt:
    07-physics' wheel visuals and a joint written so passed with no finding)."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"><visual><origin '
                    f'rpy="{rpy}"/><geometry><box size="1 1 1"/></geometry></visual></link>'
                    '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
                    '</robot>')
    found = findings(run("check", path, "--format", "json", "--isolated", "--select",
                         "SB021").stdout)
    assert bool(found) == said
    if said:
        assert found[0]["severity"] == "warning"
        assert found[0]["fix"].startswith('rpy="')


def test_a_negative_angle_in_degrees_turns_the_other_way(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
                    'type="fixed"><origin rpy="-90 0 0"/><parent link="a"/><child link="b"/>'
                    '</joint></robot>')
    (found,) = findings(run("check", path, "--format", "json", "--isolated", "--select",
                            "SB021").stdout)
    assert "so -90 is a turn of -116.6 degrees" in found["message"]


@pytest.mark.parametrize(("kind", "xyz", "refused"), [
    ("fixed", "0 1", True), ("floating", "1 0 0 0", True), ("fixed", "x y z", True),
    ("fixed", "0 0 1", False), ("fixed", "0 0 0", False)])
def test_the_axis_of_a_joint_urdfdom_skips_is_still_read_by_mujoco(run, tmp_path, kind, xyz,
                                                                    refused):
    """urdfdom skips a fixed joint's <axis>; MuJoCo refuses xyz="0 1" there ('attribute
    xyz does not have enough data'), and check said nothing."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
                    f'type="{kind}"><parent link="a"/><child link="b"/><axis xyz="{xyz}"/>'
                    '</joint></robot>')
    found = [f for f in findings(run("check", path, "--format", "json", "--isolated").stdout)
             if f["code"] == "SB013"]
    assert bool(found) is refused
    if refused:
        assert found[0]["severity"] == "error" and "MuJoCo reads it" in found[0]["message"]
