"""Real description packages nobody on the team wrote, checked as their users check them.

``tests/realworld/ws`` is a ROS 2 workspace of vendored packages (its README says where each
comes from). No ROS variable is set: packages are found as ROS finds them, from the workspace.
Each xacro is expanded with the arguments its package's launch file passes. Every finding
left is reviewed: an error is a real defect, named with the consumer it breaks.
"""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import pytest

from servicebot_cli.description.install_layout import directory_rules
from servicebot_cli.description.package_dirs import package_name
from tests.check.corpus import check_urdf_commands
from tests.check.helpers import findings
from tests.conftest import REPO

REALWORLD = REPO / "tests" / "realworld"
WS = REALWORLD / "ws"
SRC = WS / "src"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}
MISSING = {"SB007", "SB401", "SB408", "SB409"}  # a package or a mesh not found

# ur_description's launch/view_ur.launch.py, with visual_params pointing at the collision
# meshes (the visual ones are not vendored; see the README).
UR_ARGS = ("ur_type:=ur5e", "name:=ur", "safety_limits:=true", "safety_pos_margin:=0.15",
           "safety_k_position:=20", "tf_prefix:=",
           f"visual_params:={REALWORLD / 'overrides' / 'ur5e_visual_parameters.yaml'}")
# clearpath_platform_description's launch/description.launch.py, with the vendored control.yaml
JACKAL_ARGS = ("is_sim:=true",
               f"gazebo_controllers:={SRC / 'clearpath_control/config/j100/control.yaml'}",
               "namespace:=j100_0000", "use_fake_hardware:=false",
               "use_manipulation_controllers:=false", "use_platform_controllers:=true")

# name: (file, directory to run from inside, launch arguments, the codes it should report)
ROBOTS = {
    # turtlebot3_bringup's description.launch.xml passes no argument. SB215: the wheels have no
    # <limit velocity> (`servicebot drive` refuses the robot); SB301: the caster's and the
    # lidar's inertias are the placeholder 0.001 kg m^2.
    "turtlebot3_burger": (SRC / "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro",
                          SRC / "turtlebot3_description", (), {"SB215", "SB301"}),
    "ur5e": (SRC / "ur_description/urdf/ur.urdf.xacro", SRC / "ur_description", UR_ARGS, set()),
    "ur5e_mocked": (SRC / "ur_description/urdf/ur_mocked.urdf.xacro", SRC / "ur_description",
                    UR_ARGS, set()),
    # MoveIt's kinematic-only arm: no inertia (SB303 is a warning without a simulator) and
    # effort="0" limits (SB206: a simulator could not move the joints; MoveIt ignores effort).
    "fanuc": (SRC / "fanuc_description/urdf/fanuc.urdf", SRC / "fanuc_description", (),
              {"SB206", "SB303"}),
    # The launch passes two arguments the file never reads (SB017, as xacro ignores them);
    # SB215: wheels without a velocity limit.
    "jackal": (REALWORLD / "clearpath/robot.urdf.xacro", REALWORLD / "clearpath", JACKAL_ARGS,
               {"SB017", "SB215"}),
}


def _check(run, target, *args, env=None):
    result = run("check", "urdf", target, *args, "--format", "json", "--isolated",
                 env={**NO_ROS, **(env or {})})
    return result, json.loads(result.stdout)


def _assert_clean(result, document, expected_codes):
    found = findings(result.stdout)
    assert result.exit_code == 0, result.stdout
    assert not [f for f in found if f["severity"] == "error"], result.stdout
    assert not {f["code"] for f in found} & MISSING, result.stdout
    assert {f["code"] for f in found} == expected_codes, result.stdout
    for file in document["files"]:
        assert file["packages"], file["file"]
        for name, location in file["packages"].items():
            assert location["path"] and location["ros_finds_it"], (name, location)


@pytest.mark.parametrize("name", ROBOTS)
def test_each_robot_has_no_false_error_from_the_workspace_a_package_and_elsewhere(
        run, monkeypatch, tmp_path, name):
    path, package, args, expected = ROBOTS[name]
    for cwd, target in ((WS, path.relative_to(WS) if WS in path.parents else path),
                        (package, path.relative_to(package)), (tmp_path, path)):
        monkeypatch.chdir(cwd)
        result, document = _check(run, target, *args)
        _assert_clean(result, document, expected)


