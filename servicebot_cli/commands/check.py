"""``servicebot check``: validate URDF and xacro files, and controller configurations, for CI.

``check urdf [FILE|DIR]...`` and ``check controllers [YAML]``; ``check FILE...`` is short for
``check urdf FILE...``. Only Click and the light catalogue are imported here; the rules,
numpy and Pinocchio load inside the callbacks.
"""

from __future__ import annotations

from typing import Any

import click

from servicebot_cli.commands.check_options import catalogue_options, report_options
from servicebot_cli.commands.command import Command, Group
from servicebot_cli.commands.options import BundledRobot, PackageDir, RobotArgs, robot_arguments

_GROUP_ONLY = ("-h", "--help", "--list-rules", "--explain")


class CheckGroup(Group):
    """``check`` whose first argument, when not a subcommand, is the start of ``check urdf``."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Route ``check [FILE]... [OPTIONS]`` to ``check urdf``."""
        first = args[0] if args else ""
        if first not in self.commands and first.split("=")[0] not in _GROUP_ONLY:
            args = ["urdf", *args]
        return super().parse_args(ctx, args)

    def format_help(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        """The usage and options of ``check urdf``, then the subcommands."""
        urdf_command = self.commands["urdf"]
        with click.Context(urdf_command, info_name=ctx.info_name, parent=ctx.parent) as sub:
            formatter.write_usage(ctx.command_path,
                                  "[urdf|controllers] [OPTIONS] [FILE|DIR]... [NAME:=VALUE]...")
            self.format_help_text(ctx, formatter)
            urdf_command.format_options(sub, formatter)
        self.format_commands(ctx, formatter)


@click.group(cls=CheckGroup, context_settings={"help_option_names": ["-h", "--help"]})
@catalogue_options
def check() -> None:
    """Validate URDF and xacro files and controller configurations, for people and CI.

    `servicebot check urdf` checks the bundled robot; `servicebot check urdf FILE|DIR...`
    checks files and directories (*.urdf, *.urdf.xml, *.xacro), with xacro arguments
    NAME:=VALUE; `servicebot check FILE...` does the same. `servicebot check controllers
    [YAML]` checks a ros2_control controllers file against the URDF.

    \b
    Exit codes: 0 clean, 1 findings at the failing level (errors; warnings too with
    --strict), 2 bad usage or unreadable input, 3 internal error.
    Silence one rule on one element with <!-- servicebot: ignore SB301 --> just before it.
    """


@check.command("urdf", cls=Command)
@robot_arguments(multiple=True)
@report_options
@catalogue_options
def urdf(robot_args: RobotArgs, **report: Any) -> None:
    """Check URDF and xacro files and directories (default: the bundled robot).

    \b
    Examples:
      servicebot check urdf
      servicebot check urdf robots/ --strict --format github
      servicebot check urdf my_robot.urdf.xacro use_gripper:=true --format sarif -o check.sarif
    """
    from servicebot_cli.commands import check_run

    settings = check_run.settings_for(report)
    result = check_run.check_urdf_files(robot_args, settings)
    check_run.emit(result, report["fmt"], report["output"])


@check.command("controllers", cls=Command)
@click.argument("values", nargs=-1, metavar="[YAML] [NAME:=VALUE]...")
@click.option("--urdf", "urdfs", multiple=True, type=click.Path(dir_okay=False),
              help="Check against this URDF or xacro (repeatable; default: both bundled robots).")
@click.option("--robot", "bundled", type=BundledRobot(), default=None,
              help="Check against one bundled robot (sim or real) instead of both.")
@click.option("--package", "packages", type=PackageDir(), multiple=True, metavar="NAME=DIR",
              help="Where ROS package NAME lives, for the URDF's $(find) and package://.")
@report_options
@catalogue_options
def controllers(values: tuple[str, ...], urdfs: tuple[str, ...], bundled: str | None,
                packages: tuple[tuple[str, str], ...], **report: Any) -> None:
    """Check a ros2_control controllers YAML against the URDF (default: the bundled pair).

    Joint names in left_wheel_names, right_wheel_names and joints must exist and move;
    wheel_radius and wheel_separation must agree with the URDF's wheels.

    \b
    Examples:
      servicebot check controllers
      servicebot check controllers config/controllers.yaml --urdf my_robot.urdf.xacro
    """
    from servicebot_cli.commands import check_run

    settings = check_run.settings_for(report)
    result = check_run.check_controller_files(values, urdfs, bundled, packages, settings)
    check_run.emit(result, report["fmt"], report["output"])
