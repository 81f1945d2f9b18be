"""Options that ``fk`` and ``ik`` share, and how both pick their frame. Light: click only."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import click

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

F = TypeVar("F", bound=Callable[..., Any])

deg_option = click.option(
    "--deg", is_flag=True,
    help="Angles in degrees, in and out (joint values, roll-pitch-yaw); prismatic joints "
    "stay in metres.",
)
clamp_option = click.option(
    "--clamp", is_flag=True,
    help="Clamp joint values outside their limits instead of refusing them.",
)
def batch_options(flag: str, help: str) -> Callable[[F], F]:
    """The batch input option ``flag`` (a file, ``-`` for stdin), ``--output``, ``--on-error``."""

    def decorate(f: F) -> F:
        f = click.option(
            "--on-error", type=click.Choice(["stop", "skip"]), default="stop",
            show_default=True,
            help="A bad batch line: stop with its line number (exit 2, no output file), or "
            "skip it, say so on stderr, and go on.",
        )(f)
        f = click.option(
            "-o", "--output", type=click.Path(dir_okay=False, allow_dash=True), default=None,
            help="Batch results to this file, written atomically (.csv or .jsonl; default "
            "stdout: CSV with --format text, JSON Lines with --format json).",
        )(f)
        return click.option(flag, type=click.Path(dir_okay=False, allow_dash=True),
                            default=None, help=help)(f)

    return decorate


def pick_frame(robot: RobotDescription, name: str | None) -> str:
    """``name`` if it is a frame of ``robot``; without one, the arm's tool frame.

    When the tool frame is chosen by its place in the tree rather than its name, a note on
    stderr says which frame it is.

    Raises:
        FrameNotFound: ``name`` is not a link, with the nearest names.
    """
    from servicebot_cli.kinematics.frames import default_tool_frame, frame_id, link_names

    if name is not None:
        frame_id(robot.model, name, link_names(robot))
        return name
    choice = default_tool_frame(robot)
    if not choice.obvious:
        click.echo(f"note: no --frame given; using '{choice.name}', the tip of the longest "
                   f"chain ({choice.joints} joints)", err=True)
    return choice.name
