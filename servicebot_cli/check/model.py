"""The model rule: the Pinocchio model every command uses builds (SB701)."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import DescriptionError

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_HINT = re.compile(r"\s*\(run 'servicebot check [^)]*\) for details\)\s*$|\s*\(run 'servicebot "
                   r"check .*$")


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Build the fixed-base model; report what Pinocchio (and urdfdom below it) says."""
    try:
        robot.model  # noqa: B018 -- building is the check
    except DescriptionError as exc:
        text = str(exc).removeprefix(f"{robot.display}: ")
        yield Issue("SB701", _HINT.sub("", text), robot.root)
