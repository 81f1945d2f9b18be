"""Where a xacro description defines a link it did not expand: an optional part left out.

A ``<gazebo reference>`` may name a link that only a xacro condition not taken creates
(unitree's a1 ``stick_link`` under ``rolloverProtection``, off by default) or that an
include the robot's options leave out adds (warthog's ``bulkhead_link`` from
``accessories/warthog_bulkhead.urdf.xacro`` with ``WARTHOG_BULKHEAD`` set). Gazebo then
ignores the block, as its author meant. This finds such definitions in the robot's own
sources: the files the expansion read, and those their ``<xacro:include>`` elements name,
taken or not (another robot of the package is not this robot's part). A definition is a
``<link>`` or a ``<joint>`` with a ``type``: ``<ros2_control>`` and ``<transmission>`` name
joints without one.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.files import included_files
from servicebot_cli.common.inputs import display_path
from servicebot_cli.description.loader import comments_blanked

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_DEFINITION = re.compile(rb"<(link|joint)\b([^>]*)>")
_NAME = re.compile(rb"\bname\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_TYPE = re.compile(rb"\btype\s*=")
_HEAD_BYTES = 1 << 20


def defined_elsewhere(robot: RobotDescription,
                      names: Collection[str]) -> dict[str, tuple[str, int, str]]:
    """For each of ``names`` the robot's sources define: the file, line and kind.

    Kind is ``link`` or ``joint``. Nothing for a description that is not expanded from
    xacro, whose file is all there is.
    """
    if not robot.expanded or not names:
        return {}
    wanted = {name.encode(): name for name in names}
    found: dict[str, tuple[str, int, str]] = {}
    for path in included_files([Path(file) for file in robot.files]):
        try:
            with path.open("rb") as handle:
                text = comments_blanked(handle.read(_HEAD_BYTES))
        except OSError:
            continue
        for match in _DEFINITION.finditer(text):
            named = _NAME.search(match[2])
            name = wanted.get(named[1] if named[1] is not None else named[2]) if named else None
            if name is None or name in found or (match[1] == b"joint"
                                                 and not _TYPE.search(match[2])):
                continue
            line = text.count(b"\n", 0, match.start()) + 1
            found[name] = (display_path(path), line, match[1].decode())
        if len(found) == len(wanted):
            break
    return found

