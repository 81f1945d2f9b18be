"""SB521: a ros2_control Gazebo plugin's ``<parameters>`` file that does not exist.

gazebo_ros2_control and gz_ros2_control hand every ``<parameters>`` of their plugin to the
controller manager as ``--params-file FILE`` (:mod:`~servicebot_cli.description.
parameter_files`); rcl refuses a file it cannot open ("Couldn't parse params file"), the
controller manager does not start, and no controller runs: the robot spawns and never moves.

rcl opens the text as a path: ``file://`` and ``~`` are not read, and are errors. A value
still holding a launch substitution ``$(...)`` is left to the launch file. An absolute path
(what ``$(find PKG)/...`` expands to) passes where the file is, or where the package's install
rules put it: its ``install(DIRECTORY)`` source, or a file of its name anywhere in the
package's sources. A relative path is taken from the description's directory, as the
simulator and ``inspect`` take it, and is a warning where it is not there (Gazebo reads it
from its own working directory). Reads nothing but the file system's entries and
CMakeLists.txt.
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.description.install_layout import installed_source
from servicebot_cli.description.parameter_files import is_ros2_control_plugin, written_path

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription


def check(robot: RobotDescription) -> Iterator[Issue]:
    """SB521 for each ``<parameters>`` of a ros2_control plugin that names no file."""
    for plugin in robot.plugins:
        if not is_ros2_control_plugin(plugin) or plugin.element is None:
            continue
        for element in plugin.element.iter("parameters"):
            named = written_path(element.text)
            if named is None:
                continue
            text = (element.text or "").strip()
            path = Path(os.path.normpath(named if named.is_absolute()
                                         else robot.path.parent / named))
            if text.startswith(("file://", "~")):  # rcl opens the text as written
                shown = "file://" if text.startswith("file://") else "~"
                yield Issue("SB521", f"plugin '{plugin.filename or plugin.name}': <parameters> "
                            f"{text} starts with '{shown}', which rcl does not read: it opens "
                            "the text as a path ('Couldn't parse params file'), and no "
                            "controller starts", element, fix=f"write the path itself: {path}"
                            if os.path.isfile(path) else "write the path itself, as "
                            "$(find PKG)/... in a xacro file")
                continue
            if os.path.isfile(installed_source(str(path))) or (
                    named.is_absolute() and _in_package(path)):
                continue  # here, or put here by the package's install rules
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


_MOST_FILES = 20_000  # a package's files looked through for one of a missing file's name


def _in_package(path: Path) -> bool:
    """Whether the package ``path`` is in holds a file of its name elsewhere in its sources.

    Install rules put files where ``$(find PKG)/...`` names them: CMake's install(FILES) or
    install(DIRECTORY) from another directory, or a setup.py's data_files; checked from
    sources, such a file is somewhere in the package under its own name.
    """
    holder = next((parent for parent in path.parents if (parent / "package.xml").is_file()),
                  None)
    if holder is None:
        return False
    seen = 0
    for _, subdirectories, files in os.walk(holder):
        subdirectories[:] = [d for d in subdirectories if not d.startswith((".", "build"))]
        if path.name in files:
            return True
        seen += len(files)
        if seen > _MOST_FILES:
            return False
    return False


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
