"""What rcl makes of a controllers file as a whole: aliases, several documents, odd keys.

rcl_yaml_param_parser refuses an alias ('Will not support aliasing') and a key that is a
list or a mapping; it reads several documents as one file, which the spawner's
--param-file (yaml.safe_load) refuses.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import check_controllers
from tests.conftest import REPO

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()


def test_an_alias_is_refused_as_rcl_refuses_it(run, tmp_path):
    text = BUNDLED.replace("    wheel_separation: 0.54\n", "    wheel_separation: &track 0.54\n"
                           ).replace("    publish_rate: 50.0", "    publish_rate: *track")
    code, found = check_controllers(run, tmp_path, text)
    (alias,) = [f for f in found if f["code"] == "SB601"]
    assert code == 1 and alias["severity"] == "error"
    assert "an alias (*track): rcl refuses the whole file" in str(alias["message"])
    assert BUNDLED.splitlines()[int(alias["line"]) - 1].strip().startswith("publish_rate")


def test_several_documents_are_read_as_one_with_a_warning(run, tmp_path):
    head, tail = BUNDLED.split("arm_controller:\n  ros__parameters:", 1)
    code, found = check_controllers(run, tmp_path,
                                    head + "---\narm_controller:\n  ros__parameters:" + tail)
    assert code == 0
    assert [(f["code"], f["severity"]) for f in found] == [("SB601", "warning")]
    assert "2 YAML documents (---)" in str(found[0]["message"])
    code, found = check_controllers(run, tmp_path, head + "---\narm_controller:\n  ros__parameters:"
                         + tail.replace("arm_link3_to_link4", "arm_link3_to_link9"))
    assert code == 1 and "SB602" in {f["code"] for f in found}  # the second one is checked


def test_a_key_that_is_a_list_is_named_not_printed_as_a_parser_object(run, tmp_path):
    code, found = check_controllers(run, tmp_path, BUNDLED + "? [a, b]\n: ros__parameters:\n"
                         "    joints: [jointQ]\n")
    assert code == 1
    messages = [str(f["message"]) for f in found]
    assert any("a list or mapping used as a key" in m for m in messages)
    assert not any("ScalarNode" in m for m in messages)


def test_a_misspelled_ros_parameters_is_named(run, tmp_path):
    """rcl does not read 'ros_parameters' as the node's parameters: check said 'no controller
    here' (an info) and passed."""
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(
        "arm_controller:\n  ros__parameters:", "arm_controller:\n  ros_parameters:"))
    assert code == 1 and [f["code"] for f in found] == ["SB601"]
    assert "'ros_parameters' is not ros__parameters" in str(found[0]["message"])


def test_a_controller_type_a_letter_off_is_no_plugin(run, tmp_path):
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(
        "type: diff_drive_controller/DiffDriveController",
        "type: diff_drive_controller/DiffDriveControler"))
    assert code == 1 and [f["code"] for f in found] == ["SB608"]
    assert str(found[0]["message"]).endswith(
        "did you mean 'diff_drive_controller/DiffDriveController'?")
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(
        "type: diff_drive_controller/DiffDriveController", "type: my_robot/BaseController"))
    assert code == 0 and found == []  # a third party's controller is not judged


def test_an_alias_in_a_launch_pal_template_is_a_warning(run, tmp_path):
    """pal_hey5's controller file is a ${EE_SIDE_PREFIX} template that launch_pal loads and
    writes out again, its aliases spelled out, before rcl reads it."""
    text = BUNDLED.replace("    wheel_separation: 0.54\n", "    wheel_separation: &track 0.54\n"
                           ).replace("    publish_rate: 50.0", "    publish_rate: *track"
                                     ).replace("odom_frame_id: odom", "odom_frame_id: ${ODOM}")
    code, found = check_controllers(run, tmp_path, text)
    (alias,) = [f for f in found if f["code"] == "SB601"]
    assert alias["severity"] == "warning" and "launch_pal" in str(alias["message"])


def test_a_namespace_written_twice_is_one_node_not_a_mistake(run, tmp_path):
    """rcl reads both '/**' blocks (open_manipulator's configs write two)."""
    head, tail = BUNDLED.split("diff_controller:\n  ros__parameters:", 1)
    text = ("/**:\n" + "".join(f"  {line}\n" for line in head.splitlines())
            + "/**:\n  diff_controller:\n    ros__parameters:"
            + "".join(f"\n  {line}" if line else "\n" for line in tail.splitlines()))
    code, found = check_controllers(run, tmp_path, text)
    assert not [f for f in found if f["code"] == "SB601"], found


@pytest.mark.parametrize(("edit", "said"), [
    (lambda t: "use_sim_time: true\n" + t, "'use_sim_time: true' is at the top of the file"),
    (lambda t: t.replace("controller_manager:\n", "controller_manager:\n  use_sim_time: true\n",
                         1), "'use_sim_time: true' is under 'controller_manager' but outside"),
    (lambda t: t.replace("\narm_controller:\n", "\narm_controller:\n  type: joint_trajectory_"
                         "controller/JointTrajectoryController\n", 1),
     "'type: joint_trajectory_controller/JointTrajectoryController' is under 'arm_controller'"),
    (lambda t: t + "sensor_broadcaster:\n  ros__parameters:\n", "'sensor_broadcaster: "
     "ros__parameters:' holds no parameters"),
    (lambda t: t + "extra:\n  - a\n", "the list 'extra' is outside every node's"),
], ids=["top", "beside ros__parameters", "ROS 1 type", "empty parameters", "list"])
def test_a_value_outside_every_ros__parameters_is_refused_as_rcl_refuses_it(run, tmp_path,
                                                                              edit, said):
    """rcl_yaml_param_parser: 'Cannot have a value before ros__parameters at line N' (or
    'Sequences can only be values...'), the whole file refused: ros2_control_node stops."""
    text = edit(BUNDLED)
    code, found = check_controllers(run, tmp_path, text)
    (layout,) = [f for f in found if f["code"] == "SB601"]
    assert code == 1 and layout["severity"] == "error", found
    assert said in str(layout["message"]) and "rcl refuses the whole file" in str(
        layout["message"])
    assert f"at line {layout['line']}'" in str(layout["message"])


def test_nested_namespaces_and_wildcards_are_no_values_outside(run, tmp_path):
    text = ("/**:\n  ros__parameters:\n    use_sim_time: true\n"
            "robot1:\n  controller_manager:\n    ros__parameters:\n      update_rate: 50\n"
            "      diff_drive_controller:\n        type: diff_drive_controller/"
            "DiffDriveController\n  diff_drive_controller:\n    ros__parameters:\n"
            "      left_wheel_names: [front_left_wheel_joint]\n"
            "      right_wheel_names: [front_right_wheel_joint]\n")
    code, found = check_controllers(run, tmp_path, text)
    assert not [f for f in found if "rcl refuses" in str(f["message"])], found


def test_the_empty_mapping_that_ends_the_parameters_is_the_one_named(run, tmp_path):
    """x holds y: {}: y's end took the namespace x's end needed, so x's end left the
    parameters; the message named x, which is not empty."""
    code, found = check_controllers(run, tmp_path, BUNDLED + "extra:\n  ros__parameters:\n"
                                    "    x:\n      y: {}\n    z: 1\n")
    (layout,) = [f for f in found if f["code"] == "SB601"]
    assert code == 1 and str(layout["message"]).startswith("'y: {}', an empty mapping")
