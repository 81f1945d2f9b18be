"""The plugins table: Gazebo plugins, ros2_control hardware and Gazebo link properties."""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.description.extensions import GazeboBlock, Plugin, Ros2Control, Sensor


@dataclass(frozen=True)
class Param:
    """One parameter: a path below the plugin (``ros/remapping``) and its text."""

    name: str
    value: str


@dataclass(frozen=True)
class PluginInfo:
    """A Gazebo ``<plugin>``.

    Attributes:
        attached_to: ``model`` for a model-level plugin, ``sensor NAME`` inside a sensor.
        ros2_file: One of gazebo_plugins' in a file for ROS 2 (see
            :class:`~servicebot_cli.description.extensions.Plugin`): it reads no ROS 1 name.
    """

    name: str
    filename: str
    attached_to: str
    params: tuple[Param, ...]
    ros2_file: bool = False


@dataclass(frozen=True)
class HardwareInfo:
    """A ``<ros2_control>`` system and its hardware plugin."""

    name: str
    type: str
    plugin: str | None
    params: tuple[Param, ...]


@dataclass(frozen=True)
class GazeboProperties:
    """Simple children of a ``<gazebo reference=...>`` block (``mu1``, ``material``)."""

    reference: str
    properties: tuple[Param, ...]


@dataclass(frozen=True)
class PluginsInfo:
    """Everything that plugs the description into a simulator or a controller manager."""

    gazebo: tuple[PluginInfo, ...]
    ros2_control: tuple[HardwareInfo, ...]
    gazebo_properties: tuple[GazeboProperties, ...]


def _params(pairs: tuple[tuple[str, str], ...]) -> tuple[Param, ...]:
    return tuple(Param(k, v) for k, v in pairs)


def _plugin(plugin: Plugin, attached_to: str) -> PluginInfo:
    return PluginInfo(plugin.name, plugin.filename, attached_to, _params(plugin.params),
                      plugin.ros2_file)


def plugins_info(gazebo: tuple[GazeboBlock, ...], sensors: tuple[Sensor, ...],
                 systems: tuple[Ros2Control, ...]) -> PluginsInfo:
    """The plugins of a description, in document order."""
    model_level = [_plugin(p, "model" if block.reference is None else f"link {block.reference}")
                   for block in gazebo for p in block.plugins]
    in_sensors = [_plugin(p, f"sensor {s.name}") for s in sensors for p in s.plugins]
    hardware = tuple(HardwareInfo(s.name, s.type, s.plugin, _params(s.hardware_params))
                     for s in systems)
    properties = tuple(GazeboProperties(block.reference, _params(block.properties))
                       for block in gazebo if block.reference is not None and block.properties)
    return PluginsInfo(tuple(model_level + in_sensors), hardware, properties)
