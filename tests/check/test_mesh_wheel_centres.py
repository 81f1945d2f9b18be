"""Wheels drawn as meshes roll where their meshes are, on their meshes' radius.

tortoisebot's wheels are STL meshes (in millimetres, scale 0.001) that sit 0.014 m outward
of their joints. The wheels' centres were taken at the joints: SB516 said its plugin's
wheel_separation (right) should be the joints' distance, inspect showed that track, and
simulate turned the robot 21 % faster than Gazebo. The radius was the plugin's own, so a
wrong wheel_diameter passed unseen.
"""

from __future__ import annotations

import json

import pytest

from tests.check.helpers import check_controllers, findings, wheel_stl

INERTIAL = ('<inertial><mass value="0.2"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" '
            'ixz="0" iyz="0"/></inertial>')
JOINTS_Y_M = 0.07  # the wheels' centres are 0.015 m further out: 0.17 m apart
RADIUS_M = 0.0325


def _wheel(side: str, sign: int) -> str:
    return (f'<link name="wheel_{side}">{INERTIAL}<collision><geometry><mesh '
            f'filename="wheel_{side}.stl" scale="0.001 0.001 0.001"/></geometry></collision>'
            f'</link><joint name="{side}_wheel_joint" type="continuous"><parent '
            f'link="base_link"/><child link="wheel_{side}"/><origin xyz="0 {sign * JOINTS_Y_M} '
            f'{RADIUS_M}"/><axis xyz="0 1 0"/><limit effort="1" velocity="10"/></joint>')


def _robot(tmp_path, separation_m: float = 0.17, diameter_m: float = 0.065):
    for side, sign in (("left", 1), ("right", -1)):  # millimetres, as exported
        (tmp_path / f"wheel_{side}.stl").write_bytes(wheel_stl(32.5, 20, sign * 15))
    plugin = ('<gazebo><plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">'
              "<left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint"
              f"</right_joint><wheel_separation>{separation_m}</wheel_separation>"
              f"<wheel_diameter>{diameter_m}</wheel_diameter></plugin></gazebo>")
    path = tmp_path / "base.urdf"
    path.write_text('<robot name="base"><link name="base_link"><inertial><mass value="1"/>'
                    '<inertia ixx="0.002" iyy="0.004" izz="0.005" ixy="0" ixz="0" iyz="0"/>'
                    '</inertial><collision><origin xyz="0 0 0.06"/><geometry><box size="0.2 '
                    f'0.12 0.05"/></geometry></collision></link>{_wheel("left", 1)}'
                    f'{_wheel("right", -1)}{plugin}</robot>')
    return path


def _sb516(run, path) -> list[tuple[str, str]]:
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB516")
    return [(f["severity"], f["message"]) for f in findings(result.stdout)]


def test_the_plugin_that_gives_the_meshes_track_passes(run, tmp_path):
    assert _sb516(run, _robot(tmp_path)) == []


def test_the_joints_distance_is_not_the_track(run, tmp_path):
    ((severity, message),) = _sb516(run, _robot(tmp_path, separation_m=0.14))
    assert severity == "error" and "the URDF's wheels are 0.17 m apart" in message


def test_a_diameter_that_is_not_the_meshes_is_found(run, tmp_path):
    ((severity, message),) = _sb516(run, _robot(tmp_path, diameter_m=0.08))
    assert severity == "error" and "the URDF's wheel diameter is 0.065 m" in message


def test_inspect_shows_the_meshes_track_and_radius(run, tmp_path):
    result = run("inspect", _robot(tmp_path, diameter_m=0.08), "--section", "totals",
                 "--format", "json")
    drive = json.loads(result.stdout)["totals"]["drive"]
    assert drive["track_m"] == pytest.approx(0.17, abs=1e-6)
    assert drive["wheel_radius_m"] == pytest.approx(RADIUS_M, abs=1e-6)


