"""Where a run publishes joint states: where the robot's own publishers would, and only there.

Joint states reach ROS from a ``joint_state_broadcaster`` the controllers file configures
(:mod:`.config`: ``/joint_states``, or ``/NAME/joint_states`` with ``use_local_topics``) and
from the model-level Gazebo plugins that publish them, the topics ``inspect --section topics``
lists (:mod:`~servicebot_cli.description.model_plugins`): Classic's
``gazebo_ros_joint_state_publisher``, the ROS 1 diff drive with
``<publishWheelJointState>true``, gz-sim's ``JointStatePublisher``. With none of them, nothing
publishes joint states, and robot_state_publisher, which turns them into the movable joints'
transforms, has none to publish. A gz topic that names the world (``/world/WORLD/...``, its
default) cannot be named by a run, which has no world name: it is left out with a note. MODEL
is the robot's name, the name it is usually spawned with. A ``gazebo_ros_joint_state_publisher``
that is the only publisher sends its ``<joint_name>`` joints, in that order, at its
``<update_rate>`` (ROS 2 ``gazebo_ros_joint_state_publisher.cpp``), and a ROS 1 diff drive its
two wheels at its ``<updateRate>``; robot_state_publisher then has those joints only. Pure.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.description.elements import parse_float
from servicebot_cli.description.extensions import Plugin, param, params_all
from servicebot_cli.description.model_plugins import JOINT_STATE, model_plugin_rows
from servicebot_cli.simulate.sensors.joint_states import JointStates

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.simulate.controllers.config import ControllersFile
    from servicebot_cli.simulate.scenario.definition import Scenario
    from servicebot_cli.simulate.simulator import SimResult


@dataclass(frozen=True)
class JointStateTopics:
    """The topics joint states are published on, and what could not be published, why."""

    topics: tuple[str, ...]
    notes: tuple[str, ...] = ()
    joints: tuple[str, ...] | None = None
    """The joints sent, in this order; None: every movable joint, in URDF order."""
    rate_hz: float | None = None
    """The publisher's own rate [Hz] (0: every step); None: the scenario's ``rates``."""

    def timed(self, scenario: Scenario) -> Scenario:
        """``scenario`` with joint states at the publisher's own rate, if it has one.

        At most once per control tick; an ``<update_rate>`` of 0 or less: every tick.
        """
        if self.rate_hz is None:
            return scenario
        control_hz = scenario.controller.update_rate_hz
        rate_hz = control_hz if self.rate_hz <= 0 else min(self.rate_hz, control_hz)
        return dataclasses.replace(scenario, rates=dataclasses.replace(
            scenario.rates, joint_states_hz=rate_hz))

    def narrowed(self, pieces: Iterator[SimResult]) -> Iterator[SimResult]:
        """``pieces`` with only :attr:`joints`' states, in that order (all when None)."""
        for piece in pieces:
            states = piece.joints
            names = tuple(n for n in self.joints or states.names if n in states.names)
            if names == states.names:
                yield piece
                continue
            index = [states.names.index(n) for n in names]
            yield dataclasses.replace(piece, joints=JointStates(
                names, states.times_s, states.positions[:, index], states.velocities[:, index]))


def joint_state_topics(robot: RobotDescription, controllers: ControllersFile) -> JointStateTopics:
    """The broadcasters' topics of ``controllers``, then the model plugins', each once.

    When a ``gazebo_ros_joint_state_publisher`` is the only publisher, its joints and rate.
    """
    topics = list(controllers.joint_state_topics)
    notes: list[str] = []
    sources: list[Plugin] = []
    for plugin in robot.model_plugins:
        before = len(topics)
        _plugin_topics(robot, plugin, topics, notes)
        sources += [plugin] * (len(topics) > before)
    only = sources[0] if len(sources) == 1 and not controllers.joint_state_topics else None
    if only is not None and "gazebo_ros_joint_state_publisher" in only.filename:
        return JointStateTopics(tuple(dict.fromkeys(topics)), tuple(notes),
                                *_publisher_joints(robot, only))
    if only is not None and "gazebo_ros_diff_drive" in only.filename:
        return JointStateTopics(tuple(dict.fromkeys(topics)), tuple(notes),
                                *_drive_wheel_joints(robot, only))
    return JointStateTopics(tuple(dict.fromkeys(topics)), tuple(notes))


def _publisher_joints(robot: RobotDescription, plugin: Plugin) -> tuple[tuple[str, ...], float]:
    """gazebo_ros_joint_state_publisher's ``<joint_name>`` list and ``<update_rate>``.

    Its joints in the order written, those the model has (it skips the others; Gazebo merges
    away fixed joints); its rate 100 Hz by default.
    """
    movable = {j.name for j in robot.movable_joints}
    names = tuple(n for n in params_all(plugin.params, "joint_name") if n in movable)
    rate = parse_float(param(plugin.params, "update_rate"))
    return names, 100.0 if rate is None else rate


def _drive_wheel_joints(robot: RobotDescription,
                        plugin: Plugin) -> tuple[tuple[str, ...], float]:
    """The ROS 1 diff drive's ``<publishWheelJointState>``: its two wheels, at its rate.

    ``publishWheelJointState()`` sends the left and the right joint only, from
    ``UpdateChild`` once per ``<updateRate>`` (default 100 Hz; 0: every step), as gazebo_ros_pkgs'
    ROS 1 ``gazebo_ros_diff_drive.cpp`` does.
    """
    movable = {j.name for j in robot.movable_joints}
    wheels = tuple(name for side in ("left", "right")
                   for name in [param(plugin.params, f"{side}Joint")
                                or param(plugin.params, f"{side}_joint")]
                   if name is not None and name in movable)
    rate = parse_float(param(plugin.params, "updateRate"))
    return wheels, 100.0 if rate is None else rate


def _plugin_topics(robot: RobotDescription, plugin: Plugin, topics: list[str],
                   notes: list[str]) -> None:
    """Add ``plugin``'s joint-state topics to ``topics``, or a note why one is left out."""
    for direction, name, message, _ in model_plugin_rows(plugin):
        if direction != "out" or message != JOINT_STATE:
            continue
        name = name.replace("/MODEL/", f"/{robot.name}/")
        if "/WORLD/" in name:
            notes.append(f"note: {plugin.filename or plugin.name} publishes joint "
                         f"states on {name}, in the world the robot is spawned in; "
                         "give it a <topic> to have them in the run")
            continue
        topics.append(name)
