"""A ros2_control Gazebo plugin with several ``<parameters>``: every file, later ones winning.

gazebo_ros2_control and gz_ros2_control pass each ``<parameters>`` as a ``--params-file``,
in order, and ROS lets a later file's value replace an earlier one. articubot_one's layout:
``my_controllers.yaml`` names the controllers, ``use_sim.yaml`` adds to the same nodes.
Nav2's sam_bot, given such a plugin, read by ``inspect`` and by a run's bag (rosbags).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, bag_messages, edited

CONTROLLERS = """\
controller_manager:
  ros__parameters:
    update_rate: 50
    diff_cont:
      type: diff_drive_controller/DiffDriveController
    joint_broad:
      type: joint_state_broadcaster/JointStateBroadcaster
diff_cont:
  ros__parameters:
    publish_rate: 10.0
    left_wheel_names: [drivewhl_l_joint]
    right_wheel_names: [drivewhl_r_joint]
    wheel_separation: 0.4
    wheel_radius: 0.1
"""
USE_SIM = """\
controller_manager:
  ros__parameters:
    use_sim_time: true
diff_cont:
  ros__parameters:
    publish_rate: 25.0
"""
PLUGINS = ("libgazebo_ros2_control.so", "libgz_ros2_control-system.so")


def _robot(tmp_path: Path, filename: str) -> Path:
    """sam_bot with a ros2_control plugin naming two parameter files, both written."""
    plugin = (f'<gazebo><plugin name="ros2_control" filename="{filename}">'
              "<parameters>config/my_controllers.yaml</parameters>"
              "<parameters>config/use_sim.yaml</parameters></plugin></gazebo>\n</robot>")
    robot = edited(SAM_BOT, tmp_path, ("</robot>", plugin))
    (robot.parent / "config").mkdir()
    (robot.parent / "config" / "my_controllers.yaml").write_text(CONTROLLERS)
    (robot.parent / "config" / "use_sim.yaml").write_text(USE_SIM)
    return robot


@pytest.mark.parametrize("filename", PLUGINS)
def test_inspect_reads_every_parameters_file_in_order(tmp_path, filename):
    robot = _robot(tmp_path, filename)
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    topics = json.loads(result.stdout)["topics"]
    first, last = topics["controllers_file"].split(" + ")
    assert (first.endswith("my_controllers.yaml"), last.endswith("use_sim.yaml")) == (True, True)
    assert [c["name"] for c in topics["controllers"]] == ["diff_cont", "joint_broad"]
    published = {t["name"]: t["provider"] for t in topics["topics"] if t["direction"] == "out"}
    assert published["/diff_cont/odom"] == "diff_cont"
    assert published["/joint_states"] == "joint_broad"


@pytest.mark.parametrize("filename", PLUGINS)
def test_simulate_reads_every_parameters_file_later_values_winning(tmp_path, filename):
    pytest.importorskip("rosbags")
    robot = _robot(tmp_path, filename)
    out = tmp_path / "out"
    messages = bag_messages(robot, tmp_path, "--out", out)
    assert len(messages["/diff_cont/odom"]) == 50  # 2 s at use_sim.yaml's 25 Hz, not 10
    controller = json.loads((out / "summary.json").read_text())["controller"]
    assert controller["update_rate_hz"]["value"] == 50.0  # from my_controllers.yaml
    assert controller["publish_rate_hz"]["source"].endswith(
        "my_controllers.yaml + " + str(robot.parent / "config" / "use_sim.yaml"))
