"""SB608: values a controller's own parameter validation refuses at configure.

joint_trajectory_controller_parameters.yaml: joints and interfaces unique and not empty;
command interfaces of position, velocity, acceleration, effort; state interfaces of
position, velocity, acceleration, with velocity only beside position. An effort state was
SB607 with the advice to export it, after which JTC still refused it.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import check_controllers
from tests.conftest import REPO

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()
STATES = "    state_interfaces:\n      - position\n      - velocity\n"
COMMANDS = "    command_interfaces:\n      - position\n"


@pytest.mark.parametrize(("before", "after", "says"), [
    (STATES, "    state_interfaces:\n      - velocity\n", "holds velocity without position"),
    (STATES, STATES + "      - effort\n", "holds 'effort', which is none of position,"),
    (COMMANDS, "    command_interfaces: []\n", "command_interfaces is empty"),
    (COMMANDS, COMMANDS + "      - position\n", "names 'position' twice"),
    ("      - arm_link3_to_link4\n", "      - arm_link3_to_link4\n      - arm_base_to_link1\n",
     "names 'arm_base_to_link1' twice"),
])
def test_a_trajectory_controller_list_it_refuses(run, tmp_path, before, after, says):
    assert before in BUNDLED
    code, found = check_controllers(run, tmp_path, BUNDLED.replace(before, after, 1))
    assert code == 1
    assert [f["code"] for f in found] == ["SB608"], found
    assert says in str(found[0]["message"])


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


def test_a_parameter_written_twice_keeps_its_last_value(run, tmp_path):
    """rcl keeps the second diff_controller section: its wheel names are checked."""
    code, found = check_controllers(run, tmp_path, BUNDLED + "\ndiff_controller:\n"
                                    "  ros__parameters:\n    left_wheel_names: [wheel_left]\n")
    codes = [(f["code"], f["severity"]) for f in found]
    assert ("SB601", "warning") in codes and ("SB602", "error") in codes and code == 1
