"""check controllers picks the user's files, never ours against theirs.

``--urdf MY.xacro`` without a YAML checked servicebot's own bundled controllers.yaml against
the user's robot (KUKA's kr10: 8 errors in a file the user never wrote); a YAML without
``--urdf`` was judged against the bundled robots (create3's wheel_radius 'disagrees with the
URDF's 0.07 m'). Now the robot's own YAML is found as simulate and inspect find it, and a
YAML of another robot is refused with what to give.
"""

from __future__ import annotations

import json

from tests.check.helpers import findings, ros2_package
from tests.conftest import REPO, assert_one_line_error

_PLUGIN = ('<gazebo><plugin filename="gz_ros2_control-system" name="ros2_control">'
           '<parameters>$(find bot_description)/config/bot_controllers.yaml</parameters>'
           '</plugin></gazebo>')


def _package(tmp_path, plugin: bool = True):
    """ws/src/bot_description: the real robot as a xacro, its controllers in config/."""
    package = ros2_package(tmp_path / "ws", "bot_description")
    controllers = (REPO / "robots" / "controllers.yaml").read_text()
    assert "rear_left_wheel_joint" in controllers
    (package / "config" / "bot_controllers.yaml").write_text(
        controllers.replace("rear_left_wheel_joint", "rear_left_wheel_jiont", 1))
    robot = (REPO / "robots" / "service_robot_real.urdf.xml").read_text()
    xacro = package / "urdf" / "bot.urdf.xacro"
    xacro.write_text(robot.replace('<robot name="service_robot">', '<robot name="service_robot"'
                                   ' xmlns:xacro="http://www.ros.org/wiki/xacro">', 1)
                     .replace("</robot>", (_PLUGIN if plugin else "") + "\n</robot>"))
    return xacro


def test_the_robots_own_controllers_file_is_checked(run, tmp_path):
    xacro = _package(tmp_path)
    result = run("check", "controllers", "--urdf", xacro, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.stdout
    document = json.loads(result.stdout)
    [report] = document["files"]
    assert report["file"].startswith(str(xacro.parent.parent / "config" / "bot_controllers.yaml"))
    assert [f["code"] for f in report["findings"]] == ["SB602"]
    assert "rear_left_wheel_jiont" in report["findings"][0]["message"]


def test_a_robot_naming_no_controllers_file_is_asked_for_one(run, tmp_path):
    xacro = _package(tmp_path, plugin=False)
    assert_one_line_error(run("check", "controllers", "--urdf", xacro), 2,
                          "names no controllers file",
                          f"servicebot check controllers FILE.yaml --urdf {xacro}")
    assert_one_line_error(run("check", "controllers", "--urdf", xacro, "sim_mode:=true"), 2,
                          f"servicebot check controllers FILE.yaml --urdf {xacro} sim_mode:=true")


def test_controllers_yaml_beside_the_robot_is_its_own(run):
    result = run("check", "controllers", "--urdf", REPO / "robots" / "service_robot_real.urdf.xml",
                 "--format", "json", "--isolated")
    assert result.exit_code == 0, result.stdout
    [report] = json.loads(result.stdout)["files"]
    assert report["file"].split(" against ")[0].endswith("robots/controllers.yaml")


def test_another_robots_yaml_without_its_robot_is_refused(run, tmp_path):
    other = tmp_path / "control.yaml"
    other.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
                     "    diffdrive_controller:\n      type: diff_drive_controller/"
                     "DiffDriveController\ndiffdrive_controller:\n  ros__parameters:\n"
                     "    left_wheel_names: [left_wheel_joint]\n"
                     "    right_wheel_names: [right_wheel_joint]\n"
                     "    wheel_separation: 0.233\n    wheel_radius: 0.03575\n")
    assert_one_line_error(run("check", "controllers", other), 2,
                          "names none of the bundled robots' joints (left_wheel_joint, "
                          "right_wheel_joint)", "--urdf ROBOT.urdf.xacro")


def test_a_typo_in_a_bundled_robots_yaml_is_still_found(run, tmp_path):
    typo = tmp_path / "controllers.yaml"
    typo.write_text((REPO / "robots" / "controllers.yaml").read_text().replace(
        "rear_left_wheel_joint", "rear_left_wheel_jiont", 1))
    result = run("check", "controllers", typo, "--robot", "real", "--format", "json",
                 "--isolated")
    assert [f["code"] for f in findings(result.stdout)] == ["SB602"]
    unnamed = run("check", "controllers", typo, "--format", "json", "--isolated")
    assert unnamed.exit_code == 1 and {f["code"] for f in findings(unnamed.stdout)} == {"SB602"}


def test_the_file_its_install_rules_put_in_place_is_found(run, tmp_path):
    """ros2_control_demos' example_9: bringup/config installed as share/PKG/config."""
    xacro = _package(tmp_path)
    package = xacro.parent.parent
    (package / "bringup").mkdir()
    (package / "config").rename(package / "bringup" / "config")
    (package / "CMakeLists.txt").write_text(
        "project(bot_description)\n"
        "install(DIRECTORY bringup/config urdf DESTINATION share/${PROJECT_NAME})\n")
    result = run("check", "controllers", "--urdf", xacro, "--format", "json", "--isolated")
    [report] = json.loads(result.stdout)["files"]
    assert report["file"].startswith(str(package / "bringup" / "config" / "bot_controllers.yaml"))
    assert [f["code"] for f in report["findings"]] == ["SB602"]


def test_a_packages_yaml_without_its_robot_is_refused(run, tmp_path):
    """husky_control's control.yaml names the bundled robot's wheel joints, with Husky's own
    wheel radius: judged against the bundled robot, it was told to write 0.07 m."""
    package = ros2_package(tmp_path / "ws", "husky_control")
    controllers = (REPO / "robots" / "controllers.yaml").read_text()
    assert "wheel_radius: 0.07" in controllers
    yaml_file = package / "config" / "control.yaml"
    yaml_file.write_text(controllers.replace("wheel_radius: 0.07", "wheel_radius: 0.1651"))
    assert_one_line_error(run("check", "controllers", yaml_file), 2,
                          "belongs to package 'husky_control': give the robot it configures",
                          "--urdf ROBOT.urdf.xacro (or --robot sim|real for a bundled robot)")
    bundled = run("check", "controllers", yaml_file, "--robot", "real", "--format", "json",
                  "--isolated")
    assert "SB603" in {f["code"] for f in findings(bundled.stdout)}  # asked for: judged