def test_simulate_turns_the_robot_as_gazebo_does(run, tmp_path):
    scenario = tmp_path / "turn.yaml"
    scenario.write_text("duration_s: 2\ncmd_vel:\n  - {duration_s: 2, linear_m_s: 0, "
                        "angular_rad_s: 0.5}\n")
    result = run("simulate", _robot(tmp_path), "--headless", "-s", scenario, "--format", "json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["final_pose"]["yaw_rad"] == pytest.approx(1.0, abs=1e-3)


@pytest.mark.parametrize(("radius_m", "expected"), [(0.0325, []), (0.05, ["SB603"])])
def test_a_controllers_wheel_radius_is_the_meshes(run, tmp_path, radius_m, expected):
    controllers = ("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
                   "    diff_cont:\n      type: diff_drive_controller/DiffDriveController\n"
                   "diff_cont:\n  ros__parameters:\n    left_wheel_names: [left_wheel_joint]\n"
                   "    right_wheel_names: [right_wheel_joint]\n"
                   f"    wheel_separation: 0.17\n    wheel_radius: {radius_m}\n")
    path = _robot(tmp_path)
    path.write_text(path.read_text().replace("diff_drive.so", "diff_drive_off.so"))
    _, found = check_controllers(run, tmp_path, controllers, path)
    assert [f["code"] for f in found] == expected


def test_a_wheel_mesh_that_is_a_pipe_or_a_device_is_no_wheel_mesh(run, tmp_path):
    """simulate read it to its end: a named pipe blocked for ever, /dev/zero until memory
    ran out. Neither is a mesh file: the wheels stand at their joints."""
    import os

    path = _robot(tmp_path)
    (tmp_path / "wheel_left.stl").unlink()
    os.mkfifo(tmp_path / "wheel_left.stl")
    (tmp_path / "wheel_right.stl").unlink()
    (tmp_path / "wheel_right.stl").symlink_to("/dev/zero")
    from tests.conftest import run_servicebot

    result = run_servicebot("simulate", path, "--headless", "--duration-s", "0.2", timeout=60)
    assert result.returncode in (0, 2) and "Traceback" not in result.stderr, result.stderr
    result = run_servicebot("inspect", path, "--section", "totals", timeout=60)
    assert result.returncode == 0 and "track (wheel separation)  0.14 m" in result.stdout


def test_drive_finds_wheel_meshes_in_the_packages_it_is_given(tmp_path):
    """drive took the environment's packages for mesh wheels, not --package: its wheel
    radius was the plugin's where simulate's was the mesh's."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.drive.motors import motor_map

    package = tmp_path / "elsewhere"  # found by --package only: no package.xml, another name
    package.mkdir()
    path = _robot(tmp_path, diameter_m=0.2)
    for side in ("left", "right"):
        (tmp_path / f"wheel_{side}.stl").rename(package / f"wheel_{side}.stl")
    path.write_text(path.read_text().replace('filename="wheel_', 'filename="package://'
                                             'meshes_pkg/wheel_'))
    source = RobotSource(path, str(path), packages=(("meshes_pkg", str(package)),))
    motors = motor_map(load(source), source.resolver())
    assert motors.geometry.wheel_radius_m == pytest.approx(RADIUS_M, abs=1e-6)
    assert motor_map(load(source)).geometry.wheel_radius_m == pytest.approx(0.1)


def test_a_wheel_mesh_in_millimetres_without_a_scale_is_refused_in_mesh_words(run, tmp_path):
    """A 650 mm wheel mesh without its scale is a wheel of 325 m: simulate refused it asking
    for "its cylinder's real radius", where the wheel is a mesh that needs a scale."""
    path = _robot(tmp_path)
    path.write_text(path.read_text().replace(' scale="0.001 0.001 0.001"', ''))
    for side, sign in (("left", 1), ("right", -1)):
        (tmp_path / f"wheel_{side}.stl").write_bytes(wheel_stl(325.0, 20, sign * 15))
    result = run("simulate", path, "--headless", "--duration-s", "0.5", "--out", tmp_path / "r")
    assert result.exit_code == 2
    assert "rolls on a radius of 325 m" in result.output
    assert 'scale="0.001 0.001 0.001" for millimetres' in result.output
    assert "cylinder's real radius" not in result.output
    assert not (tmp_path / "r").exists()
