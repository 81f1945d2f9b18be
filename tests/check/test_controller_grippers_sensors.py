"""Gripper action controllers and sensor broadcasters claim interfaces too (SB602, SB607, SB608).

robotiq_2f_85's controllers claim 'robotiq_85_left_knuckle_joint/effort' as the gripper's
max_effort_interface, which its <ros2_control> never exports; an imu_sensor_broadcaster named a
sensor the URDF calls otherwise; a gripper's ``joint: [finger_joint]`` and ``max_effort: -5``
are refused at configure: each passed. So did a controllers file of controller_manager alone
with a misspelt type, and a section named a letter off its controller.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
            'ixz="0" iyz="0"/></inertial>')
IMU_STATES = "".join(f'<state_interface name="{part}.{axis}"/>' for part, axes in (
    ("orientation", "xyzw"), ("angular_velocity", "xyz"), ("linear_acceleration", "xyz"))
    for axis in axes)
URDF = (f'<robot name="g"><link name="base">{INERTIAL}</link><link name="finger">{INERTIAL}'
        '</link><joint name="finger_joint" type="prismatic"><parent link="base"/>'
        '<child link="finger"/><axis xyz="1 0 0"/><limit lower="0" upper="0.04" effort="10" '
        'velocity="0.1"/></joint><ros2_control name="hw" type="system"><hardware>'
        '<plugin>mock_components/GenericSystem</plugin></hardware><joint name="finger_joint">'
        '<command_interface name="position"/><state_interface name="position"/>'
        f'<state_interface name="velocity"/></joint><sensor name="imu">{IMU_STATES}</sensor>'
        '</ros2_control></robot>')
MANAGER = """controller_manager:
  ros__parameters:
    update_rate: 100
    gripper_controller:
      type: parallel_gripper_action_controller/GripperActionController
    imu_broadcaster:
      type: imu_sensor_broadcaster/IMUSensorBroadcaster
"""
GOOD = MANAGER + """
gripper_controller:
  ros__parameters:
    joint: finger_joint
    max_effort: 5.0
imu_broadcaster:
  ros__parameters:
    sensor_name: imu
    frame_id: imu_link
"""


def _check(run, tmp_path, yaml_text: str) -> tuple[int, list[dict[str, object]]]:
    (tmp_path / "g.urdf").write_text(URDF)
    (tmp_path / "c.yaml").write_text(yaml_text)
    result = run("check", "controllers", tmp_path / "c.yaml", "--urdf", tmp_path / "g.urdf",
                 "--format", "json", "--isolated")
    return result.exit_code, findings(result.stdout)


def test_the_good_file_passes(run, tmp_path):
    assert _check(run, tmp_path, GOOD) == (0, [])


@pytest.mark.parametrize(("edit", "code", "words"), [
    (("max_effort: 5.0", "max_effort: 5.0\n    max_effort_interface: finger_joint/effort"),
     "SB607", "claims the command interface 'effort' of joint 'finger_joint'"),
    (("max_effort: 5.0", "max_effort: -5.0"), "SB608", "refuses a negative value"),
    (("joint: finger_joint", "joint: [finger_joint]"), "SB608", "declares a string"),
    (("sensor_name: imu", "sensor_name: imu_sensor"), "SB602",
     "'imu_sensor' is no <ros2_control> sensor"),
    (("gripper_controller:\n  ros__parameters", "gripper_controler:\n  ros__parameters"),
     "SB608", "section 'gripper_controler' configures no controller"),
])
def test_each_broken_variant_fails_with_its_reason(run, tmp_path, edit, code, words):
    text = GOOD.replace(*edit)
    assert text != GOOD
    exit_code, found = _check(run, tmp_path, text)
    assert exit_code == 1, found
    assert any(f["code"] == code and words in str(f["message"]) for f in found), found


def test_a_sensor_lacking_states_is_named_once(run, tmp_path):
    (tmp_path / "g.urdf").write_text(URDF.replace(IMU_STATES, '<state_interface name="x"/>'))
    (tmp_path / "c.yaml").write_text(GOOD)
    result = run("check", "controllers", tmp_path / "c.yaml", "--urdf", tmp_path / "g.urdf",
                 "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert found["code"] == "SB607" and "of sensor 'imu'" in str(found["message"])


def test_a_file_of_controller_manager_alone_is_checked(run, tmp_path):
    """A misspelt type there was 'no controller here ... nothing was checked' (info)."""
    typo = MANAGER.replace("IMUSensorBroadcaster", "IMUSensorBroadcastr")
    exit_code, found = _check(run, tmp_path, typo)
    errors = [f for f in found if f["severity"] == "error"]
    assert exit_code == 1 and [f["code"] for f in errors] == ["SB608"]
    assert "did you mean 'imu_sensor_broadcaster/IMUSensorBroadcaster'" in str(errors[0]["message"])
    exit_code, found = _check(run, tmp_path, MANAGER)  # its parameters may be another file's
    assert exit_code == 0 and {(f["code"], f["severity"]) for f in found} == {("SB608", "info")}


def test_a_section_without_what_its_controller_needs_is_a_warning(run, tmp_path):
    """A diff drive section holding only publish_rate: no wheel names, and the controller
    refuses to configure (not_empty)."""
    text = GOOD.replace("    sensor_name: imu\n", "")
    exit_code, found = _check(run, tmp_path, text)
    assert exit_code == 0 and [(f["code"], f["severity"]) for f in found] == [
        ("SB608", "warning")]
    assert found[0]["message"].startswith("imu_broadcaster gives no sensor_name")


def test_a_declared_controller_without_parameters_beside_others_is_a_warning(run, tmp_path):
    lone = GOOD[:GOOD.index("imu_broadcaster:\n  ros__parameters")]
    exit_code, found = _check(run, tmp_path, lone)
    assert exit_code == 0 and [(f["code"], f["severity"]) for f in found] == [
        ("SB608", "warning")]
    assert "refuses to configure without sensor_name and frame_id" in str(found[0]["message"])


@pytest.mark.parametrize("prefix", ["", "/**:\n  ", "twice"])
def test_a_misnamed_section_is_found_at_its_name(run, tmp_path, prefix):
    """Where the typo is: the section's key, not its first parameter (create3's 'dif:')."""
    text = GOOD.replace("gripper_controller:\n  ros__parameters",
                        "gripper_controler:\n  ros__parameters")
    if prefix == "twice":  # written again further down: rcl merges the two, as here
        text += "gripper_controler:\n  ros__parameters:\n    max_effort: 6.0\n"
    elif prefix:  # every node under the /** namespace, as irobot_create_control writes it
        text = prefix + text.rstrip("\n").replace("\n", "\n  ") + "\n"
    code, found = _check(run, tmp_path, text)
    [misnamed] = [f for f in found if "configures no controller" in f["message"]]
    line = next(n for n, written in enumerate(text.splitlines(), 1)
                if written.strip() == "gripper_controler:")
    assert misnamed["line"] == line
