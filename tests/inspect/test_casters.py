"""Passive casters are neither drive wheels nor an arm (MiR's layout).

mir_description (DFKI-NI/mir_robot) gives MiR two driven wheels at y = +/-0.222604 m and
four casters: a continuous swivel about z over a continuous caster wheel. The casters' wheels
were taken for drive wheels, so the track was the mean over six wheels (0.419 m instead of
diff_drive_controller's 0.445208 m), and the swivels made an "arm" 0.1 m long.
"""

from __future__ import annotations

import json

import pytest

INERTIA = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
           'ixz="0" iyz="0"/></inertial>')
WHEEL = '<collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="{r}" length="0.03"/>'\
        '</geometry></collision>'


def _link(name: str, radius: float | None = None) -> str:
    shape = WHEEL.format(r=radius) if radius else ""
    return f'<link name="{name}">{INERTIA}{shape}</link>'


def _continuous(name: str, parent: str, child: str, xyz: str, axis: str) -> str:
    return (f'<joint name="{name}" type="continuous"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="{xyz}"/><axis xyz="{axis}"/>'
            '<limit effort="100" velocity="20"/></joint>')


def _mir_like() -> str:
    parts = [_link("base_link")]
    for side, y in (("left", 0.222604), ("right", -0.222604)):
        parts += [_link(f"{side}_wheel_link", 0.0625),
                  _continuous(f"{side}_wheel_joint", "base_link", f"{side}_wheel_link",
                              f"0 {y} 0.0625", "0 1 0")]
    for corner, x, y in (("fl", 0.3037, 0.203), ("fr", 0.3037, -0.203),
                         ("bl", -0.3037, 0.203), ("br", -0.3037, -0.203)):
        parts += [_link(f"{corner}_caster_rotation_link"),
                  _link(f"{corner}_caster_wheel_link", 0.0625),
                  _continuous(f"{corner}_caster_rotation_joint", "base_link",
                              f"{corner}_caster_rotation_link", f"{x} {y} 0.1565", "0 0 1"),
                  _continuous(f"{corner}_caster_wheel_joint", f"{corner}_caster_rotation_link",
                              f"{corner}_caster_wheel_link", "-0.0382 0 -0.094", "0 1 0")]
    return '<robot name="mir_like">' + "".join(parts) + "</robot>\n"


@pytest.fixture
def mir(tmp_path):
    path = tmp_path / "mir_like.urdf"
    path.write_text(_mir_like())
    return path


def test_totals_count_casters_apart_and_take_the_track_from_the_drive_wheels(run, mir):
    result = run("inspect", mir, "--section", "totals", "--format", "json")
    assert result.exit_code == 0, result.stderr
    totals = json.loads(result.stdout)["totals"]
    assert totals["dof"] == {"total": 10, "wheels": 2, "arm": 0, "chassis": 8}
    assert totals["arm"] is None
    drive = totals["drive"]
    assert drive["left"] == ["left_wheel_joint"] and drive["right"] == ["right_wheel_joint"]
    assert drive["track_m"] == pytest.approx(0.445208)
    text = run("inspect", mir, "--section", "totals").stdout
    assert "10: 2 wheels + 0 arm + 8 casters and suspension" in text and "arm reach" not in text


def test_check_controllers_takes_mirs_wheel_separation(run, mir, tmp_path):
    yaml = tmp_path / "controllers.yaml"
    yaml.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 50\n"
                    "    diff_drive_controller:\n"
                    "      type: diff_drive_controller/DiffDriveController\n"
                    "diff_drive_controller:\n  ros__parameters:\n"
                    '    left_wheel_names: ["left_wheel_joint"]\n'
                    '    right_wheel_names: ["right_wheel_joint"]\n'
                    "    wheel_separation: 0.445208\n    wheel_radius: 0.0625\n")
    result = run("check", "controllers", yaml, "--urdf", mir, "--isolated")
    assert result.exit_code == 0, result.stdout
    assert "SB60" not in result.stdout


