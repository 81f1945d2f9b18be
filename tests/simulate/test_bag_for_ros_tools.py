"""What ROS tools need from the bag: /clock, /robot_description and each topic's QoS.

Read back with libraries that share no code with the writer: ``rosbags`` (messages and its
own parsing of metadata.yaml's QoS), the ``mcap`` package (channel metadata) and PyYAML.
"""

from __future__ import annotations

import pytest
import yaml

from tests.conftest import SIM_URDF

SCENARIO = """\
duration_s: 2.5
cmd_vel:
  - {duration_s: 2, linear_m_s: 0.05, angular_rad_s: 0.1}
"""
LATCHED = {"/robot_description", "/tf_static"}


@pytest.fixture(scope="module")
def bag(tmp_path_factory):
    from click.testing import CliRunner

    from servicebot_cli.cli import main

    directory = tmp_path_factory.mktemp("ros_tools")
    (directory / "s.yaml").write_text(SCENARIO)
    result = CliRunner().invoke(main, ["simulate", "--headless", "-s", str(directory / "s.yaml"),
                                       "--bag", str(directory / "bag")], catch_exceptions=False)
    assert result.exit_code == 0, result.stderr
    return directory / "bag"


def _messages(bag):
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    seen: dict[str, list] = {}
    with Reader(bag) as reader:
        connections = {c.topic: c for c in reader.connections}
        for connection, stamp, raw in reader.messages():
            seen.setdefault(connection.topic, []).append(
                (stamp, store.deserialize_cdr(raw, connection.msgtype)))
    return connections, seen


def test_clock_ticks_with_the_simulated_time(bag):
    connections, seen = _messages(bag)
    assert connections["/clock"].msgtype == "rosgraph_msgs/msg/Clock"
    clock = seen["/clock"]
    values = [m.clock.sec * 1_000_000_000 + m.clock.nanosec for _, m in clock]
    assert values == [stamp for stamp, _ in clock]  # each says the time it is logged at
    # every control tick (the default 100 Hz), from 0 to the end of the run
    assert values == [k * 10_000_000 for k in range(251)]
    assert max(s for topic in seen.values() for s, _ in topic) == values[-1]


def test_robot_description_is_the_urdf_once_at_time_zero(bag):
    connections, seen = _messages(bag)
    assert connections["/robot_description"].msgtype == "std_msgs/msg/String"
    [(stamp, message)] = seen["/robot_description"]
    assert stamp == 0
    assert message.data == SIM_URDF.read_text(encoding="utf-8")


def test_every_topic_offers_its_publishers_qos(bag):
    from rosbags.interfaces import QosDurability, QosReliability

    metadata = yaml.safe_load((bag / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    offered = {t["topic_metadata"]["name"]: yaml.safe_load(t["topic_metadata"][
        "offered_qos_profiles"]) for t in metadata["topics_with_message_count"]}
    assert set(offered) == LATCHED | {"/clock", "/diff_controller/odom", "/tf", "/joint_states",
                                      "/scan", "/imu/data", "/pi_camera/camera_info"}
    for topic, profiles in offered.items():
        assert profiles, f"{topic} has no QoS"
        for profile in profiles:
            assert set(profile) == {"history", "depth", "reliability", "durability", "deadline",
                                    "lifespan", "liveliness", "liveliness_lease_duration",
                                    "avoid_ros_namespace_conventions"}
            # rmw enums as integers (metadata version 5): transient local 1, volatile 2
            assert profile["durability"] == (1 if topic in LATCHED else 2), topic
            assert profile["deadline"] == {"sec": 9223372036, "nsec": 854775807}
    assert [p["depth"] for p in offered["/tf"]] == [10, 100]  # drive controller, robot_state_pub
    assert offered["/clock"][0]["reliability"] == 2  # best effort, as gazebo_ros publishes it
    assert offered["/scan"][0]["depth"] == 5  # sensor data

    connections, _ = _messages(bag)  # rosbags parses the same strings its own way
    for topic, connection in connections.items():
        durability = {q.durability for q in connection.ext.offered_qos_profiles}
        assert durability == ({QosDurability.TRANSIENT_LOCAL} if topic in LATCHED
                              else {QosDurability.VOLATILE}), topic
    assert connections["/clock"].ext.offered_qos_profiles[0].reliability \
        == QosReliability.BEST_EFFORT


def test_mcap_channels_carry_the_same_qos(bag):
    from mcap.reader import make_reader

    metadata = yaml.safe_load((bag / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    expected = {t["topic_metadata"]["name"]: t["topic_metadata"]["offered_qos_profiles"]
                for t in metadata["topics_with_message_count"]}
    with (bag / "bag_0.mcap").open("rb") as handle:
        channels = make_reader(handle).get_summary().channels.values()
        assert {c.topic: c.metadata["offered_qos_profiles"] for c in channels} == expected
