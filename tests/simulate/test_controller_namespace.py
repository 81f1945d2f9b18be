"""Controllers run in the ros2_control Gazebo plugin's namespace, under its remap rules.

gazebo_ros2_control and gz_ros2_control (``*_ros2_control_plugin.cpp``) turn the plugin's
``<ros><namespace>`` into ``__ns:=`` and each ``<ros><remapping>`` into ``-r RULE`` for the
controller manager and the controllers it loads: ``~/odom`` of ``diff_controller`` is then
``/robot1/diff_controller/odom``, or ``/robot1/odom`` under ``~/odom:=odom``; the
joint_state_broadcaster's relative ``joint_states`` is ``/robot1/joint_states``; and
diff_drive_controller's empty ``tf_frame_prefix`` is the namespace. inspect listed, and
simulate published, every one of them at the root.
"""

from __future__ import annotations

import shutil

import pytest

from tests.conftest import REPO
from tests.simulate.plugin_robots import bag_messages, listed_topics

PLUGIN = '<plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">'


def _namespaced(tmp_path, ros: str):
    shutil.copy(REPO / "robots" / "controllers.yaml", tmp_path / "controllers.yaml")
    text = (REPO / "robots" / "service_robot.urdf.xml").read_text()
    assert PLUGIN in text
    robot = tmp_path / "robot.urdf"
    robot.write_text(text.replace(PLUGIN, PLUGIN + f"<ros>{ros}</ros>"))
    return robot


def test_inspect_names_controller_topics_in_the_plugins_namespace(tmp_path):
    robot = _namespaced(tmp_path, "<namespace>robot1</namespace>"
                                  "<remapping>~/odom:=odom</remapping>")
    listed = {(t["provider"], t["name"]) for t in listed_topics(robot)}
    assert {("diff_controller", "/robot1/diff_controller/cmd_vel"),
            ("diff_controller", "/robot1/odom"),
            ("joint_state_broadcaster", "/robot1/joint_states"),
            ("arm_controller", "/robot1/arm_controller/joint_trajectory")} <= listed
    assert not {name for _, name in listed} & {"/diff_controller/odom", "/joint_states"}


@pytest.mark.parametrize(("rule", "expected"), [
    ("~/cmd_vel_unstamped:=platform/cmd_vel_unstamped",  # clearpath_common's gazebo.urdf.xacro
     "which the ros2_control plugin remaps to /robot1/platform/cmd_vel_unstamped"),
    ("~/odom:=odom", "remap it to ~/cmd_vel"),  # no rule for it: the advice stands
])
def test_the_unstamped_note_follows_the_plugins_own_remap(tmp_path, rule, expected):
    robot = _namespaced(tmp_path, f"<namespace>robot1</namespace><remapping>{rule}</remapping>")
    [cmd_vel] = [t for t in listed_topics(robot) if t["name"].endswith("/cmd_vel")]
    assert cmd_vel["note"].startswith("Humble subscribes ~/cmd_vel_unstamped when "
                                      "use_stamped_vel is false")
    assert cmd_vel["note"].endswith(expected)


def test_simulate_publishes_there_with_the_namespaces_frames(tmp_path):
    pytest.importorskip("rosbags")
    robot = _namespaced(tmp_path, "<namespace>/robot1</namespace>")
    messages = bag_messages(robot, tmp_path, duration_s="0.5")
    assert messages["/robot1/diff_controller/odom"] and messages["/robot1/joint_states"]
    assert not {"/diff_controller/odom", "/joint_states"} & set(messages)
    [frames] = {(m.header.frame_id, m.child_frame_id)
                for m in messages["/robot1/diff_controller/odom"]}
    assert frames == ("robot1/odom", "robot1/base_link")
