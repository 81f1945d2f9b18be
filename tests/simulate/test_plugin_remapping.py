"""A gazebo_ros plugin's topics follow its node's remap rules, in inspect and in the bag.

As gazebo_ros's ``node.cpp`` builds the node (name: the plugin's; namespace:
``<ros><namespace>``; each ``<ros><argument>`` an argument, each ``<ros><remapping>`` a
``--ros-args -r`` rule) and rcl's ``remap.c`` applies the rules: names compared fully
qualified, the first matching rule wins. Real descriptions: Neobotix's MP-400 (its LIDAR
remapped with the older ``<argument>~/out:=scan</argument>``) and Nav2's sam_bot.
"""

from __future__ import annotations

import pytest

from tests.simulate.plugin_robots import (
    MP_400,
    SAM_BOT,
    bag_messages,
    edited,
    plugin_topics,
    sensor_topics,
)

SCAN_RULE = "<remapping>~/out:=scan</remapping>"


def test_mp_400s_argument_rule_puts_its_scan_on_scan(tmp_path):
    pytest.importorskip("rosbags")
    assert sensor_topics(MP_400)["scan"] == "lidar_1_sensor"
    messages = bag_messages(MP_400, tmp_path)
    assert messages["/scan"] and "/lidar_1/out" not in messages


def test_a_remapped_sensor_topic_is_put_in_the_plugins_namespace(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, (SCAN_RULE, "<namespace>robot1</namespace>" + SCAN_RULE))
    assert sensor_topics(robot)["robot1/scan"] == "lidar"
    messages = bag_messages(robot, tmp_path)
    assert messages["/robot1/scan"] and "/scan" not in messages


def test_the_first_matching_rule_wins_and_a_rule_must_match_the_full_name(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, (SCAN_RULE, "<remapping>out:=wrong</remapping>"
                                       + SCAN_RULE + "<remapping>~/out:=late</remapping>"))
    assert sensor_topics(robot)["scan"] == "lidar"
    messages = bag_messages(robot, tmp_path)
    assert messages["/scan"] and not {"/wrong", "/late", "/demo/wrong"} & set(messages)


def test_the_drive_plugins_odometry_follows_an_argument_rule(tmp_path):
    pytest.importorskip("rosbags")
    robot = edited(SAM_BOT, tmp_path, ("<namespace>/demo</namespace>\n        <remap",
                                       "<namespace>/demo</namespace>\n        "
                                       "<argument>odom:=wheel/odom</argument><remap"))
    assert plugin_topics(robot, "diff_drive")["/demo/wheel/odom"] == "out"
    messages = bag_messages(robot, tmp_path)
    assert messages["/demo/wheel/odom"] and "/demo/odom" not in messages


def test_a_rule_for_another_node_is_not_this_ones(tmp_path):
    robot = edited(SAM_BOT, tmp_path, (SCAN_RULE, "<remapping>other:~/out:=nope</remapping>"))
    assert sensor_topics(robot)["scan/out"] == "lidar"  # the plugin is named scan


def test_a_renamed_node_takes_the_rules_for_its_new_name(tmp_path):
    # rcl renames the node first (__node:=), then matches node-specific rules to that name
    robot = edited(SAM_BOT, tmp_path, (SCAN_RULE, "<argument>__node:=lidar2</argument>"
                                       "<remapping>lidar2:~/out:=scan2</remapping>"))
    assert sensor_topics(robot)["scan2"] == "lidar"


def test_the_first_rename_of_a_node_wins(tmp_path):
    robot = edited(SAM_BOT, tmp_path, (SCAN_RULE, "<argument>__node:=first</argument>"
                                       "<argument>__node:=second</argument>"))
    assert sensor_topics(robot)["first/out"] == "lidar"
