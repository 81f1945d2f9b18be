"""``servicebot ik``."""

from __future__ import annotations

import click

from servicebot_cli.commands._pending import pending
from servicebot_cli.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments()
def ik(robot_args: RobotArgs) -> None:
    """Inverse kinematics: joint values that reach a target (not available yet)."""
    pending("ik", robot_args)