def test_rockers_that_carry_the_wheels_are_running_gear_not_an_arm(run, tmp_path):
    # Leo Rover (LeoRover/leo_common-ros2): each side's two wheels hang from a rocker, a
    # revolute joint about y; the rockers were an "arm" reaching 0.19 m
    parts = [_link("base_link")]
    for side, y in (("L", 0.1), ("R", -0.1)):
        parts += [_link(f"rocker_{side}_link"),
                  f'<joint name="rocker_{side}_joint" type="revolute"><parent link="base_link"/>'
                  f'<child link="rocker_{side}_link"/><origin xyz="0 {y} 0"/>'
                  '<axis xyz="0 1 0"/><limit lower="-0.24" upper="0.24" effort="100" '
                  'velocity="2"/></joint>']
        for end, x in (("F", 0.15), ("B", -0.15)):
            parts += [_link(f"wheel_{side}{end}_link", 0.057),
                      _continuous(f"wheel_{side}{end}_joint", f"rocker_{side}_link",
                                  f"wheel_{side}{end}_link", f"{x} {y * 1.2} -0.05", "0 1 0")]
    robot = tmp_path / "leo_like.urdf"
    robot.write_text('<robot name="leo_like">' + "".join(parts) + "</robot>\n")
    result = run("inspect", robot, "--section", "totals", "--format", "json")
    assert result.exit_code == 0, result.stderr
    totals = json.loads(result.stdout)["totals"]
    assert totals["dof"] == {"total": 6, "wheels": 4, "arm": 0, "chassis": 2}
    assert totals["arm"] is None


def _joint(name: str, kind: str, parent: str, child: str, xyz: str, axis: str) -> str:
    limit = '<limit lower="-2" upper="2" effort="10" velocity="1"/>' if kind != "continuous" \
        else '<limit effort="10" velocity="10"/>'
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="{xyz}"/><axis xyz="{axis}"/>{limit}</joint>')


def _totals(run, tmp_path, body: str) -> dict:
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">{body}</robot>\n')
    result = run("inspect", path, "--section", "totals", "--format", "json")
    assert result.exit_code == 0, result.stderr
    totals: dict = json.loads(result.stdout)["totals"]
    return totals


def test_an_arm_with_a_waist_and_a_continuous_elbow_is_an_arm(run, tmp_path):
    # Kinova's layout: a continuous joint about z, then others; no wheel anywhere
    links = "".join(_link(n) for n in ("base", "l1", "l2", "l3", "l4"))
    joints = (_joint("joint_1", "continuous", "base", "l1", "0 0 0.15", "0 0 1")
              + _joint("joint_2", "revolute", "l1", "l2", "0 0 0.1", "0 1 0")
              + _joint("joint_3", "continuous", "l2", "l3", "0 0 0.2", "0 0 1")
              + _joint("joint_4", "revolute", "l3", "l4", "0 0 0.2", "0 1 0"))
    totals = _totals(run, tmp_path, links + joints)
    assert totals["dof"] == {"total": 4, "wheels": 0, "arm": 4, "chassis": 0}


def test_a_virtual_planar_base_above_the_robot_is_neither_caster_nor_suspension(run, tmp_path):
    wheels = "".join(
        _link(f"{side}_wheel", 0.1)
        + _joint(f"{side}_wheel_joint", "continuous", "base_link", f"{side}_wheel",
                 f"0 {y} 0.1", "0 1 0") for side, y in (("left", 0.2), ("right", -0.2)))
    virtual = (_link("odom") + _link("yaw_link") + _link("base_link")
               + _joint("base_x", "prismatic", "odom", "yaw_link", "0 0 0", "1 0 0")
               + _joint("base_theta", "continuous", "yaw_link", "base_link", "0 0 0", "0 0 1"))
    totals = _totals(run, tmp_path, virtual + wheels)
    assert totals["drive"]["left"] == ["left_wheel_joint"]
    assert totals["drive"]["track_m"] == pytest.approx(0.4)
    assert totals["dof"]["chassis"] == 0


def test_a_ball_caster_on_the_centre_line_is_no_drive_wheel(run, tmp_path):
    wheels = "".join(
        _link(f"{side}_wheel", 0.1)
        + _joint(f"{side}_wheel_joint", "continuous", "base_link", f"{side}_wheel",
                 f"0 {y} 0.1", "0 1 0") for side, y in (("left", 0.2), ("right", -0.2)))
    ball = ('<link name="ball"><collision><geometry><sphere radius="0.05"/></geometry>'
            '</collision></link>'
            + _joint("ball_joint", "continuous", "base_link", "ball", "-0.3 0 0.05", "0 1 0"))
    totals = _totals(run, tmp_path, _link("base_link") + wheels + ball)
    assert totals["drive"]["right"] == ["right_wheel_joint"]
    assert totals["drive"]["wheel_radius_m"] == pytest.approx(0.1)
    assert totals["dof"] == {"total": 3, "wheels": 2, "arm": 0, "chassis": 1}
