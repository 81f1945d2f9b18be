"""``servicebot check``: validate URDF and xacro files, and controller configurations, for CI.

``check urdf [FILE|DIR]...`` and ``check controllers [YAML]``; ``check FILE...`` is short for
``check urdf FILE...``. Each subcommand turns its options into a
:class:`~servicebot_cli.check.run.CheckRequest`, calls :func:`servicebot_cli.check.run.run`
and hands the result to ``output/findings``. Only Click and the light catalogue are imported
here; the rules, numpy and Pinocchio load inside the callbacks.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import click

from servicebot_cli.commands.check_options import (
    ReportOptions,
    catalogue_options,
    comma_separated,
    refuse_catalogue_mix,
    report_options,
    settings_path,
)
from servicebot_cli.commands.command import Command, Group
from servicebot_cli.commands.options import (
    BundledRobot,
    PackageDir,
    RobotArgs,
    distinct_packages,
    refuse_overwriting,
    refuse_without,
    robot_arguments,
    split_robot_args,
)
from servicebot_cli.common.blas_threads import use_one_blas_thread

if TYPE_CHECKING:
    from servicebot_cli.check.run import CheckRequest, SettingsChoice

_GROUP_ONLY = ("-h", "--help", "--list-rules", "--explain")


class CheckGroup(Group):
    """``check`` whose first argument, when not a subcommand, is the start of ``check urdf``."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Route ``check [FILE]... [OPTIONS]`` to ``check urdf``."""
        first = args[0] if args else ""
        if first not in self.commands and first.split("=")[0] not in _GROUP_ONLY:
            args = ["urdf", *args]
        if first.split("=")[0] in ("--list-rules", "--explain"):
            # what follows is check urdf's (a FILE, --format): said, not silently ignored
            refuse_catalogue_mix(self.commands["urdf"], ctx, args)
        refuse_catalogue_mix(self, ctx, args[: self._own_args(ctx, args)])
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


class CheckCommand(Command):
    """A ``check`` subcommand: ``--list-rules`` and ``--explain`` refuse company."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Refuse a catalogue option beside anything else, then parse as Command does."""
        refuse_catalogue_mix(self, ctx, args)
        return super().parse_args(ctx, args)


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
    use_one_blas_thread()  # before numpy loads: check's matrices are 3x3


@check.command("urdf", cls=CheckCommand)
@robot_arguments(multiple=True)
@click.option("-j", "--jobs", type=click.IntRange(min=1), default=None, metavar="N",
              help="Worker processes when several files are checked (default: one per "
              "available core; 1: none).")
@click.option("--mesh-cache", is_flag=True,
              help="Keep what was read of each mesh in the user's cache directory "
              "($XDG_CACHE_HOME/servicebot/meshes), keyed on path, size and time: later runs "
              "skip reading meshes that did not change.")
@click.option("--show-packages", is_flag=True,
              help="Text: list the packages each file uses, where and how each was found "
              "(--package, the package holding the file, the workspace, ROS_PACKAGE_PATH...).")
@report_options
@catalogue_options
def urdf(robot_args: RobotArgs, jobs: int | None, mesh_cache: bool, show_packages: bool,
         report: ReportOptions) -> None:
    """Check URDF and xacro files and directories (default: the bundled robot).

    \b
    Examples:
      servicebot check urdf
      servicebot check urdf robots/ --strict --format github
      servicebot check urdf my_robot.urdf.xacro use_gripper:=true --format sarif -o check.sarif
    """
    from servicebot_cli.check.run import CheckRequest, UrdfTargets

    if robot_args.files and robot_args.bundled:
        raise click.UsageError(f"give FILEs or --robot {robot_args.bundled}, not both")
    default = None if robot_args.files else robot_args.source()
    cache = None
    if mesh_cache:
        from servicebot_cli.check.mesh_store import default_directory

        cache = default_directory()
    _refuse_overwriting_inputs(report, robot_args.files)
    targets = UrdfTargets(robot_args.files, robot_args.xacro_args, robot_args.packages, default,
                          jobs, cache)
    _run(CheckRequest(targets, _settings(report)), report, show_packages)


@check.command("controllers", cls=CheckCommand)
@click.argument("values", nargs=-1, metavar="[YAML] [NAME:=VALUE]...")
@click.option("--urdf", "urdfs", multiple=True, type=click.Path(dir_okay=False),
              help="Check against this URDF or xacro (repeatable; default: both bundled robots).")
@click.option("--robot", "bundled", type=BundledRobot(), default=None,
              help="Check against one bundled robot (sim or real) instead of both.")
