"""Controllers YAMLs laid out as real packages write them: namespaces and third-party types."""

from __future__ import annotations

import textwrap

from tests.check.helpers import findings
from tests.conftest import REPO, SIM_URDF

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()


def _check(run, tmp_path, text: str) -> list[dict[str, object]]:
    path = tmp_path / "controllers.yaml"
    path.write_text(text)
    result = run("check", "controllers", path, "--urdf", SIM_URDF, "--format", "json",
                 "--isolated")
    return findings(result.stdout)


def test_sections_under_a_namespace_are_checked(run, tmp_path):
    # irobot_create_control's control.yaml puts every node under "/**:" (any namespace)
    wrong_radius = BUNDLED.replace("wheel_radius: 0.07", "wheel_radius: 0.7")
    for namespace in ("/**", "robot1", "/robot1"):
        text = f"{namespace}:\n" + textwrap.indent(wrong_radius, "  ")
        found = [(f["code"], f["message"]) for f in _check(run, tmp_path, text)]
        assert [code for code, _ in found] == ["SB603"], (namespace, found)
        assert "wheel_radius 0.7 m" in found[0][1]


def _with_controller(name: str, controller_type: str, params: str) -> str:
    declared = BUNDLED.replace(
        "    joint_state_broadcaster:\n",
        f"    {name}:\n      type: {controller_type}\n\n    joint_state_broadcaster:\n")
    assert declared != BUNDLED
    return declared + f"\n{name}:\n  ros__parameters:\n{textwrap.indent(params, '    ')}"


def test_a_third_party_controllers_joint_is_not_taken_for_a_urdf_joint(run, tmp_path):
    # ros2_kortex's twist controller: "joint: tcp" prefixes the interfaces its hardware
    # exports (tcp/twist.linear.x ...); the URDF has no joint 'tcp'
    params = "joint: tcp\ninterface_names: [twist.linear.x, twist.angular.z]\n"
    text = _with_controller("twist_controller", "picknik_twist_controller/"
                            "PicknikTwistController", params)
    assert _check(run, tmp_path, text) == []
    # nodes keyed by their path are named by its last part: the type is still found
    by_path = text.replace("controller_manager:", "/robot1/controller_manager:").replace(
        "\ntwist_controller:", "\n/robot1/twist_controller:")
    assert by_path.count("/robot1/") == 2 and _check(run, tmp_path, by_path) == []


def test_a_ros2_controllers_joint_is_still_checked(run, tmp_path):
    text = _with_controller("gripper_controller", "parallel_gripper_controller/"
                            "GripperActionController", "joint: tcp\n")
    found = _check(run, tmp_path, text)
    assert [f["code"] for f in found] == ["SB602"] and "'tcp'" in str(found[0]["message"])
    # the type may also sit in the controller's own parameters (ros2_control since Jazzy)
    own = BUNDLED + "\ngripper:\n  ros__parameters:\n    type: gripper_controllers/" \
        "GripperActionController\n    joint: tcp\n"
    assert [f["code"] for f in _check(run, tmp_path, own)] == ["SB602"]


def test_wheels_the_urdf_does_not_describe_as_cylinders_are_not_an_error(run, tmp_path):
    # gz_ros2_control_demos' test_diff_drive.xacro.urdf: wheels are spheres of radius 0.3,
    # and diff_drive_controller_velocity.yaml says wheel_radius: 0.3; Gazebo drives it
    urdf = tmp_path / "spheres.urdf"
    urdf.write_text(SIM_URDF.read_text().replace('<cylinder length="0.04" radius="0.07"/>',
                                                 '<sphere radius="0.07"/>'))
    path = tmp_path / "controllers.yaml"
    path.write_text(BUNDLED)
    result = run("check", "controllers", path, "--urdf", urdf, "--format", "json", "--isolated")
    assert result.exit_code == 0 and findings(result.stdout) == [], result.stdout
