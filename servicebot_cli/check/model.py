"""The model rule: the Pinocchio model every command uses builds (SB701)."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.check.syntax import vectors_split_wrong
from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.forked import WorkerEnded
from servicebot_cli.description.model import refused_for_blanks

if TYPE_CHECKING:
    from servicebot_cli.check.model_ahead import ModelAhead
    from servicebot_cli.description.robot import RobotDescription

_HINT = re.compile(r"\s*\(run 'servicebot check [^)]*\) for details\)\s*$|\s*\(run 'servicebot "
                   r"check .*$")


def check(robot: RobotDescription, ahead: ModelAhead | None = None) -> Iterator[Issue]:
    """Build the fixed-base model; report what Pinocchio (and urdfdom below it) says.

    With ``ahead``, the verdict of the child building it meanwhile (built here if it gave none).
    """
    refused = _refusal(robot, ahead)
    if refused is not None:
        text = _HINT.sub("", refused.removeprefix(f"{robot.display}: "))
        if not refused_for_blanks(text):
            yield Issue("SB701", text, robot.root)
            return
        # the XML parser here reads a written tab as a space, as XML says; urdfdom's does not:
        # the file's text says where (SB013's own search, when that rule is not selected)
        found = None if robot.expanded else next(
            iter(vectors_split_wrong(robot.xml_text, robot.display)), None)
        yield Issue("SB701", text, None if found else robot.root,
                    where=found.where if found else None, fix="put spaces between the numbers")


def _refusal(robot: RobotDescription, ahead: ModelAhead | None) -> str | None:
    """Pinocchio's error line for ``robot``, or None when it builds the model."""
    if ahead is not None:
        try:
            return ahead.result()
        except WorkerEnded:  # no verdict came: built here, as a serial run does
            pass
        finally:
            ahead.close()
    try:
        robot.pinocchio_model()  # building is the check; what else refuses it, rules report
    except DescriptionError as exc:
        return str(exc)
    return None