@click.option("--package", "packages", type=PackageDir(), multiple=True, metavar="NAME=DIR",
              callback=distinct_packages,
              help="Where ROS package NAME lives, for the --urdf file's $(find) and package://.")
@click.option("--spawned", "spawned", multiple=True, metavar="NAME[,NAME]",
              callback=comma_separated,
              help="Only these controllers (those your launch spawns; repeatable) are checked "
                   "against the robot: a file shared by several robots configures others.")
@report_options
@catalogue_options
@click.pass_context
def controllers(ctx: click.Context, values: tuple[str, ...], urdfs: tuple[str, ...],
                bundled: str | None, packages: tuple[tuple[str, str], ...],
                spawned: tuple[str, ...], report: ReportOptions) -> None:
    """Check a ros2_control controllers YAML against the URDF (default: the bundled pair).

    Without YAML, a --urdf robot's own: the file its Gazebo ros2_control plugin loads
    (<parameters>), else controllers.yaml beside it. A YAML without --urdf is checked
    against the bundled robots, and refused when it names none of their joints or belongs to
    a ROS package (give its robot, or --robot sim|real).

    Joint names in left_wheel_names, right_wheel_names and joints must exist and move;
    wheel_radius and wheel_separation must agree with the URDF's wheels.

    \b
    Examples:
      servicebot check controllers
      servicebot check controllers config/controllers.yaml --urdf my_robot.urdf.xacro
      servicebot check controllers config/controllers.yaml --urdf arm.urdf \\
          --spawned joint_state_broadcaster,arm_controller
    """
    from servicebot_cli.check.run import CheckRequest, ControllerTargets
    from servicebot_cli.description.loader import RobotSource

    yaml_files, xacro_args = split_robot_args(values)
    if len(yaml_files) > 1:
        raise click.UsageError(f"one controllers YAML at a time, got {len(yaml_files)}")
    if urdfs and bundled:
        raise click.UsageError(f"give --urdf or --robot {bundled}, not both")
    if xacro_args and not urdfs:
        raise click.UsageError("xacro arguments need a xacro --urdf FILE")
    refuse_without(ctx, "--package", "--urdf FILE", name="packages", present=bool(urdfs))
    sources = tuple(RobotSource.of(u, xacro_args=xacro_args, packages=packages) for u in urdfs)
    if bundled:
        sources = (RobotSource.bundled(bundled),)
    _refuse_overwriting_inputs(report, [*yaml_files, *urdfs])
    if ctx.get_parameter_source("spawned") is click.core.ParameterSource.COMMANDLINE \
            and not spawned:
        raise click.BadParameter("give the names of the controllers the launch spawns "
                                 "(comma-separated); without --spawned every one is checked",
                                 param_hint="'--spawned'")
    targets = ControllerTargets(yaml_files[0] if yaml_files else None, sources, spawned)
    _run(CheckRequest(targets, _settings(report)), report)


def _settings(report: ReportOptions) -> SettingsChoice:
    """The settings part of a request; ``--config`` and ``--isolated`` exclude each other."""
    from servicebot_cli.check.run import SettingsChoice

    if report.isolated and report.config:
        raise click.UsageError("--config has no effect with --isolated (which reads no "
                               "pyproject.toml); drop one of them")
    return SettingsChoice(report.select, report.ignore, report.strict, settings_path(report),
                          report.isolated)


def _refuse_overwriting_inputs(report: ReportOptions, named: Sequence[str]) -> None:
    """Refuse a report file that is a named input, or a robot file of a named directory."""
    output = report.output
    inputs = list(named)
    if output not in (None, "-") and os.path.isfile(Path(output)):
        from servicebot_cli.check.files import is_robot_file

        target = Path(output).resolve()
        if is_robot_file(target):
            inputs += [output for d in named if os.path.isdir(Path(d))
                       and Path(d).resolve() in target.parents]
    refuse_overwriting(output, inputs)


def _run(request: CheckRequest, report: ReportOptions, packages: bool = False) -> None:
    """Run the check, show the report; the answer is no (exit 1) when the run fails.

    ``packages``: the text report lists the packages each file uses.
    """
    from servicebot_cli.check.run import run
    from servicebot_cli.common.errors import AnswerIsNo
    from servicebot_cli.output.findings import show

    result = run(request)
    # the report replaces no file the run read: an include the named file pulled in
    refuse_overwriting(report.output, [f for r in result.reports for f in r.read])
    show(result, report.fmt, report.output, packages)
    if result.failed:
        raise AnswerIsNo("")  # the summary line already says so
