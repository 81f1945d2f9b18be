"""The wheel geometry a Gazebo diff-drive plugin computes with: its parameters, or its defaults.

A diff-drive plugin turns a twist into wheel speeds with its own separation and radius
(gazebo_ros_pkgs' ``gazebo_ros_diff_drive.cpp``: ``vr +- va * wheel_separation / 2``, then
divided by ``wheel_diameter / 2``; gz-sim's ``DiffDrive.cc`` the same with ``wheel_radius``),
while the URDF's wheels carry the robot: numbers other than the URDF's make it drive and turn
other than commanded, as a diff_drive_controller's do.

- Gazebo Classic, ROS 2: ``<wheel_separation>`` (default 0.34 m) and ``<wheel_diameter>``
  (0.15 m); of several wheel pairs (``<num_wheel_pairs>``), the first pair's;
- Gazebo Classic, ROS 1: ``<wheelSeparation>`` and ``<wheelDiameter>``, the same defaults;
- gz-sim's DiffDrive: ``<wheel_separation>`` (1 m) and ``<wheel_radius>`` (0.2 m);
- the ROS 1 skid-steer drive: the same elements as the ROS 1 diff drive, with defaults of its
  own that are not read here (a number it does not write is unknown).

sdformat reads the first element of a name. Pure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from servicebot_cli.description.extensions import Plugin
from servicebot_cli.description.model_plugins import diff_drive_kind, ros1_plugin

_CLASSIC_DEFAULTS = (0.34, 0.15)  # separation, diameter [m]
_GZ_DEFAULTS = (1.0, 0.2)  # separation, radius [m]
_UNKNOWN_DEFAULTS = (None, None)
_OWN_DEFAULTS = "skid_steer"
"""The ROS 1 skid-steer drive's file name: defaults of its own, not read here."""


@dataclass(frozen=True)
class PluginValue:
    """One of the plugin's wheel numbers.

    Attributes:
        key: The element that sets it (``wheel_diameter`` for a radius from a diameter).
        value_m: The value in metres: a radius is half a diameter; NaN where the text is no
            number (an empty element too: sdformat converts its text); None where it is not
            written and the plugin's default is not known here.
        given: Written in the plugin; else the plugin's default.
    """

    key: str
    value_m: float | None
    given: bool
    text: str = ""

    @property
    def known_m(self) -> float | None:
        """The value the plugin drives with, when it is a number known here."""
        return self.value_m if self.value_m is not None and math.isfinite(self.value_m) \
            else None


@dataclass(frozen=True)
class PluginWheels:
    """The separation and radius a diff-drive plugin drives with."""

    separation: PluginValue
    radius: PluginValue


def plugin_wheels(plugin: Plugin) -> PluginWheels | None:
    """The wheel numbers of a diff-drive ``plugin``; None for any other plugin."""
    kind = diff_drive_kind(plugin)
    if kind is None:
        return None
    if kind == "gz":
        return PluginWheels(_value(plugin, "wheel_separation", _GZ_DEFAULTS[0]),
                            _value(plugin, "wheel_radius", _GZ_DEFAULTS[1]))
    ros1 = ros1_plugin(plugin)
    defaults = _UNKNOWN_DEFAULTS if _OWN_DEFAULTS in plugin.filename else _CLASSIC_DEFAULTS
    separation = _value(plugin, "wheelSeparation" if ros1 else "wheel_separation", defaults[0])
    diameter = _value(plugin, "wheelDiameter" if ros1 else "wheel_diameter", defaults[1])
    radius = None if diameter.value_m is None else diameter.value_m / 2.0
    return PluginWheels(separation, PluginValue(diameter.key, radius, diameter.given,
                                                diameter.text))


def _value(plugin: Plugin, key: str, default_m: float | None) -> PluginValue:
    text = next((value for path, value in plugin.params if path == key), None)
    if text is None:
        return PluginValue(key, default_m, False)
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    return PluginValue(key, value if math.isfinite(value) else math.nan, True, text.strip())