def test_check_urdf_accepts_every_robot_servicebot_passes(run, tmp_path, installed):
    """urdfdom's check_urdf agrees: each expansion checked above parses, nothing dropped."""
    _, native, env = check_urdf_commands()
    cases = [(name, path, args) for name, (path, _, args, _) in ROBOTS.items()]
    cases += [(example, SRC / example / "description" / "urdf" / urdf, (*args, *installed))
              for example, (urdf, args, _, _) in EXAMPLES.items()]
    for name, path, args in cases:
        urdf = tmp_path / f"{name}.urdf"
        expanded = run("expand", path, *args, "-o", urdf, env=NO_ROS)
        assert expanded.exit_code == 0, expanded.stderr
        verdict = subprocess.run([*native, str(urdf)], capture_output=True, text=True, env=env)
        assert verdict.returncode == 0 and "Could not parse" not in verdict.stdout, name


def test_the_workspace_walked_from_its_root_skips_includes_and_finds_every_package(
        run, monkeypatch):
    monkeypatch.chdir(WS)
    result, document = _check(run, "src")
    by_file = {Path(f["file"]).name: f for f in document["files"]}
    # xacro includes are checked through the robot that includes them, not as robots
    assert not {"common_properties.xacro", "turtlebot3_burger.gazebo.xacro", "j100.urdf.xacro",
                "rrbot.ros2_control.xacro", "diffbot_description.urdf.xacro"} & set(by_file)
    assert {f["code"] for f in findings(result.stdout)} & {"SB401", "SB408", "SB409"} == set()
    # ur.urdf.xacro needs the launch's name:= and ur_type:= (its default, ur5x, is meant to
    # fail): the real xacro stops the same way without them.
    for ur in ("ur.urdf.xacro", "ur_mocked.urdf.xacro"):
        (error,) = by_file[ur]["findings"]
        assert error["code"] == "SB006" and "Undefined substitution argument name" in error[
            "message"]
    # ros2_control_demos include what their CMakeLists.txt installs: read from the source
    # directory the install rule names, so the whole robot is checked from the sources.
    assert by_file["rrbot_system_with_sensor.urdf.xacro"]["findings"] == []
    expanded = run("expand", "src/example_4/description/urdf/rrbot_system_with_sensor.urdf.xacro",
                   env=NO_ROS)
    assert expanded.exit_code == 0, expanded.output
    assert '<ros2_control name="RRBotSystemWithSensor" type="system">' in expanded.stdout
    assert '<sensor name="tcp_fts_sensor">' in expanded.stdout
    others = [f for name, f in by_file.items() if name not in ("ur.urdf.xacro",
                                                                "ur_mocked.urdf.xacro")]
    assert not [f for file in others for f in file["findings"] if f["severity"] == "error"]


def test_install_rules_are_read_from_cmakelists():
    cmake = (SRC / "example_9" / "CMakeLists.txt").read_text()
    # hardware/include/ goes to include/, not to share/: not a $(find) path
    assert directory_rules(cmake, "ros2_control_demo_example_9") == [
        ("description/launch", "launch"), ("description/ros2_control", "ros2_control"),
        ("description/urdf", "urdf"), ("description/gazebo", "gazebo"),
        ("bringup/launch", "launch"), ("bringup/config", "config")]


# ros2_control_demos: package directory -> (URDF, the arguments and the controllers YAML of the
# example's bringup/launch/*.launch.py (example 9: rrbot_gazebo), codes the URDF reports).
# SB301/SB303 (carlikebot): a placeholder chassis inertia and the massless virtual wheels of a
# bicycle model. SB309 (diffbot): KDL ignores the root link's 0.3 kg, as the note says.
SENSOR_ARGS = ("prefix:=", "use_mock_hardware:=false", "mock_sensor_commands:=false",
               "slowdown:=50.0")
