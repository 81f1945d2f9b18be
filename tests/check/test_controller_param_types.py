"""SB608: values rcl reads as another type than the controller declares, or lists it refuses.

rcl_yaml_param_parser's typing (parse.c): a quoted value is a string, y/n/on/off are
booleans, a list takes one type. diff_drive_controller declares wheel_separation a double,
the wheel names a string array; a value of another type fails at configure.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import check_controllers, findings
from tests.conftest import REPO

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()


def _sb608(run, tmp_path, text: str) -> tuple[int, list[dict[str, object]]]:
    code, found = check_controllers(run, tmp_path, text)
    return code, [f for f in found if f["code"] == "SB608"]


@pytest.mark.parametrize(("before", "after", "says", "fix"), [
    ("wheel_separation: 0.54", 'wheel_separation: "0.54"', "reads '0.54' as a string",
     "write 0.54 without quotes"),
    ("wheel_separation_multiplier: 1.0", "wheel_separation_multiplier: 1",
     "reads '1' as an integer", "write 1.0"),
    ('left_wheel_names: ["front_left_wheel_joint", "rear_left_wheel_joint"]',
     "left_wheel_names: front_left_wheel_joint", "as a string, and diff_drive",
     "left_wheel_names: [front_left_wheel_joint]"),
    ("open_loop: false", 'open_loop: "false"', "reads 'false' as a string",
     "write false without quotes"),
    ("pose_covariance_diagonal: [0.001, 0.001, 0.001, 0.001, 0.001, 0.01]",
     "pose_covariance_diagonal: [0, 0, 0, 0, 0, 0]", "its items as integers ('0')",
     "write 0.0"),
    ("pose_covariance_diagonal: [0.001, 0.001, 0.001, 0.001, 0.001, 0.01]",
     "pose_covariance_diagonal: [0.001, 0.001, 0, 0.001, 0.001, 0.01]",
     "reads '0' as an integer among doubles, and refuses the whole file", "write 0.0"),
    ("      - arm_link3_to_link4\n", "      - y\n", "reads 'y' as a boolean among strings",
     "quote it: 'y'"),
    ("      - arm_link3_to_link4\n", "      - .NaN\n", "reads '.NaN' as a double among strings",
     "quote it"),
    # strtoll stops at 8, no octal digit: rcl reads a double, the manager wants an integer
    ("update_rate: 100", "update_rate: 08", "reads '08' as a double", "update_rate: 8"),
    # strtod stops early (0x1.2.3) or overflows (1e400): rcl keeps the text, a string
    ("update_rate: 100", "update_rate: 0x1.2.3", "reads '0x1.2.3' as a string", "update_rate: 100"),
    ("wheel_separation: 0.54", "wheel_separation: 1e400", "reads '1e400' as a string", ""),
])
def test_a_value_of_another_type_is_refused_as_rcl_and_the_controller_would(
        run, tmp_path, before, after, says, fix):
    assert before in BUNDLED
    code, found = _sb608(run, tmp_path, BUNDLED.replace(before, after, 1))
    assert code == 1 and len(found) == 1, found
    assert says in str(found[0]["message"])
    assert str(found[0]["fix"]).startswith(fix)


@pytest.mark.parametrize(("before", "after"), [
    ("wheel_separation: 0.54", "wheel_separation: 5.4e-1"),
    ("wheel_separation: 0.54", "wheel_separation: $(var wheel_separation)"),  # launch fills it
    ("      - arm_link3_to_link4\n", "      - 'y'\n"),  # quoted: a joint named y (SB602)
    ("open_loop: false", "open_loop: off"),
    ("cmd_vel_timeout: 0.5", "cmd_vel_timeout: .inf"),
    ("state_publish_rate: 50.0", "state_publish_rate: 5e1"),
    # rcl's own spellings of nan and inf only: '.nAN' and '+.nan' are strings (parse.c)
    ("      - arm_link3_to_link4\n", "      - .nAN\n"),
    ("      - arm_link3_to_link4\n", "      - +.nan\n"),
    ("update_rate: 100", "update_rate: 0144"),  # octal, as C reads it: 100 (it raised)
    ("cmd_vel_timeout: 0.5", "cmd_vel_timeout: 08"),  # a double to rcl, not an integer
])
def test_values_rcl_reads_as_declared_pass(run, tmp_path, before, after):
    assert before in BUNDLED
    assert _sb608(run, tmp_path, BUNDLED.replace(before, after, 1))[1] == []


def test_the_bundled_controllers_pass(run, tmp_path):
    assert _sb608(run, tmp_path, BUNDLED) == (0, [])


def test_a_parameter_finding_is_said_once_whatever_the_robots(run, tmp_path):
    """SB608 holds whatever the robot: against the two bundled robots it was said twice."""
    path = tmp_path / "controllers.yaml"
    path.write_text(BUNDLED.replace("wheel_separation: 0.54", 'wheel_separation: "0.54"'))
    result = run("check", "controllers", path, "--format", "json", "--isolated")
    assert [f["code"] for f in findings(result.stdout)].count("SB608") == 1, result.stdout


@pytest.mark.parametrize("value", [".inf", "-.inf", ".nan", "0x1p3", "1e400", "0x1.2.3", "0x.",
                                   "1e-400"])
def test_a_number_as_c_writes_it_is_no_internal_error(run, tmp_path, value):
    """max_effort: .inf ended in an internal error (Python's float() refuses '.inf')."""
    text = BUNDLED + ("gripper_controller:\n  ros__parameters:\n    type: parallel_gripper_"
                      "action_controller/GripperActionController\n    joint: arm_link3_to_link4"
                      f"\n    max_effort: {value}\n")
    code, found = _sb608(run, tmp_path, text)
    assert code in (0, 1) and not any("gt_eq 0" in str(f["message"]) for f in found
                                      if value != "-.inf")
