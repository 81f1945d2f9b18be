"""The model rule: the Pinocchio model every command uses builds (SB701)."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.forked import WorkerEnded
from servicebot_cli.description.model import vector_with_other_blanks

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
        piece = vector_with_other_blanks(text)
        if piece is None:
            yield Issue("SB701", text, robot.root)
            return
        # the parser here reads a tab in an attribute as a space, as XML says; urdfdom's does not
        as_read = re.sub(r"\r\n|[\t\n\r]", " ", piece)
        element = next((element for element in robot.root.iter()
                        if any(as_read in value for value in element.attrib.values())),
                       robot.root)
        yield Issue("SB701", text, element, fix="put spaces between the numbers")


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