EXAMPLES = {
    "example_1": ("rrbot.urdf.xacro", (), "rrbot_controllers.yaml", set()),
    "example_2": ("diffbot.urdf.xacro", ("use_mock_hardware:=false",), "diffbot_controllers.yaml",
                  {"SB309"}),
    "example_4": ("rrbot_system_with_sensor.urdf.xacro", SENSOR_ARGS,
                  "rrbot_with_sensor_controllers.yaml", set()),
    "example_5": ("rrbot_system_with_external_sensor.urdf.xacro", SENSOR_ARGS,
                  "rrbot_with_external_sensor_controllers.yaml", set()),
    "example_9": ("rrbot.urdf.xacro", ("use_gazebo:=true",), "rrbot_controllers.yaml", set()),
    "example_11": ("carlikebot.urdf.xacro", (), "carlikebot_controllers.yaml", {"SB301", "SB303"}),
    "example_12": ("rrbot.urdf.xacro", (), "rrbot_chained_controllers.yaml", set()),
    "example_13": ("three_robots.urdf.xacro", ("slowdown:=50.0",),
                   "three_robots_controllers.yaml", set()),
    # one joint in an actuator that only commands and a sensor that only reports (SB507 silent)
    "example_14": ("rrbot_modular_actuators_without_feedback_sensors_for_position_feedback"
                   ".urdf.xacro", ("prefix:=", "slowdown:=50.0"),
                   "rrbot_modular_actuators_without_feedback_sensors_for_position_feedback.yaml",
                   set()),
    "example_16": ("diffbot.urdf.xacro", ("use_mock_hardware:=false",),
                   "diffbot_chained_controllers.yaml", {"SB309"}),
}
# The diffbot's left_wheel_joint is at y = -0.05 m (REP 103: the right side) and its right one
# at +0.05 m: diff_drive_controller turns it the wrong way and mirrors its odometry. Example 16
# commands the same wheels through chained PID controllers.
REAL_DEFECTS = {"example_2": {"SB605"}, "example_16": {"SB605"}}


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> list[str]:
    """``--package`` options for the examples, installed as ``colcon --symlink-install`` does."""
    install = tmp_path_factory.mktemp("install")
    options = []
    for package in sorted(SRC.glob("example_*")):
        name = package_name(package)
        assert name is not None
        share = install / name / "share" / name
        share.mkdir(parents=True)
        (share / "package.xml").symlink_to(package / "package.xml")
        for source, installed_dir in directory_rules((package / "CMakeLists.txt").read_text(),
                                                     name):
            if (package / source).is_dir() and not (share / installed_dir).exists():
                (share / installed_dir).symlink_to(package / source)  # launch/ merges two: one
        options += ["--package", f"{name}={share}"]
    return options


@pytest.mark.parametrize("example", EXAMPLES)
def test_ros2_control_demos_built_have_no_false_error_and_their_controllers_match(
        run, monkeypatch, installed, example):
    urdf_name, args, yaml_name, expected = EXAMPLES[example]
    urdf = SRC / example / "description" / "urdf" / urdf_name
    monkeypatch.chdir(WS)
    result, document = _check(run, urdf.relative_to(WS), *args, *installed)
    _assert_clean(result, document, expected)
    controllers = run("check", "controllers", SRC / example / "bringup" / "config" / yaml_name,
                      "--urdf", urdf, *args, *installed, "--format", "json", "--isolated",
                      env=NO_ROS)
    # chained references (pid_controller_left_wheel_joint/left_wheel_joint) and launch
    # substitutions ($(var joint_prefix)1) are not unknown joints: no SB602
    assert {f["code"] for f in findings(controllers.stdout)} == REAL_DEFECTS.get(example, set())
    assert controllers.exit_code == (1 if example in REAL_DEFECTS else 0), controllers.stdout


def test_a_skid_steer_separation_multiplier_is_calibration_not_a_mismatch(run):
    # The Jackal's control.yaml keeps the URDF's wheel_separation (0.37559 m) and multiplies
    # it by 1.5 for its four skidding wheels: the controller's model, not the geometry.
    yaml = SRC / "clearpath_control" / "config" / "j100" / "control.yaml"
    result = run("check", "controllers", yaml, "--urdf", ROBOTS["jackal"][0], *JACKAL_ARGS,
                 "--format", "json", "--isolated", env=NO_ROS)
    assert result.exit_code == 0 and findings(result.stdout) == [], result.stdout


