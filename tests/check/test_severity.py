"""What is an error and what is a warning, on the layouts real description packages use."""

from __future__ import annotations

import pytest

from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.findings import Severity
from tests.check.helpers import findings, fixture
from tests.conftest import REPO, SIM_URDF

ARM = """<robot name="arm">
  <link name="base"/>
  <link name="arm"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
  {extra}
</robot>
"""
GZ_CONTROL = """<ros2_control name="sim" type="system">
    <hardware><plugin>{plugin}</plugin></hardware>
    <joint name="shoulder"><command_interface name="position"/></joint>
  </ros2_control>"""


def _severities(run, path, code: str) -> list[str]:
    result = run("check", path, "--format", "json", "--isolated")
    return [f["severity"] for f in findings(result.stdout) if f["code"] == code]


def test_every_error_rule_names_what_breaks(run):
    for rule in RULES.values():
        if rule.severity is Severity.ERROR:
            assert rule.breaks, rule.code
    explained = run("check", "--explain", "SB303").stdout
    assert "What breaks:" in explained and "MuJoCo" in explained


def test_a_kinematic_only_arm_without_masses_is_a_warning(run, tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra=""))
    assert _severities(run, path, "SB303") == ["warning"]
    assert run("check", path, "--isolated").exit_code == 0


@pytest.mark.parametrize("extra", [
    '<gazebo reference="arm"><mu1>0.5</mu1></gazebo>',
    GZ_CONTROL.format(plugin="gz_ros2_control/GazeboSimSystem"),
    GZ_CONTROL.format(plugin="ign_ros2_control/IgnitionSystem"),
    GZ_CONTROL.format(plugin="gazebo_ros2_control/GazeboSystem"),
])
def test_a_description_for_a_simulator_without_masses_is_an_error(run, tmp_path, extra):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra=extra))
    assert _severities(run, path, "SB303") == ["error"]
    assert run("check", path, "--isolated").exit_code == 1


def test_a_severity_set_in_the_settings_wins_over_the_context(run, tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra='<gazebo reference="arm"/>'))
    (tmp_path / "pyproject.toml").write_text('[tool.servicebot.check]\n'
                                             'severity = { SB303 = "info" }\n')
    result = run("check", path, "--format", "json", "--config", tmp_path / "pyproject.toml")
    assert [f["severity"] for f in findings(result.stdout) if f["code"] == "SB303"] == ["info"]


def test_an_actuator_that_commands_and_a_sensor_that_reports_share_a_joint(run, tmp_path):
    text = fixture("SB507").read_text()
    first = text.index('<command_interface name="position"></command_interface>')
    second = text.index('<command_interface name="position"></command_interface>', first + 1)
    end = len('<command_interface name="position"></command_interface>')
    state = text.index('<state_interface name="position"/>')
    # the first component only commands, the second only reports
    layout = (text[:state] + text[state + len('<state_interface name="position"/>'):second]
              + text[second + end:])
    assert layout.count("command_interface") == 2 and layout.count("state_interface") == 1
    path = tmp_path / "modular.urdf"
    path.write_text(layout)
    assert _severities(run, path, "SB507") == []
    assert _severities(run, fixture("SB507"), "SB507") == ["error"]


def test_lower_above_upper_says_what_pybullet_makes_of_it(run):
    result = run("check", fixture("SB203"), "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB203"]
    assert found["severity"] == "warning" and "pybullet reads that as no limit" in found["message"]


def test_chained_controllers_and_launch_substitutions_are_not_unknown_joints(run, tmp_path):
    yaml_text = (REPO / "robots" / "controllers.yaml").read_text() + """
pid_controller_left_wheel_joint:
  ros__parameters:
    dof_names: ["front_left_wheel_joint"]

chained_controller:
  ros__parameters:
    joints: ["pid_controller_left_wheel_joint/front_left_wheel_joint", "$(var prefix)1"]

broken_controller:
  ros__parameters:
    joints: ["no_such_controller/front_left_wheel_joint"]
"""
    path = tmp_path / "controllers.yaml"
    path.write_text(yaml_text)
    result = run("check", "controllers", path, "--urdf", SIM_URDF, "--format", "json",
                 "--isolated")
    unknown = [f["message"] for f in findings(result.stdout) if f["code"] == "SB602"]
    assert len(unknown) == 1 and "no_such_controller/front_left_wheel_joint" in unknown[0]


def test_a_wheel_without_a_velocity_limit_is_what_drive_refuses(run):
    from servicebot_cli.common.errors import DescriptionError
    from servicebot_cli.description.loader import RobotSource, read_description
    from servicebot_cli.drive.motors import motor_map

    path = fixture("SB215")
    assert _severities(run, path, "SB215") == ["warning"]
    with pytest.raises(DescriptionError, match="front_left_wheel_joint"):
        motor_map(read_description(RobotSource.of(path)))
    assert _severities(run, SIM_URDF, "SB215") == []


def test_an_empty_robot_name_is_a_warning_a_missing_one_an_error(run, tmp_path):
    """bullet3's humanoid.urdf: <robot name="">; urdfdom (check_urdf), Pinocchio and yourdfpy
    load it. Without the attribute urdfdom refuses the file."""
    from tests.check.corpus import check_urdf_rejects

    empty = tmp_path / "empty.urdf"
    empty.write_text(ARM.format(extra="").replace('name="arm">', 'name="">', 1))
    missing = tmp_path / "missing.urdf"
    missing.write_text(ARM.format(extra="").replace(' name="arm">', ">", 1))
    assert _severities(run, empty, "SB009") == ["warning"]
    assert _severities(run, missing, "SB009") == ["error"]
    assert not check_urdf_rejects(empty) and check_urdf_rejects(missing)


