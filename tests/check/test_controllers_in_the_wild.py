"""check controllers on the shapes real controller files take, each a false error before.

- ros2_control_demos' example 15: one file for two controller managers, the same controller
  in ``/rrbot_1/`` and ``/rrbot_2/``, its type in ``/**/``. rcl gives each namespace its own
  section merged with ``/**/``: the rrbot_2 section is no part of rrbot_1.
- Clearpath's ``control.yaml``: ``NAME.type:`` in the controller manager's section, the same
  parameter as ``NAME: {type:}`` once rcl flattens it.
- PAL's gripper controllers: ``${EE_SIDE_PREFIX}`` templates that launch_pal fills in.
- A number a launch file fills in (``$(var wheel_separation)``).
- igus' iRC_ROS: ``<prefix>joint_1`` placeholders that nav2_common's ReplaceString rewrites.
- A base with passive ball casters on continuous joints: diff_drive_controller's radius and
  track are those of the wheels it names, not an average with the casters.

Files in controllers_in_the_wild/; each wrong value is still found.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import REPO, run_servicebot

HERE = REPO / "tests" / "check" / "controllers_in_the_wild"


def _check(yaml_name: str, urdf_name: str, tmp_path=None, **changes: str):
    """Findings of ``check controllers`` on the files, with ``changes`` made to the YAML."""
    yaml_file = HERE / yaml_name
    if changes and tmp_path is not None:
        text = yaml_file.read_text()
        for old, new in changes.values():
            text = text.replace(old, new)
        yaml_file = tmp_path / yaml_name
        yaml_file.write_text(text)
    result = run_servicebot("check", "controllers", yaml_file, "--urdf", HERE / urdf_name,
                            "--format", "json")
    assert result.returncode in (0, 1), result.stderr
    return [(f["code"], f["message"]) for f in findings(result.stdout)]


@pytest.mark.parametrize(("yaml_name", "urdf_name"), [
    ("two_robots.yaml", "robot1.urdf"), ("lost_type.yaml", "robot1.urdf"),
    ("dotted.yaml", "arm.urdf"), ("gripper_controller.yaml", "gripper.urdf"),
    ("dd_substituted.yaml", "corner_casters.urdf"), ("dd.yaml", "corner_casters.urdf"),
    ("split_namespaces.yaml", "corner_casters.urdf"),
    ("replace_string.yaml", "arm.urdf"),
])
def test_real_shapes_pass(yaml_name, urdf_name):
    assert _check(yaml_name, urdf_name) == []


def test_a_namespace_that_fits_no_robot_is_still_checked(tmp_path):
    found = _check("two_robots.yaml", "robot1.urdf", tmp_path,
                   a=("[rrbot_1_joint1]", "[rrbot_3_joint1]"))
    assert [code for code, _ in found] == ["SB602", "SB602"]  # both sections, both wrong


def test_a_wrong_wheel_among_casters_is_still_found(tmp_path):
    found = _check("dd.yaml", "corner_casters.urdf", tmp_path, a=("wheel_radius: 0.1",
                                                                 "wheel_radius: 0.12"))
    assert [code for code, _ in found] == ["SB603"]
    assert "the URDF's 0.1 m" in found[0][1]


def test_what_diff_drive_controller_refuses_is_found(tmp_path):
    """An empty wheel list (its validator is not_empty), a radius of 1e400 hidden by a
    multiplier of nan, and parallel_gripper_controller's plugin, whose namespace
    (parallel_gripper_action_controller) is not its package's name, all passed."""
    found = _check("dd.yaml", "corner_casters.urdf", tmp_path,
                   a=("[left_wheel_joint]", "[]"),
                   b=("wheel_radius: 0.1", "wheel_radius: 1e400\n    "
                                           "left_wheel_radius_multiplier: nan"))
    codes = [code for code, _ in found]
    assert codes.count("SB601") == 1 and codes.count("SB603") == 1, found
    gripper = tmp_path / "gripper.yaml"
    gripper.write_text("controller_manager:\n  ros__parameters:\n    gripper_controller:\n"
                       "      type: parallel_gripper_action_controller/GripperActionController\n"
                       "gripper_controller:\n  ros__parameters:\n    joint: no_such_joint\n")
    result = run_servicebot("check", "controllers", gripper, "--urdf", HERE / "arm.urdf",
                            "--format", "json")
    assert [f["code"] for f in findings(result.stdout)] == ["SB602"]


def test_a_wrong_number_given_for_every_namespace_is_still_found(tmp_path):
    found = _check("split_namespaces.yaml", "corner_casters.urdf", tmp_path,
                   a=("wheel_separation: 0.4", "wheel_separation: 0.5"))
    assert [code for code, _ in found] == ["SB604"]


def test_a_joint_without_a_placeholder_is_still_checked(tmp_path):
    found = _check("replace_string.yaml", "arm.urdf", tmp_path,
                   a=("      - <prefix>joint_1\n", "      - <prefix>joint_1\n      - joint_9\n"))
    assert [code for code, _ in found] == ["SB602"] and "'joint_9'" in found[0][1]


@pytest.mark.parametrize("prefixed", ["<prefix>joint_2", "$(var tf_prefix)joint_2"])
def test_a_prefixed_joint_no_urdf_joint_ends_like_is_still_found(tmp_path, prefixed):
    """UR's '$(var tf_prefix)elbo_joint' passed: whatever the prefix, no joint ends so."""
    found = _check("replace_string.yaml", "arm.urdf", tmp_path,
                   a=("      - <prefix>joint_1\n", f"      - {prefixed}\n"))
    assert [code for code, _ in found] == ["SB602"]
    assert "ends in 'joint_2'" in found[0][1] and "did you mean" in found[0][1]
