"""SB608 for controller_manager's own parameters and for a controller declared without a type.

controller_manager declares update_rate an integer (above 0 from Jazzy on): '100' quoted,
100.0 or 'fast' stop the node at start; a controller declared as 'name: {}', typed nowhere,
cannot be loaded ("The 'type' param was not defined"). check passed each of them.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import check_controllers

_BASE = ("controller_manager:\n  ros__parameters:\n    update_rate: {rate}\n"
         "    joint_state_broadcaster:\n      type: joint_state_broadcaster/JointStateBroadcaster\n"
         "{more}")


def _sb608(run, tmp_path, rate: str = "100", more: str = ""):
    _, found = check_controllers(run, tmp_path, _BASE.format(rate=rate, more=more))
    return [(f["severity"], f["message"], f["fix"]) for f in found if f["code"] == "SB608"]


def test_an_integer_rate_and_typed_controllers_pass(run, tmp_path):
    assert _sb608(run, tmp_path, more="    hardware_components_initial_state:\n"
                  "      unconfigured: [arm]\n") == []


@pytest.mark.parametrize(("rate", "read", "fix"), [
    ('"100"', "'100' as a string", "update_rate: 100"),
    ("100.0", "'100.0' as a double", "update_rate: 100"),
    ("fast", "'fast' as a string", "update_rate: 100"),
    ("250.4", "'250.4' as a double", "update_rate: 250"),
    # no integer near: the fix was computed with float() and round(), exit 3
    (".inf", "'.inf' as a double", "update_rate: 100"),
    (".NaN", "'.NaN' as a double", "update_rate: 100"),
    ("1e400", "'1e400' as a string", "update_rate: 100"),  # strtod's ERANGE: rcl keeps text
    # beyond 64 bits strtoll fails and rcl reads a double: it passed
    ("99999999999999999999999", "'99999999999999999999999' as a double", "update_rate: 100"),
    ("[100, 200]", "a list as an array", "update_rate: 100"),
])
def test_a_rate_that_is_no_integer_stops_the_node(run, tmp_path, rate, read, fix):
    ((severity, message, given_fix),) = _sb608(run, tmp_path, rate)
    assert severity == "error" and f"controller_manager.update_rate: rcl reads {read}" in message
    assert given_fix == fix


def test_the_largest_integer_is_one(run, tmp_path):
    assert _sb608(run, tmp_path, str(2 ** 63 - 1)) == []
    assert _sb608(run, tmp_path, "0x10") == []


def test_a_rate_of_zero_or_less(run, tmp_path):
    ((_, message, _),) = _sb608(run, tmp_path, "-5")
    assert "from Jazzy on the controller manager wants a rate above 0" in message


def test_a_controller_declared_without_a_type(run, tmp_path):
    ((severity, message, fix),) = _sb608(run, tmp_path, more="    velocity_controller: {}\n")
    assert severity == "error"
    assert "declares 'velocity_controller' without a type" in message
    assert fix == "write velocity_controller: {type: package/ControllerClass}"


def test_a_type_in_the_controllers_own_section_is_its_type(run, tmp_path):
    more = ("    velocity_controller: {}\nvelocity_controller:\n  ros__parameters:\n"
            "    type: velocity_controllers/JointGroupVelocityController\n"
            "    joints: [left_wheel_joint]\n")
    assert [m for _, m, _ in _sb608(run, tmp_path, more=more) if "without a type" in m] == []


@pytest.mark.parametrize(("name", "valid"), [("/ns/diff_controller", "diff_controller"),
                                           ("diff-controller", "diff_controller"),
                                           ("2nd_arm", "_2nd_arm")])
def test_a_controller_name_no_node_can_have(run, tmp_path, name, valid):
    """A controller's name is its node's: rclcpp refuses '/ns/diff_controller'. check said
    to rename its section to the name it already had."""
    text = (f"controller_manager:\n  ros__parameters:\n    update_rate: 100\n    '{name}':\n"
            "      type: joint_state_broadcaster/JointStateBroadcaster\n")
    found = _sb608(run, tmp_path, more="")  # the base file passes
    assert found == []
    _, issues = check_controllers(run, tmp_path, text)
    ((severity, message, fix),) = [(f["severity"], f["message"], f["fix"]) for f in issues]
    assert severity == "error" and f"controller_manager declares '{name}': a controller's " \
        "name is its node's" in message
    assert fix.startswith(f"declare it as '{valid}'")


@pytest.mark.parametrize(("name", "said", "valid"), [
    ("diff-controller", "must not contain characters other than alphanumerics", "diff_controller"),
    ("2wd_controller", "must not start with a number", "_2wd_controller"),
])
def test_a_section_named_no_node_can_have_makes_rcl_refuse_the_file(run, tmp_path, name, said,
                                                                    valid):
    """rcl validates the node name before ros__parameters and refuses the whole file; the
    fix named 'controller' (the last run of letters) or the same invalid name."""
    text = (f"controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
            f"{name}:\n  ros__parameters:\n"
            "    type: joint_state_broadcaster/JointStateBroadcaster\n")
    code, issues = check_controllers(run, tmp_path, text)
    ((line, message, fix),) = [(f["line"], f["message"], f["fix"]) for f in issues]
    assert code == 1 and line == 4 and f"'{name}' names no node rcl accepts" in message
    assert said in message and "rcl refuses the whole file" in message
    assert fix.startswith(f"name it '{valid}'")


def test_a_name_a_launch_file_fills_in_is_left_to_it(run, tmp_path):
    text = ("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
            "    $(var prefix)broadcaster:\n"
            "      type: joint_state_broadcaster/JointStateBroadcaster\n")
    _, issues = check_controllers(run, tmp_path, text)
    assert [f for f in issues if "node's" in f["message"]] == []