def test_inspect_and_fk_load_vendored_robots_from_the_workspace(run, monkeypatch):
    monkeypatch.chdir(WS)
    burger = run("inspect", ROBOTS["turtlebot3_burger"][0].relative_to(WS), "--section",
                 "totals", "--format", "json", env=NO_ROS)
    drive = json.loads(burger.stdout)["totals"]["drive"]
    # turtlebot3_bringup's param/burger.yaml: wheels.separation 0.160, wheels.radius 0.033
    assert (drive["track_m"], drive["wheel_radius_m"]) == pytest.approx((0.160, 0.033))
    fk = run("fk", ROBOTS["ur5e"][0].relative_to(WS), *UR_ARGS, "-j",
             f"shoulder_lift_joint={-math.pi / 2}", "--frame", "tool0", "--format", "json",
             env=NO_ROS)
    assert fk.exit_code == 0, fk.stderr
    # UR5e DH parameters (Universal Robots): d1 0.1625, a2 0.425, a3 0.3922, d4 0.1333,
    # d5 0.0997, d6 0.0996. Arm straight up: tool0 at (d5, d4 + d6, d1 + a2 + a3).
    (pose,) = json.loads(fk.stdout)["poses"]
    assert pose["position_m"] == pytest.approx(
        [0.0997, 0.1333 + 0.0996, 0.1625 + 0.425 + 0.3922], abs=1e-6)


def test_a_file_included_by_a_relative_path_is_not_walked_as_a_robot(run, tmp_path):
    (tmp_path / "robot.urdf.xacro").write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="parts/base.xacro"/><link name="a"/></robot>')
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "base.xacro").write_text(
        '<robot name="materials"><material name="m"><color rgba="1 1 1 1"/></material></robot>')
    result, document = _check(run, tmp_path)
    assert [Path(f["file"]).name for f in document["files"]] == ["robot.urdf.xacro"]
    assert result.exit_code == 0, result.stdout


@pytest.mark.parametrize(("separation", "stated"), [
    ("0.37", "wheel_separation 0.37 m (1.5 % off; 0.555 m with the multipliers)"),
    ("0.2", "wheel_separation 0.3 m (0.2 m times the multipliers)"),
    ("0.8", "wheel_separation 0.8 m (113 % off; 1.2 m with the multipliers)"),
])
def test_a_separation_just_off_names_the_value_that_nearly_matched(run, tmp_path, separation,
                                                                   stated):
    """Husarion's Lynx: 0.45 m times 1.6 is 0.72 m, but 0.45 m is only 1.1 % off the URDF's
    0.455 m: the message leads with the value that nearly matched, not the calibrated one."""
    source = SRC / "clearpath_control" / "config" / "j100" / "control.yaml"
    text = source.read_text()
    assert "wheel_separation: 0.37559" in text and "wheel_separation_multiplier: 1.5" in text
    yaml = tmp_path / "control.yaml"
    yaml.write_text(text.replace("wheel_separation: 0.37559", f"wheel_separation: {separation}"))
    result = run("check", "controllers", yaml, "--urdf", ROBOTS["jackal"][0], *JACKAL_ARGS,
                 "--format", "json", "--isolated", env=NO_ROS)
    (found,) = findings(result.stdout)
    assert found["code"] == "SB604" and stated in found["message"], found["message"]


CHAINED = SRC / "example_16" / "bringup" / "config" / "diffbot_chained_controllers.yaml"
CARLIKE = SRC / "example_11" / "bringup" / "config" / "carlikebot_controllers.yaml"


