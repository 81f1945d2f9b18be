"""SB607: a controller claims an interface the URDF's <ros2_control> does not export."""

from __future__ import annotations

import re

from tests.check.helpers import findings
from tests.conftest import REPO, SIM_URDF

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()
EXAMPLE_14 = REPO / "tests" / "realworld" / "ws" / "src" / "example_14"


def _check(run, tmp_path, yaml_text: str, urdf_text: str | None = None,
           *urdf_args: str) -> tuple[int, list[dict[str, object]]]:
    path = tmp_path / "controllers.yaml"
    path.write_text(yaml_text)
    urdf = SIM_URDF
    if urdf_text is not None:
        urdf = tmp_path / "robot.urdf"
        urdf.write_text(urdf_text)
    result = run("check", "controllers", path, "--urdf", urdf, *urdf_args, "--format", "json",
                 "--isolated")
    return result.exit_code, findings(result.stdout)


def _without_state(interface: str) -> str:
    """The bundled robot, its joints exporting no ``interface`` state."""
    text = SIM_URDF.read_text()
    cut = text.replace(f'      <state_interface name="{interface}"/>\n', "")
    assert cut != text
    return cut


def test_the_bundled_controllers_claim_what_the_bundled_robots_export(run, tmp_path):
    assert _check(run, tmp_path, BUNDLED) == (0, [])


def test_a_trajectory_controller_commanding_velocity_of_position_joints(run, tmp_path):
    text = BUNDLED.replace("    command_interfaces:\n      - position\n",
                           "    command_interfaces:\n      - velocity\n")
    code, found = _check(run, tmp_path, text)
    assert code == 1 and [f["code"] for f in found] == ["SB607"]  # one for the four joints
    message = str(found[0]["message"])
    assert "command interface 'velocity'" in message and "'arm_link3_to_link4'" in message
    assert "(command interfaces: position)" in message
    line = text.splitlines()[int(found[0]["line"]) - 1]  # placed at the claim
    assert line.strip() == "- velocity"
    assert "arm_tool_joint" not in message  # fixed: SB606's, not this rule's


def test_diff_drive_reads_wheel_positions_unless_told_velocities(run, tmp_path):
    # by default (position_feedback true) diff_drive_controller claims each wheel's position
    code, found = _check(run, tmp_path, BUNDLED, _without_state("position"))
    assert code == 1 and {f["code"] for f in found} == {"SB607"}
    assert len(found) == 4 and all("state interface 'position'" in str(f["message"])
                                   for f in found)  # the four wheels (the arm's: JTC's claim)
    told = BUNDLED.replace("    open_loop: false\n",
                           "    open_loop: false\n    position_feedback: false\n")
    code, found = _check(run, tmp_path, told, _without_state("position"))
    wheels = [f for f in found if "wheel" in str(f["message"])]
    assert wheels == []
    code, found = _check(run, tmp_path, told, _without_state("velocity"))
    wheels = [str(f["message"]) for f in found if str(f["message"]).startswith("diff_controller")]
    assert len(wheels) == 4 and all("state interface 'velocity'" in m for m in wheels)
    assert sum("'front_left_wheel_joint'" in m for m in wheels) == 1


def test_a_joint_in_no_ros2_control_block(run, tmp_path):
    urdf = SIM_URDF.read_text()
    block = re.search(r'    <joint name="arm_link3_to_link4">.*?</joint>\n', urdf, re.DOTALL)
    assert block is not None
    code, found = _check(run, tmp_path, BUNDLED, urdf.replace(block[0], ""))
    assert code == 1 and [f["code"] for f in found] == ["SB607"]
    assert "joint 'arm_link3_to_link4' is in no <ros2_control>" in str(found[0]["message"])


def test_a_robot_without_ros2_control_is_not_judged(run, tmp_path):
    urdf = re.sub(r"<ros2_control .*?</ros2_control>", "", SIM_URDF.read_text(),
                  flags=re.DOTALL)
    assert "<ros2_control" not in urdf
    assert _check(run, tmp_path, BUNDLED, urdf) == (0, [])


