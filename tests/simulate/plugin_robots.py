"""Real plugin-driven robots, edited one tag at a time, and what inspect and simulate say of them.

TurtleBot3 burger (gazebo_ros_pkgs' ROS 1 diff drive), Nav2's sam_bot (the ROS 2 plugin in
``/demo``), Leo Rover (gz-sim's DiffDrive system) and Neobotix's MP-400 (ROS 2, a LIDAR
remapped with ``<argument>``): each copied into a temporary package with one text replaced,
then read back from ``inspect --format json`` and from a bag, through rosbags.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from tests.conftest import REPO, run_servicebot
from tests.simulate.helpers import NO_ROS, REALWORLD_SRC

FIXTURES = REPO / "tests" / "fixtures"
SAM_BOT = FIXTURES / "sam_bot_description" / "src" / "description" / "sam_bot_description.urdf"
LEO = FIXTURES / "leo_description" / "urdf" / "leo_sim.urdf.xacro"
MP_400 = FIXTURES / "neo_simulation2" / "robots" / "mp_400" / "mp_400.urdf"
TURTLEBOT3 = REALWORLD_SRC / "turtlebot3_description" / "urdf" / "turtlebot3_burger.urdf.xacro"
TURTLEBOT3_GAZEBO = "turtlebot3_burger.gazebo.xacro"


def edited(robot: Path, tmp_path: Path, *replacements: tuple[str, str],
           file: str | None = None) -> Path:
    """A copy of ``robot``'s package in ``tmp_path``, ``file`` (default: the robot) edited.

    Each ``(old, new)`` must occur in the file. The copy is the robot's package directory
    (the one holding ``package.xml``), so ``$(find ...)`` and ``package://`` still resolve.
    """
    package = next(p for p in robot.parents if (p / "package.xml").is_file())
    copy = tmp_path / package.name
    shutil.copytree(package, copy)
    target = copy / robot.relative_to(package).parent / (file or robot.name)
    text = target.read_text()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    target.write_text(text)
    return copy / robot.relative_to(package)


def plugin_topics(robot: Path, provider: str) -> dict[str, str]:
    """``inspect --section topics``: the topics ``provider`` lists, name -> direction."""
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return {t["name"]: t["direction"] for t in json.loads(result.stdout)["topics"]["topics"]
            if t["provider"] == provider}


def sensor_topics(robot: Path) -> dict[str, str]:
    """``inspect --section topics``: every published topic, name -> provider."""
    return {t["name"]: t["provider"] for t in listed_topics(robot) if t["direction"] == "out"}


def listed_topics(robot: Path) -> list[dict]:
    """``inspect --section topics --format json``: every topic's record."""
    result = run_servicebot("inspect", robot, "--section", "topics", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    return list(json.loads(result.stdout)["topics"]["topics"])


def bag_messages(robot: Path, tmp_path: Path, *extra: str,
                 duration_s: str = "2") -> dict[str, list]:
    """Every message of a headless run of ``robot``, by topic, read back by rosbags."""
    return run_with_bag(robot, tmp_path, *extra, duration_s=duration_s)[1]


def run_with_bag(robot: Path, tmp_path: Path, *extra: str,
                 duration_s: str = "2") -> tuple[str, dict[str, list]]:
    """A headless run of ``robot``: its stdout and every message of its bag, by topic."""
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    bag = tmp_path / "bag"
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", duration_s,
                            "--bag", bag, *extra, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    store = get_typestore(Stores.ROS2_HUMBLE)
    messages: dict[str, list] = {}
    with Reader(bag) as reader:
        for connection, _, raw in reader.messages():
            messages.setdefault(connection.topic, []).append(
                store.deserialize_cdr(raw, connection.msgtype))
    return result.stdout, messages


def tf_pairs(messages: dict[str, list]) -> set[tuple[str, str]]:
    """(parent, child) of every transform on ``/tf``."""
    return {(t.header.frame_id, t.child_frame_id) for m in messages.get("/tf", [])
            for t in m.transforms}
