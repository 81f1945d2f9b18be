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
is the robot's name, the name it is usually spawned with. Pure.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.description.model_plugins import JOINT_STATE, model_plugin_rows

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.simulate.controllers.config import ControllersFile


@dataclass(frozen=True)
class JointStateTopics:
    """The topics joint states are published on, and what could not be published, why."""

    topics: tuple[str, ...]
    notes: tuple[str, ...] = ()


def joint_state_topics(robot: RobotDescription, controllers: ControllersFile) -> JointStateTopics:
    """The broadcasters' topics of ``controllers``, then the model plugins', each once."""
    topics = list(controllers.joint_state_topics)
    notes = []
    for block in robot.gazebo:
        if block.reference is not None:
            continue
        for plugin in block.plugins:
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
    return JointStateTopics(tuple(dict.fromkeys(topics)), tuple(notes))