@pytest.mark.parametrize(("example", "before", "after", "code", "says"), [
    # a reference of a chained pid_controller that it does not export
    ("example_16", "pid_controller_left_wheel_joint/left_wheel_joint\"",
     "pid_controller_left_wheel_joint/left_wheel_jiont\"", "SB602",
     "which exports references of its dof names only (left_wheel_joint)"),
    # a pid_controller's dof that is no joint
    ("example_16", "dof_names:\n      - left_wheel_joint", "dof_names:\n      - left_wheel_jiont",
     "SB602", "'left_wheel_jiont' is no joint and no <ros2_control> component"),
    # a command interface the pid's joint does not export
    ("example_16", "command_interface: velocity", "command_interface: effort", "SB607",
     "claims the command interface 'effort' of joint 'left_wheel_joint'"),
    # steering_controllers_library's joints are joints
    ("example_11", "virtual_rear_wheel_joint", "virtual_rear_wheel_jiont", "SB602",
     "joint 'virtual_rear_wheel_jiont' is not in"),
])
def test_mistakes_in_real_chained_and_steering_controllers_are_found(
        run, installed, tmp_path, example, before, after, code, says):
    urdf_name, args, yaml_name, _ = EXAMPLES[example]
    source = CHAINED if example == "example_16" else CARLIKE
    text = source.read_text()
    assert before in text, before
    broken = tmp_path / yaml_name
    broken.write_text(text.replace(before, after, 1))
    result = run("check", "controllers", broken, "--urdf",
                 SRC / example / "description" / "urdf" / urdf_name, *args, *installed,
                 "--format", "json", "--isolated", env=NO_ROS)
    found = [f for f in findings(result.stdout) if f["code"] == code]
    assert any(says in str(f["message"]) for f in found), result.stdout


def test_a_closed_loop_diff_drive_reads_no_position_through_a_velocity_pid(run, installed,
                                                                           tmp_path):
    """example_16 reads velocities (position_feedback: false), since its pid controllers
    export only theirs; with position feedback and a closed loop the controller manager
    cannot activate the diff drive."""
    urdf_name, args, yaml_name, _ = EXAMPLES["example_16"]
    text = CHAINED.read_text().replace("position_feedback: false", "position_feedback: true")
    broken = tmp_path / yaml_name
    broken.write_text(text.replace("open_loop: true", "open_loop: false"))
    result = run("check", "controllers", broken, "--urdf",
                 SRC / "example_16" / "description" / "urdf" / urdf_name, *args, *installed,
                 "--format", "json", "--isolated", env=NO_ROS)
    found = [f for f in findings(result.stdout) if f["code"] == "SB607"]
    assert len(found) == 2 and all("does not export (it exports velocity" in str(f["message"])
                                   for f in found), result.stdout
    assert found[0]["fix"] == "position_feedback: false (odometry from the wheels' velocities)"


def test_a_skid_steer_track_written_wider_is_a_warning_a_two_wheel_one_an_error(run, installed,
                                                                                tmp_path):
    """Clearpath's Warthog writes wheel_separation 1.5 m on its wheels' 1.14 m track, the
    effective track of a base whose four wheels skid when it turns; the Jackal writes the
    same with a multiplier of 1.5, and passed. A two-wheel base has no such excuse."""
    source = SRC / "clearpath_control" / "config" / "j100" / "control.yaml"
    yaml = tmp_path / "control.yaml"
    yaml.write_text(source.read_text().replace("wheel_separation: 0.37559",
                                               "wheel_separation: 0.56").replace(
        "wheel_separation_multiplier: 1.5", "wheel_separation_multiplier: 1.0"))
    result = run("check", "controllers", yaml, "--urdf", ROBOTS["jackal"][0], *JACKAL_ARGS,
                 "--format", "json", "--isolated", env=NO_ROS)
    (found,) = findings(result.stdout)
    assert (found["code"], found["severity"]) == ("SB604", "warning")
    assert "a skid-steer base's effective track" in found["message"]
    assert result.exit_code == 0
    urdf_name, args, yaml_name, _ = EXAMPLES["example_2"]
    two = tmp_path / yaml_name
    two.write_text((SRC / "example_2" / "bringup" / "config" / yaml_name).read_text().replace(
        "wheel_separation: 0.10", "wheel_separation: 0.15"))
    result = run("check", "controllers", two, "--urdf",
                 SRC / "example_2" / "description" / "urdf" / urdf_name, *args, *installed,
                 "--format", "json", "--isolated", env=NO_ROS)
    (wide,) = [f for f in findings(result.stdout) if f["code"] == "SB604"]
    assert wide["severity"] == "error"
