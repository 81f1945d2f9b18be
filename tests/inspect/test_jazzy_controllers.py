"""inspect reads a controllers file in the layout ros2_control uses since Jazzy.

ros2_control_demos' example_2 names each controller's ``type`` in its own
``ros__parameters`` and lists nothing under ``controller_manager``; inspect refused the file
("no 'controller_manager: ros__parameters:' mapping").
"""

from __future__ import annotations

import json

from tests.conftest import REPO, run_servicebot

EXAMPLE = REPO / "tests" / "realworld" / "ws" / "src" / "example_2"
DIFFBOT = EXAMPLE / "description" / "urdf" / "diffbot.urdf.xacro"
CONTROLLERS = EXAMPLE / "bringup" / "config" / "diffbot_controllers.yaml"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def test_the_controllers_and_their_topics_are_listed():
    result = run_servicebot("inspect", DIFFBOT, "--section", "topics", "--controllers",
                            CONTROLLERS, "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    topics = json.loads(result.stdout)["topics"]
    names = {(t["direction"], t["name"], t["provider"]) for t in topics["topics"]}
    assert names == {("in", "/diffbot_base_controller/cmd_vel", "diffbot_base_controller"),
                     ("out", "/diffbot_base_controller/odom", "diffbot_base_controller"),
                     ("out", "/tf", "diffbot_base_controller"),
                     ("out", "/joint_states", "joint_state_broadcaster")}
