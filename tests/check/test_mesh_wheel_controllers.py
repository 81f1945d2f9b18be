"""check controllers on a base whose wheels are meshes (igus ReBeL's mobile platform).

The URDF gives no wheel radius, so SB603 and SB604 were both skipped, silently: a
wheel_separation of 0.47285 m on wheels 0.5 m apart passed. The joints the controller names
place its wheels, which is all the separation needs; the radius stays unchecked.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import check_controllers, tetrahedron_stl

INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
            'ixz="0" iyz="0"/></inertial>')


def _wheel(side: str, y_m: float) -> str:
    return (f'<link name="wheel_{side}">{INERTIAL}<visual><geometry><mesh filename="wheel.stl"/>'
            f'</geometry></visual></link><joint name="joint_wheel_{side}" type="continuous">'
            f'<parent link="base_link"/><child link="wheel_{side}"/><origin xyz="0 {y_m} 0.07"/>'
            '<axis xyz="0 1 0"/><limit effort="10" velocity="10"/></joint>')


def _controllers(separation_m: float) -> str:
    return ("controller_manager:\n  ros__parameters:\n    update_rate: 100\n    diff_cont:\n"
            "      type: diff_drive_controller/DiffDriveController\n"
            "diff_cont:\n  ros__parameters:\n    left_wheel_names: [joint_wheel_left]\n"
            "    right_wheel_names: [joint_wheel_right]\n"
            f"    wheel_separation: {separation_m}\n    wheel_radius: 7.0\n")


@pytest.mark.parametrize(("separation_m", "expected"), [
    (0.5, []), (0.3, [("SB604", "error")]), (0.47285, [("SB604", "warning")])])
def test_mesh_wheels_are_placed_by_the_joints_the_controller_names(run, tmp_path, separation_m,
                                                                   expected):
    (tmp_path / "wheel.stl").write_bytes(tetrahedron_stl(0.15))
    urdf = tmp_path / "base.urdf"
    urdf.write_text(f'<robot name="b"><link name="base_link">{INERTIAL}</link>'
                    f'{_wheel("left", 0.25)}{_wheel("right", -0.25)}</robot>')
    exit_code, found = check_controllers(run, tmp_path, _controllers(separation_m), urdf)
    assert [(f["code"], f["severity"]) for f in found] == expected  # wheel_radius 7 m: unchecked
    if expected:
        assert found[0]["message"].startswith(
            f"diff_cont: wheel_separation {separation_m:g} m disagrees with the URDF's 0.5 m")
    assert exit_code == (1 if ("SB604", "error") in expected else 0)
