"""check controllers --spawned: a controllers file shared by robots, checked per launch.

Kassow's kassow_kord_controllers.yaml configures the single arm's trajectory controller and
the dual arm's left and right ones; each launch spawns its own, and controller_manager loads
no other. Every controller was checked against every robot: the file failed against both
(14 and 7 SB602 errors) and no option could say which controllers a robot runs.
"""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

YAML = """controller_manager:
  ros__parameters:
    update_rate: 100
    arm_controller:
      type: joint_trajectory_controller/JointTrajectoryController
    left_controller:
      type: joint_trajectory_controller/JointTrajectoryController
arm_controller:
  ros__parameters:
    joints: [arm_joint_1]
    command_interfaces: [position]
    state_interfaces: [position]
left_controller:
  ros__parameters:
    joints: [left_joint_1]
    command_interfaces: [position]
    state_interfaces: [position]
"""


def _arm(prefix: str) -> str:
    return (f'<robot name="{prefix}arm"><link name="base"/><link name="l1"/><joint '
            f'name="{prefix}joint_1" type="revolute"><parent link="base"/><child link="l1"/>'
            '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            "</robot>")


@pytest.fixture
def files(tmp_path):
    (tmp_path / "controllers.yaml").write_text(YAML)
    (tmp_path / "single.urdf").write_text(_arm("arm_"))
    (tmp_path / "dual.urdf").write_text(_arm("left_"))
    return tmp_path


def _check(files, *args: str):
    return run_servicebot("check", "controllers", "controllers.yaml", "--isolated", *args,
                          cwd=files)


def test_every_controller_is_checked_against_the_robot_by_default(files):
    result = _check(files, "--urdf", "single.urdf")
    assert result.returncode == 1
    assert "left_controller.joints: joint 'left_joint_1' is not in single.urdf" in result.stdout


@pytest.mark.parametrize(("urdf", "spawned"), [("single.urdf", "arm_controller"),
                                               ("dual.urdf", "left_controller")])
def test_the_spawned_controllers_alone_are_checked_against_the_robot(files, urdf, spawned):
    result = _check(files, "--urdf", urdf, "--spawned", spawned)
    assert result.returncode == 0, result.stdout
    assert "0 errors" in result.stdout


def test_a_spawned_controller_is_still_checked(files):
    result = _check(files, "--urdf", "single.urdf", "--spawned", "arm_controller,left_controller")
    assert result.returncode == 1 and "left_joint_1" in result.stdout
    repeated = _check(files, "--urdf", "dual.urdf", "--spawned", "arm_controller",
                      "--spawned", "left_controller")
    assert repeated.returncode == 1 and "'arm_joint_1' is not in dual.urdf" in repeated.stdout


def test_a_name_the_file_does_not_give_is_one_line(files):
    result = _check(files, "--urdf", "dual.urdf", "--spawned", "lft_controller")
    assert_one_line_error(result, 2, "--spawned lft_controller: no such controller in the file "
                          "(it has: arm_controller, left_controller)")


@pytest.mark.parametrize("given", [",", "", " , "])
def test_an_empty_list_is_refused_not_read_as_every_controller(files, given):
    """--spawned "$LIST" with an empty LIST checked every controller, with no word of it."""
    result = _check(files, "--urdf", "dual.urdf", "--spawned", given)
    assert_one_line_error(result, 2, "give the names of the controllers the launch spawns")


def test_a_parameter_wildcard_is_no_controller(files):
    """A '/**:' section configures every node: it was listed among the controllers, and
    --spawned '**' was taken (checking nothing)."""
    (files / "controllers.yaml").write_text(YAML + "/**:\n  ros__parameters:\n"
                                            "    use_sim_time: true\n")
    result = _check(files, "--urdf", "dual.urdf", "--spawned", "**")
    assert_one_line_error(result, 2, "--spawned **: no such controller in the file (it has: "
                          "arm_controller, left_controller)")
