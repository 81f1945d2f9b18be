"""SB608: values a controller's own parameter validation refuses at configure.

joint_trajectory_controller_parameters.yaml: joints and interfaces unique and not empty;
command interfaces of position, velocity, acceleration, effort; state interfaces of
position, velocity, acceleration, with velocity only beside position. An effort state was
SB607 with the advice to export it, after which JTC still refused it.
"""

from __future__ import annotations

import re

import pytest

from tests.check.helpers import check_controllers
from tests.conftest import REPO

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()
STATES = "    state_interfaces:\n      - position\n      - velocity\n"
COMMANDS = "    command_interfaces:\n      - position\n"


@pytest.mark.parametrize(("before", "after", "says", "fix"), [
    (STATES, "    state_interfaces:\n      - velocity\n", "holds velocity without position",
     "state_interfaces: [position, velocity]"),
    (STATES, STATES + "      - effort\n", "holds 'effort', which is none of position,",
     "replace 'effort' with one of position, velocity, acceleration"),
    (COMMANDS, "    command_interfaces: []\n", "command_interfaces is empty",
     "name at least one interface"),
    (COMMANDS, COMMANDS + "      - position\n", "names 'position' twice",
     "name 'position' once"),
    ("      - arm_link3_to_link4\n", "      - arm_link3_to_link4\n      - arm_base_to_link1\n",
     "names 'arm_base_to_link1' twice", "name 'arm_base_to_link1' once"),
])
def test_a_trajectory_controller_list_it_refuses(run, tmp_path, before, after, says, fix):
    """Each with its own fix: every one said 'Write the value in the declared type'."""
    assert before in BUNDLED
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(before, after, 1))
    assert code == 1
    assert [f["code"] for f in found] == ["SB608"], found
    assert says in str(found[0]["message"])
    assert found[0]["fix"] == fix


def test_a_forward_command_controller_without_interface_name(run, tmp_path):
    text = BUNDLED.replace("    joint_state_broadcaster:\n",
                           "    fwd:\n      type: forward_command_controller/"
                           "ForwardCommandController\n    joint_state_broadcaster:\n")
    code, found = check_controllers(run, tmp_path, text + "\nfwd:\n  ros__parameters:\n"
                         "    joints: [arm_base_to_link1]\n")
    assert code == 1 and [f["code"] for f in found] == ["SB608"]
    assert "no interface_name" in str(found[0]["message"])
    code, found = check_controllers(run, tmp_path, text + "\nfwd:\n  ros__parameters:\n"
                         "    joints: [arm_base_to_link1]\n    interface_name: position\n")
    assert (code, found) == (0, [])


def test_a_node_written_twice_is_read_merged_its_last_values_winning(run, tmp_path):
    """rcl reads both diff_controller blocks as one node; its second wheel names win."""
    code, found = check_controllers(run, tmp_path, BUNDLED + "\ndiff_controller:\n"
                                    "  ros__parameters:\n    left_wheel_names: [wheel_left]\n")
    codes = [(f["code"], f["severity"]) for f in found]
    assert ("SB602", "error") in codes and code == 1
    assert "SB601" not in {c for c, _ in codes}  # a node twice is no mistake to rcl


def test_a_parameter_written_twice_is_a_warning(run, tmp_path):
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(
        "    wheel_radius: 0.07\n", "    wheel_radius: 0.07\n    wheel_radius: 0.07\n", 1))
    assert code == 0 and [(f["code"], f["severity"]) for f in found] == [("SB601", "warning")]
    assert "'wheel_radius' is written twice" in str(found[0]["message"])


WILD = REPO / "tests" / "check" / "controllers_in_the_wild"


@pytest.mark.parametrize("name", ["pid_encoder", "gpio_io"])
def test_pid_state_dofs_and_gpio_components_are_what_the_controllers_claim(run, tmp_path, name):
    """pid_controller reads its states from reference_and_state_dof_names (a sensor here),
    and a gpio component's interfaces are component/interface: no joint needed."""
    code, found = check_controllers(run, tmp_path, (WILD / f"{name}.yaml").read_text(),
                                    WILD / f"{name}.urdf")
    assert (code, found) == (0, [])


def test_a_forward_command_controller_split_over_two_sections_has_its_interface(run, tmp_path):
    """'fwd:' and '/fwd:' configure one node: interface_name in either is enough."""
    text = BUNDLED.replace("    joint_state_broadcaster:\n",
                           "    fwd:\n      type: forward_command_controller/"
                           "ForwardCommandController\n    joint_state_broadcaster:\n")
    code, found = check_controllers(run, tmp_path, text + "\nfwd:\n  ros__parameters:\n"
                                    "    joints: [arm_base_to_link1]\n/fwd:\n"
                                    "  ros__parameters:\n    interface_name: position\n")
    assert (code, found) == (0, [])


def test_a_type_only_humble_reads_is_a_warning(run, tmp_path):
    """JTC's state_publish_rate is gone from Jazzy: an undeclared override is never read."""
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(
        "state_publish_rate: 50.0", "state_publish_rate: 50"))
    assert code == 0 and [(f["code"], f["severity"]) for f in found] == [("SB608", "warning")]


def test_a_list_in_quotes_is_one_string_fixed_without_quotes(run, tmp_path):
    """left_wheel_names: "[wheel_left]" is a string to rcl: the fix was the nested
    [[wheel_left]], beside an SB602 for a joint called '[wheel_left]'."""
    text = re.sub(r"left_wheel_names: \[([^\]]*)\]", r"left_wheel_names: '[\1]'", BUNDLED,
                  count=1)
    assert text != BUNDLED
    code, found = check_controllers(run, tmp_path, text)
    (only,) = found
    assert code == 1 and only["code"] == "SB608"
    assert only["fix"].endswith("] (no quotes)") and "[[" not in only["fix"]


def test_a_joint_defined_twice_is_judged_by_its_first_definition(run, tmp_path):
    """The URDF's 'lift' is prismatic, then (a copy left behind) fixed: the controllers'
    joint table kept the last, and a controller of 'lift' was told it is fixed (SB606)."""
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="lift" type="prismatic"><parent link="a"/><child link="b"/>'
        '<axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
        '<joint name="lift" type="fixed"><parent link="b"/><child link="c"/></joint>'
        '<ros2_control name="s" type="system"><hardware><plugin>mock_components/GenericSystem'
        '</plugin></hardware><joint name="lift"><command_interface name="position"/>'
        '<state_interface name="position"/></joint></ros2_control></robot>')
    _, found = check_controllers(run, tmp_path, (
        "controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
        "    lift_controller:\n      type: position_controllers/JointGroupPositionController\n"
        "lift_controller:\n  ros__parameters:\n    joints: [lift]\n"), urdf)
    assert "SB606" not in {f["code"] for f in found}, found
