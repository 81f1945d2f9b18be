"""The topics a robot's model plugins publish that a run does not: said, not left silent.

``inspect --section topics`` lists what each known model-level plugin publishes
(:func:`~servicebot_cli.description.model_plugins.model_plugin_rows`); a run writes the
drive's, the joint states' and the sensors' topics. gz-sim's OdometryPublisher, Gazebo
Classic's p3d ground truth and hector's GPS are not simulated: a bag without their topics,
and no word of it, read as if the robot published none. Pure.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

from servicebot_cli.description.model_plugins import model_plugin_rows

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def unpublished(robot: RobotDescription, published: Collection[str]) -> tuple[str, ...]:
    """A note for each topic a model plugin of ``robot`` publishes and ``published`` lacks."""
    notes = []
    for plugin in robot.model_plugins:
        for direction, topic, message, _ in model_plugin_rows(plugin):
            name = topic.replace("/MODEL/", f"/{robot.name}/")
            if direction == "out" and name not in published and "/WORLD/" not in name:
                notes.append(f"note: {name} ({message}) of plugin "
                             f"{plugin.filename or plugin.name} is not simulated: the run "
                             "writes no such topic")
    return tuple(dict.fromkeys(notes))
