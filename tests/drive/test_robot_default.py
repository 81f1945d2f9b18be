"""robot_arguments(default=...): a command may talk to another bundled robot by default."""

from __future__ import annotations

import click
from click.testing import CliRunner

from servicebot_cli.commands.options import RobotArgs, robot_arguments


@click.command()
@robot_arguments(default="real")
def probe(robot_args: RobotArgs) -> None:
    click.echo(robot_args.source().path.name)


def test_the_default_robot_is_the_commands_choice():
    runner = CliRunner()
    assert runner.invoke(probe, []).stdout.strip() == "service_robot_real.urdf.xml"
    assert runner.invoke(probe, ["--robot", "sim"]).stdout.strip() == "service_robot.urdf.xml"
    help_text = " ".join(runner.invoke(probe, ["--help"]).stdout.split())
    assert "default: real when no FILE is given" in help_text


def test_every_other_command_keeps_sim(run):
    assert "default: sim when no FILE" in " ".join(run("fk", "--help").stdout.split())
