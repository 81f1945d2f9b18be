"""``servicebot check``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def check(robot_args: RobotArgs) -> None:
    """Validate a URDF or xacro file for CI (not available yet)."""
    pending("check", robot_args)
