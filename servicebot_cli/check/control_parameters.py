"""SB521: a ros2_control Gazebo plugin's ``<parameters>`` file that does not exist.

gazebo_ros2_control and gz_ros2_control hand every ``<parameters>`` of their plugin to the
controller manager as ``--params-file FILE`` (:mod:`~servicebot_cli.description.
parameter_files`); rcl refuses a file it cannot open ("Couldn't parse params file"), the
controller manager does not start, and no controller runs: the robot spawns and never moves.
A relative path (Gazebo reads it from its own working directory) that is not beside the
description is a warning. A path is taken as the simulator and ``inspect`` take it:
relative to the description,
``file://`` and ``~`` read, a value still holding a launch substitution ``$(...)`` left
alone; a file that only a CMake ``install(DIRECTORY)`` puts there is found in the sources
(:mod:`~servicebot_cli.description.install_layout`). Reads nothing but the file system's
entries and CMakeLists.txt.
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.description.install_layout import installed_source
from servicebot_cli.description.parameter_files import is_ros2_control_plugin

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def check(robot: RobotDescription) -> Iterator[Issue]:
    """SB521 for each ``<parameters>`` of a ros2_control plugin that names no file."""
    for plugin in robot.plugins:
        if not is_ros2_control_plugin(plugin) or plugin.element is None:
            continue
        for element in plugin.element.iter("parameters"):
            text = (element.text or "").strip()
            if not text or "$(" in text:
                continue
            named = Path(text.removeprefix("file://")).expanduser()
            path = Path(os.path.normpath(named if named.is_absolute()
                                         else robot.path.parent / named))
            if os.path.isfile(installed_source(str(path))):  # once installed, if not here
                continue
            what = "is a directory" if os.path.isdir(path) else "does not exist"
            said = (f"plugin '{plugin.filename or plugin.name}': <parameters> names {path}, "
                    f"which {what}: the controller manager gets it as --params-file, rcl "
                    "refuses it ('Couldn't parse params file') and no controller starts")
            if named.is_absolute():
                yield Issue("SB521", said, element, fix=_fix(path))
            else:  # Gazebo reads it from its working directory, which may hold it
                yield Issue("SB521", f"{said}, unless Gazebo runs where '{named}' is",
                            element, severity=Severity.WARNING,
                            fix="write it as $(find PKG)/..., which does not depend on where "
                            "Gazebo runs")


def _fix(path: Path) -> str:
    """Name a YAML file beside the missing one whose name is close, else say what to write."""
    try:
        beside = [p.name for p in path.parent.iterdir()
                  if p.suffix in (".yaml", ".yml") and p.is_file()]
    except OSError:
        beside = []
    close = difflib.get_close_matches(path.name, beside, n=1, cutoff=0.8)
    if close:
        return f"did you mean {path.parent / close[0]}?"
    return ("name the controllers YAML the robot is controlled with ($(find PKG)/config/"
            "FILE.yaml in a xacro file)")