def test_forward_and_group_controllers_claim_their_interface(run, tmp_path):
    declared = BUNDLED.replace(
        "    joint_state_broadcaster:\n",
        "    forward:\n      type: forward_command_controller/ForwardCommandController\n"
        "    group:\n      type: velocity_controllers/JointGroupVelocityController\n"
        "    joint_state_broadcaster:\n")
    text = declared + ("\nforward:\n  ros__parameters:\n    joints: [arm_base_to_link1]\n"
                       "    interface_name: effort\n"
                       "\ngroup:\n  ros__parameters:\n    joints: [front_left_wheel_joint, "
                       "arm_link1_to_link2]\n")
    code, found = _check(run, tmp_path, text)
    messages = sorted(str(f["message"]) for f in found)
    assert code == 1 and len(messages) == 2, messages
    assert messages[0].startswith("forward claims the command interface 'effort' of joint "
                                  "'arm_base_to_link1'")
    assert messages[1].startswith("group claims the command interface 'velocity' of joint "
                                  "'arm_link1_to_link2'")  # the wheel exports velocity


def test_an_actuator_and_a_sensor_export_one_joints_interfaces_together(run, tmp_path):
    # ros2_control_demos example 14: joint1's velocity command is in an actuator component,
    # its position state in a sensor component; a trajectory controller may claim both
    urdf = (EXAMPLE_14 / "description" / "urdf" / "rrbot_modular_actuators_without_feedback_"
            "sensors_for_position_feedback.urdf.xacro")
    package = f"ros2_control_demo_example_14={EXAMPLE_14}"
    yaml_text = ("controller_manager:\n  ros__parameters:\n    trajectory:\n      type: "
                 "joint_trajectory_controller/JointTrajectoryController\n"
                 "trajectory:\n  ros__parameters:\n    joints: [joint1, joint2]\n"
                 "    command_interfaces: [velocity]\n    state_interfaces: [position]\n")
    path = tmp_path / "controllers.yaml"
    path.write_text(yaml_text)
    args = ("--urdf", urdf, "prefix:=", "slowdown:=50.0", "--package", package,
            "--format", "json", "--isolated")
    result = run("check", "controllers", path, *args)
    assert result.exit_code == 0 and findings(result.stdout) == [], result.stdout
    path.write_text(yaml_text.replace("state_interfaces: [position]",
                                      "state_interfaces: [position, velocity]"))
    result = run("check", "controllers", path, *args)
    found = findings(result.stdout)
    assert [f["code"] for f in found] == ["SB607"], result.stdout
    assert "state interface 'velocity' of joints 'joint1', 'joint2'" in str(found[0]["message"])
    assert "(state interfaces: position)" in str(found[0]["message"])


def test_gazebos_pid_interfaces_are_exported_under_the_plain_names(run, tmp_path):
    """gazebo_ros2_control_demos' vertical cart: <command_interface name="position_pid"/>,
    which GazeboSystem exports as 'position' (gazebo_system.cpp), and a position controller
    claiming 'position'; SB607 refused the demo, and SB505 called the name a misspelling."""
    urdf = SIM_URDF.read_text()
    arm = re.search(r'    <joint name="arm_base_to_link1">.*?</joint>\n', urdf, re.DOTALL)
    assert arm is not None
    pid = arm[0].replace('<command_interface name="position">',
                         '<command_interface name="position_pid">')
    gazebo = urdf.replace(arm[0], pid)
    assert "gazebo_ros2_control/GazeboSystem" in gazebo
    assert _check(run, tmp_path, BUNDLED, gazebo) == (0, [])
    path = tmp_path / "robot.urdf"
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB505")
    assert findings(result.stdout) == []
    # the mock exports the name as written: the trajectory controller lacks 'position'
    real = gazebo.replace("gazebo_ros2_control/GazeboSystem", "mock_components/GenericSystem")
    code, found = _check(run, tmp_path, BUNDLED, real)
    assert code == 1 and "(command interfaces: position_pid)" in str(found[0]["message"])
    # a controller claiming the loop's own name is refused, told what to claim
    claiming = BUNDLED.replace("    command_interfaces:\n      - position\n",
                               "    command_interfaces:\n      - position_pid\n")
    code, found = _check(run, tmp_path, claiming, gazebo)
    (claim,) = [f for f in found if f["code"] == "SB607"]
    assert code == 1 and claim["fix"] == ("claim 'position': gazebo_ros2_control exports "
                                          "its position_pid loop under that name")
    # and JointTrajectoryController's own validation refuses the name (SB608)
    assert any(f["code"] == "SB608" and "'position_pid'" in str(f["message"]) for f in found)


