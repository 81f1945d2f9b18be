"""``servicebot drive``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def drive(robot_args: RobotArgs) -> None:
    """Stream commands to the real motors over serial (not available yet)."""
    pending("drive", robot_args)
