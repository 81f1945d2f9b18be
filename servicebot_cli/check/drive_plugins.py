"""SB516: a Gazebo diff-drive plugin's wheel numbers against the URDF's wheels.

The plugin makes wheel speeds from its own separation and radius (written, or its defaults:
:mod:`~servicebot_cli.description.drive_plugin_wheels`) and the URDF's wheels roll the robot:
other numbers drive it at another speed and turn rate than commanded, and its encoder
odometry drifts. Measured as a diff_drive_controller's are (:mod:`.wheel_numbers`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.check.wheel_numbers import driven, mismatch
from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.drive_plugin_wheels import PluginValue, plugin_wheels

if TYPE_CHECKING:
    from servicebot_cli.description.extensions import Plugin
    from servicebot_cli.description.robot import RobotDescription
    from servicebot_cli.kinematics.drive_geometry import DriveGeometry
    from servicebot_cli.kinematics.mesh_wheels import MeshPoints

_WHEEL_KEYS = ("left_joint", "right_joint", "leftJoint", "rightJoint")


def check(robot: RobotDescription, meshes: MeshPoints | None = None) -> Iterator[Issue]:
    """SB516 for each diff-drive plugin whose wheel numbers are not the URDF's wheels'.

    ``meshes``: the vertices of mesh shapes (wheels drawn as meshes are where those are).
    """
    plugins = [(p, numbers) for p in robot.model_plugins
               if (numbers := plugin_wheels(p)) is not None]
    if not plugins:
        return
    from servicebot_cli.kinematics.drive_geometry import drive_geometry

    try:
        geometry = drive_geometry(robot, meshes)
    except DescriptionError:  # no wheels on both sides: inspect and simulate say why
        return
    for plugin, numbers in plugins:
        radius_m, track_m, skid = _driven(plugin, geometry)
        yield from _judged(plugin, numbers.separation, track_m, "apart", skid)
        yield from _judged(plugin, numbers.radius, radius_m, "radius", False)


def _driven(plugin: Plugin, geometry: DriveGeometry) -> tuple[float, float, bool]:
    """Radius and track of the wheels the plugin drives, and whether they skid as it turns.

    The wheels it names; all the URDF's drive wheels where it names none on a side. Two or
    more a side skid.
    """
    radius_m, track, wheels = driven(
        geometry, {value for key, value in plugin.params if key in _WHEEL_KEYS})
    return radius_m, track, min(sum(w.side == side for w in wheels)
                                for side in ("left", "right")) >= 2


def _judged(plugin: Plugin, number: PluginValue, expected_m: float, measure: str,
            skid: bool) -> Iterator[Issue]:
    known = number.known_m
    element = plugin.element.find(number.key) if plugin.element is not None else None
    if known is None and number.given:  # "abc", "nan", "": sdformat cannot convert it
        yield Issue("SB516", f"Gazebo plugin '{plugin.filename or plugin.name}': "
                    f"<{number.key}>{number.text}</{number.key}> is no number: sdformat cannot "
                    "convert it, and the plugin makes wheel speeds with a value that is not "
                    "the wheels'", element if element is not None else plugin.element,
                    fix=f"<{number.key}>{_shown(number, expected_m)}</{number.key}>")
        return
    if known is None or math.isnan(expected_m):
        return  # a default not known here; mesh wheels that are not round: no radius known
    diameter = number.key.lower().endswith("diameter")
    value_m, expected_shown = ((2 * known, 2 * expected_m) if diameter
                               else (known, expected_m))
    off = mismatch((value_m,), expected_shown, skid)
    if off is None:
        return
    urdf = (f"the URDF's wheels are {expected_shown:.6g} m apart" if measure == "apart" else
            f"the URDF's wheel {'diameter' if diameter else 'radius'} is {expected_shown:.6g} m")
    said = (f"<{number.key}> {value_m:g} m" if number.given
            else f"<{number.key}> is not written: the plugin's default {value_m:g} m")
    effect = "turns at another rate" if measure == "apart" else "drives at another speed"
    yield Issue("SB516", f"Gazebo plugin '{plugin.filename or plugin.name}': {said}, where "
                f"{urdf}{off.purpose}: the robot {effect} than commanded, and its encoder "
                "odometry drifts", element if element is not None else plugin.element,
                fix=f"<{number.key}>{expected_shown:.6g}</{number.key}>",
                severity=off.severity)


def _shown(number: PluginValue, expected_m: float) -> str:
    """The URDF's value as the plugin's element writes it (a diameter is twice a radius)."""
    if math.isnan(expected_m):
        return "the wheels' diameter in metres" if number.key.lower().endswith("diameter") \
            else "the wheels' value in metres"
    return f"{2 * expected_m if number.key.lower().endswith('diameter') else expected_m:.6g}"
