"""A file xacro cannot expand is not said to be checked: the summary and JUnit say so.

pal-robotics' pmb2_robot needs pal_urdf_utils; without it, a walk reported '1 file checked:
0 errors, 1 warning; passed' and JUnit skipped="0", while nothing in the robot was read (a
link of mass -5 went unseen). Real xacro expands the files.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from tests.check.helpers import findings

_ROBOT = """<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find pal_urdf_utils)/urdf/deg_to_rad.urdf.xacro"/>
  <link name="base_link"><inertial><mass value="-5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1"
    iyz="0" izz="1"/></inertial></link>
</robot>
"""
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def test_a_walked_file_xacro_cannot_expand_is_not_checked_and_says_so(run, tmp_path):
    (tmp_path / "bot.urdf.xacro").write_text(_ROBOT)
    (tmp_path / "plain.urdf").write_text('<robot name="p"><link name="a"/></robot>')
    text = run("check", "urdf", tmp_path, "--isolated", env=NO_ROS)
    assert text.exit_code == 0
    assert text.stdout.splitlines()[-1] == (
        "2 files checked (1 file not expanded, so not checked: see its finding): 0 errors, "
        "1 warning, 0 info; passed")
    junit = run("check", "urdf", tmp_path, "--isolated", "--format", "junit", env=NO_ROS)
    suite = ET.fromstring(junit.stdout).find("testsuite")
    assert suite is not None and (suite.get("tests"), suite.get("skipped")) == ("2", "1")
    [skipped] = [case for case in suite.iter("testcase") if case.find("skipped") is not None]
    assert skipped.get("file", "").endswith("bot.urdf.xacro")
    assert "not expanded: package 'pal_urdf_utils' not found" in \
        skipped.find("skipped").get("message", "")  # type: ignore[union-attr]


def test_a_file_that_expands_with_its_package_is_checked(run, tmp_path):
    """Given the package (--package), the same file is expanded and its defect found."""
    robot = tmp_path / "bot.urdf.xacro"
    robot.write_text(_ROBOT)
    utils = tmp_path / "utils"
    (utils / "urdf").mkdir(parents=True)
    (utils / "urdf" / "deg_to_rad.urdf.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"/>')
    result = run("check", "urdf", robot, "--isolated", "--format", "json",
                 "--package", f"pal_urdf_utils={utils}", env=NO_ROS)
    assert result.exit_code == 1 and "SB302" in {f["code"] for f in findings(result.stdout)}
    text = run("check", "urdf", robot, "--isolated", "--package", f"pal_urdf_utils={utils}",
               env=NO_ROS)
    assert "not expanded" not in text.stdout


def test_a_launch_file_named_urdf_xacro_is_no_robot_even_when_xacro_fails_first(run, tmp_path):
    """A ROS 1 launch file's $(find xacro) failed the expansion: a warning (a package not
    found) and exit 0 hid that the file is no robot description at all."""
    launch = tmp_path / "bringup.urdf.xacro"
    launch.write_text('<?xml version="1.0"?>\n<launch>\n  <param name="robot_description" '
                      'command="$(find xacro)/xacro $(arg model)"/>\n</launch>\n')
    result = run("check", "urdf", launch, "--isolated", "--format", "json", env=NO_ROS)
    assert result.exit_code == 1
    (finding,) = findings(result.stdout)
    assert (finding["code"], finding["line"]) == ("SB008", 2)
    assert "root element is <launch>" in finding["message"]


def test_a_pipe_xacro_cannot_expand_is_not_opened_again(tmp_path):
    """Reading its root after the expansion failed opened the pipe again, which waited
    for a writer for ever."""
    import os
    import subprocess
    import sys
    import threading

    pipe = tmp_path / "robot.urdf.xacro"
    os.mkfifo(pipe)

    def write() -> None:
        with open(pipe, "w") as handle:
            handle.write(_ROBOT)

    writer = threading.Thread(target=write, daemon=True)
    writer.start()
    result = subprocess.run([sys.executable, "-m", "servicebot_cli", "check", "urdf", str(pipe),
                             "--isolated"], capture_output=True, text=True, timeout=60,
                            env={**os.environ, **NO_ROS})
    assert result.returncode == 0, result.stderr
    assert "SB007" in result.stdout and "not expanded" in result.stdout