def test_a_null_interface_name_claims_nothing(run, tmp_path):
    """interface_name: [position, ~]: a YAML null is no interface '~'."""
    declared = BUNDLED.replace(
        "    joint_state_broadcaster:\n",
        "    fwd:\n      type: forward_command_controller/ForwardCommandController\n"
        "    joint_state_broadcaster:\n")
    text = declared + ("\nfwd:\n  ros__parameters:\n    joints: [arm_base_to_link1]\n"
                       "    interface_name: [position, ~]\n")
    code, found = _check(run, tmp_path, text)
    assert not [f for f in found if f["code"] == "SB607"]
    # a list where the controller declares one string: refused at configure, as SB608 says
    assert [f["code"] for f in found] == ["SB608"] and "declares a string" in found[0]["message"]


def test_an_open_loop_diff_drive_claims_wheel_states_on_humble_only(run, tmp_path):
    """ros2_controllers#1731: from Jazzy on, open_loop: true claims no state interface."""
    without = SIM_URDF.read_text()
    for interface in ("position", "velocity"):
        without = without.replace(f'      <state_interface name="{interface}"/>\n', "")
    # the arm's trajectory controller would claim the arm's states: only the wheels' part
    wheels_only = BUNDLED[:BUNDLED.index("arm_controller:\n  ros__parameters")]
    code, found = _check(run, tmp_path, wheels_only.replace("open_loop: false",
                                                            "open_loop: true"), without)
    # (arm_controller, declared and now without parameters, is a warning of its own)
    found = [f for f in found if f["code"] == "SB607"]
    assert code == 0 and len(found) == 4
    assert all(f["code"] == "SB607" and f["severity"] == "warning"
               and "Humble's diff_drive_controller still claims" in str(f["message"])
               for f in found)
    code, found = _check(run, tmp_path, wheels_only, without)  # closed loop: every release
    assert code == 1 and {f["severity"] for f in found if f["code"] == "SB607"} == {"error"}


def test_a_driver_that_may_export_unlisted_interfaces_gets_a_warning(run, tmp_path):
    """ros2_canopen's canopen_tests: Cia402System exports position, velocity and effort of
    every joint its URDF lists, with no interface written there; SB607 called its
    maintained test configurations broken. A driver's code, not the URDF, says what it
    exports: a warning that names the plugin. The mock exports what is listed: an error."""
    urdf = SIM_URDF.read_text()
    arm = re.search(r'    <joint name="arm_base_to_link1">.*?</joint>\n', urdf, re.DOTALL)
    assert arm is not None
    bare = urdf.replace(arm[0], '    <joint name="arm_base_to_link1"/>\n')
    plugin = re.search(r"<plugin>([^<]+)</plugin>", bare)
    assert plugin is not None
    driver = bare.replace(plugin[0], "<plugin>canopen_ros2_control/Cia402System</plugin>")
    code, found = _check(run, tmp_path, BUNDLED, driver)
    claims = [f for f in found if f["code"] == "SB607"]
    assert code == 0 and claims and {f["severity"] for f in claims} == {"warning"}
    assert all("unless the hardware plugin 'canopen_ros2_control/Cia402System' exports it"
               in str(f["message"]) for f in claims)
    mock = bare.replace(plugin[0], "<plugin>mock_components/GenericSystem</plugin>")
    code, found = _check(run, tmp_path, BUNDLED, mock)
    assert code == 1 and {f["severity"] for f in found if f["code"] == "SB607"} == {"error"}
