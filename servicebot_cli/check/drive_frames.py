"""SB520: a Gazebo drive plugin's odometry frames that leave the robot without odometry in TF.

A drive plugin broadcasts odom -> base on ``/tf`` (:func:`~servicebot_cli.description.
model_plugins.odometry_frames` names the two frames). tf2 ignores a transform from a frame to
itself (``TF_SELF_TRANSFORM``): an odometry frame written equal to the base frame is never
on ``/tf``. A base frame that is no link of the robot joins no frame robot_state_publisher
publishes: odom and the robot's links are two trees. Only frames written in the file are
judged (a launch file may publish a default ``base_footprint``), as tf2 reads them: without a
leading ``/``. Pure.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.description.extensions import param
from servicebot_cli.description.model_plugins import (
    diff_drive_kind,
    odometry_frame_tags,
    odometry_frames,
    publishes_odom_tf,
)

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from servicebot_cli.description.extensions import Plugin
    from servicebot_cli.description.robot import RobotDescription

_PLANAR_MOVE = "gazebo_ros_planar_move"  # its odom -> base tf is on unless turned off


def check(robot: RobotDescription) -> Iterator[Issue]:
    """SB520 for each drive plugin whose odom -> base transform tf2 drops or cannot join."""
    links = {link.name for link in robot.links}
    for plugin in robot.model_plugins:
        tags = _frame_tags(plugin)
        if tags is None or not _broadcasts(plugin):
            continue
        odom_tag, base_tag = tags
        written = param(plugin.params, base_tag)
        # tf2 strips a leading '/' from every frame it is given (BufferCore::setTransform)
        odom, base = (frame.lstrip("/") for frame in odometry_frames(
            plugin, robot.name, robot.root_link or "base_link"))
        where = _element(plugin, base_tag)
        if odom == base:  # the defaults differ: one of them is written
            yield Issue("SB520", f"plugin '{plugin.filename or plugin.name}': <{odom_tag}> and "
                        f"<{base_tag}> are both '{base}': tf2 ignores a transform from a frame "
                        "to itself (TF_SELF_TRANSFORM), so its odometry never reaches /tf",
                        where if where is not None else plugin.element,
                        fix=f"set <{odom_tag}> to the odometry frame (odom)")
        elif written is not None and written.strip() and links and base not in links:
            # (a file of no link is a part of a robot, whose links are elsewhere)
            yield Issue("SB520", f"plugin '{plugin.filename or plugin.name}': <{base_tag}> "
                        f"'{base}' is no link of the robot: its odom -> {base} transform joins "
                        "no frame robot_state_publisher publishes, so the robot's links hang "
                        "apart from odom", where if where is not None else plugin.element,
                        fix=f"name the robot's base link ('{robot.root_link}') there, or add a "
                            f"link '{base}' to the URDF")


def _frame_tags(plugin: Plugin) -> tuple[str, str] | None:
    """The odometry and base frame tags the plugin reads; None for a plugin that drives none."""
    if diff_drive_kind(plugin) is None and _PLANAR_MOVE not in plugin.filename:
        return None
    return odometry_frame_tags(plugin)


def _broadcasts(plugin: Plugin) -> bool:
    """Whether the plugin puts odom -> base on /tf (gz-sim's DiffDrive always does)."""
    if diff_drive_kind(plugin) == "gz":
        return True
    return publishes_odom_tf(plugin, default=_PLANAR_MOVE in plugin.filename)


def _element(plugin: Plugin, tag: str) -> ET.Element | None:
    return None if plugin.element is None else plugin.element.find(tag)
