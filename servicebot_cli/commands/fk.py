"""``servicebot fk``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def fk(robot_args: RobotArgs) -> None:
    """Forward kinematics: the pose of any frame (not available yet)."""
    pending("fk", robot_args)
