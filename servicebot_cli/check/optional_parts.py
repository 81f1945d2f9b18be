"""Where a xacro description defines a link it did not expand: an optional part left out.

A ``<gazebo reference>`` may name a link that only a xacro condition not taken creates
(unitree's a1 ``stick_link`` under ``rolloverProtection``, off by default) or that an
include the robot's options leave out adds (warthog's ``bulkhead_link`` from
``accessories/warthog_bulkhead.urdf.xacro`` with ``WARTHOG_BULKHEAD`` set). Gazebo then
ignores the block, as its author meant. This finds such a definition: in the files the
expansion read, then in the other robot files of their packages.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.files import head_without_comments, robot_files
from servicebot_cli.common.inputs import display_path
from servicebot_cli.description.package_dirs import holding_package

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_MOST_FILES = 2000  # a package's robot files searched at most


def defined_elsewhere(robot: RobotDescription, name: str) -> tuple[str, int, str] | None:
    """The file, line and kind (``link`` or ``joint``) that define ``name`` in the sources.

    None when no read file or robot file of their packages defines it with that literal
    name, or for a description that is not expanded from xacro.
    """
    if not robot.expanded:
        return None
    pattern = re.compile(rb"<(link|joint)\b[^>]*?\bname\s*=\s*[\"']" + re.escape(name.encode())
                         + rb"[\"']")
    for path in _candidates(robot):
        text = head_without_comments(path)
        match = pattern.search(text) if text is not None else None
        if text is not None and match is not None:
            line = text.count(b"\n", 0, match.start()) + 1
            return display_path(path), line, match[1].decode()
    return None


def _candidates(robot: RobotDescription) -> list[Path]:
    """The files the expansion read, then the other robot files of their packages."""
    read = [Path(file) for file in robot.files]
    seen = {path.absolute() for path in read}
    packages = {holder[1] for path in read
                if (holder := holding_package(path.absolute().parent)) is not None}
    more: list[Path] = []
    for directory in sorted(packages):
        for path in robot_files(directory):
            if path.absolute() not in seen and len(more) < _MOST_FILES:
                seen.add(path.absolute())
                more.append(path)
    return read + more
