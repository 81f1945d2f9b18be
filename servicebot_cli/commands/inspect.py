"""``servicebot inspect``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def inspect(robot_args: RobotArgs) -> None:
    """Show what a robot description holds (not available yet)."""
    pending("inspect", robot_args)
