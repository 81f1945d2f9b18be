"""``servicebot simulate``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def simulate(robot_args: RobotArgs) -> None:
    """Run the headless kinematic simulator (not available yet)."""
    pending("simulate", robot_args)