def test_an_effort_limit_of_0_is_information_where_no_simulator_runs(run, tmp_path):
    """ROS-Industrial's support packages write effort="0" on arms MoveIt moves (abb, kuka)."""
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra="").replace('effort="10"', 'effort="0"'))
    assert _severities(run, path, "SB206") == ["info"]
    simulated = tmp_path / "simulated.urdf"
    simulated.write_text(ARM.format(extra='<gazebo reference="arm"><mu1>0.5</mu1></gazebo>')
                         .replace('effort="10"', 'effort="0"'))
    result = run("check", simulated, "--format", "json", "--isolated")
    [found] = [f for f in findings(result.stdout) if f["code"] == "SB206"]
    assert found["severity"] == "warning" and "Gazebo's motors" in found["message"]
    assert "never move" not in found["message"]


@pytest.mark.parametrize(("plugin", "interface", "severity"), [
    ("gazebo_ros2_control/GazeboSystem", "position", "info"),
    ("gazebo_ros2_control/GazeboSystem", "effort", "warning"),
    ("gz_ros2_control/GazeboSimSystem", "position", "warning"),
])
def test_an_effort_limit_of_0_under_classic_position_control_moves(run, tmp_path, plugin,
                                                                   interface, severity):
    """Dobot's cra_description: Gazebo Classic's GazeboSystem sets a position-commanded
    joint's position, which no effort limit bounds; the warning said it cannot be driven."""
    path = tmp_path / "arm.urdf"
    control = GZ_CONTROL.format(plugin=plugin).replace('"position"', f'"{interface}"')
    path.write_text(ARM.format(extra=control + '<gazebo reference="arm"><mu1>1</mu1></gazebo>')
                    .replace('effort="10"', 'effort="0"'))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB206")
    [found] = findings(result.stdout)
    assert found["severity"] == severity
    assert ("sets its position directly" in found["message"]) == (severity == "info")


def test_a_velocity_limit_of_0_is_a_warning_everywhere(run, tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra="").replace('velocity="1"', 'velocity="0"'))
    assert _severities(run, path, "SB206") == ["warning"]


_MASS = ('<inertial><mass value="{0}"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
         'ixz="0" iyz="0"/></inertial>')
# base -shoulder-> flange -fixed-> gripper (mass on the gripper only) -finger-> finger
FLANGE = """<robot name="flange">
  <link name="base"/>
  <link name="flange">{flange}</link>
  <link name="gripper">{gripper}</link>
  <link name="finger">""" + _MASS.format(0.1) + """</link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="flange"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
  <joint name="mount" type="fixed"><parent link="flange"/><child link="gripper"/></joint>
  <joint name="finger" type="prismatic">
    <parent link="gripper"/><child link="finger"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.04" effort="10" velocity="0.1"/>
  </joint>
</robot>
"""


@pytest.mark.parametrize(("flange", "gripper", "expected"), [
    ("", _MASS.format(1.0), set()),  # the gripper fixed to it lends it its mass (kortex)
    (_MASS.format(0), _MASS.format(1.0), set()),
    ("", "", {"SB304"}),  # only the finger, past another moving joint, has mass
    (_MASS.format(0), "", {"SB305"}),
], ids=["no inertial, fixed gripper with mass", "mass 0, fixed gripper with mass",
        "no inertial, massless fixed gripper", "mass 0, massless fixed gripper"])
def test_links_fixed_to_a_moving_link_lend_it_their_mass(run, tmp_path, flange, gripper,
                                                         expected):
    """sdformat lumps links on fixed joints into their parent, and Pinocchio merges them: a
    massless flange carrying a gripper is a body with the gripper's mass."""
    path = tmp_path / "flange.urdf"
    path.write_text(FLANGE.format(flange=flange, gripper=gripper))
    result = run("check", path, "--format", "json", "--isolated")
    codes = {f["code"] for f in findings(result.stdout)} & {"SB303", "SB304", "SB305"}
    assert codes == expected, result.stdout


def test_fix_lines_fit_their_findings(run, tmp_path):
    """mycobot_ros2's .urdf files hold xacro properties and velocity="0" limits: SB017's fix
    spoke of xacro's advice in a message that is servicebot's own, and SB206's fix of the
    largest force, for a velocity."""
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra='<xacro:property name="x" value="1" '
                                     'xmlns:xacro="http://www.ros.org/wiki/xacro"/>')
                    .replace('velocity="1"', 'velocity="0"'))
    found = {f["code"]: f for f in findings(run("check", path, "--format", "json",
                                                "--isolated").stdout)}
    assert found["SB206"]["fix"] == "write the joint's top speed in rad/s"
    assert not found["SB017"]["message"].startswith(str(path))  # the place is said once
    assert "xacro's advice" not in found["SB017"]["fix"]


def test_a_limit_without_lower_and_upper_says_they_default_to_zero(run, tmp_path):
    """A revolute wheel with <limit effort velocity/> only: 'lower = upper = 0' for a file
    that writes neither, and the fix 'make it fixed', for a wheel that should be continuous."""
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.format(extra="").replace('lower="-1" upper="1" ', ""))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB204")
    [found] = findings(result.stdout)
    assert found["message"] == ("revolute joint 'shoulder' has a <limit> without lower and "
                                "upper, which default to 0: it cannot move")
    assert found["fix"].endswith('or type="continuous" if it turns without end (a wheel)')
