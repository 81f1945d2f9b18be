"""``servicebot expand``: xacro to URDF, with no ROS installed."""

from __future__ import annotations

from typing import TYPE_CHECKING

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import (
    OutputPath,
    RobotArgs,
    refuse_overwriting,
    refuse_without,
    robot_arguments,
)

if TYPE_CHECKING:
    from collections.abc import Iterable

    from servicebot_cli.description.load_warnings import LoadWarning, Said

URDF_SUFFIXES = (".urdf", ".xml")
"""What ``-o`` may be called: ``robot.urdf``, ``robot.urdf.xml`` (as the bundled ones), ``.xml``."""


_SAID: dict[Said, tuple[str, str]] = {
    "warning": ("warning: ", ""), "error": ("warning: ", "the file's xacro.error(): "),
    "message": ("", ""), "package": ("warning: ", ""), "installed": ("warning: ", "")}
"""How each kind of thing xacro printed is shown, before and after its place: a file's
messages as they are."""


def _show(warnings: Iterable[LoadWarning]) -> None:
    """Each warning on stderr as xacro shows it: a file's messages bare."""
    for warning in warnings:
        fix = f"; {warning.fix}" if warning.fix else ""
        click.echo(f"{_SAID[warning.said_as][0]}{warning.where}{_SAID[warning.said_as][1]}"
                   f"{warning.text}{fix}", err=True)


@click.command(cls=Command)
@robot_arguments()
@click.option("-o", "--output",
              type=OutputPath(URDF_SUFFIXES, allow_dash=True, what="URDF", parents=True),
              default="-", metavar="FILE.urdf",
              help="Write the URDF here (.urdf or .xml, atomically) instead of to stdout; "
              "missing directories are created, as xacro -o does.")
@click.option("--inorder", "-i", "inorder", is_flag=True, hidden=True,
              help="xacro's --inorder, the default since ROS Melodic: accepted, with a note.")
@click.pass_context
def expand(ctx: click.Context, robot_args: RobotArgs, output: str, inorder: bool) -> None:
    """Expand a xacro file into URDF.

    Without FILE, expands the bundled robot's xacro source into exactly the bundled
    simulation URDF, or with --robot real (hardware:=real) the real one. $(find PKG) and
    package://PKG resolve through --package, ROS_PACKAGE_PATH and AMENT_PREFIX_PATH.

    \b
    Examples:
      servicebot expand robots/service_robot.urdf.xacro hardware:=real -o real.urdf
      servicebot expand my_robot.urdf.xacro --package my_robot_description=./src/desc
    """
    from servicebot_cli.common.errors import DescriptionError
    from servicebot_cli.common.files import write_atomic
    from servicebot_cli.description.load_warnings import LoadWarning
    from servicebot_cli.description.loader import RobotSource, read_description
    from servicebot_cli.description.resources import DEFAULT_ROBOT, XACRO_SOURCE, bundled_file

    if inorder:  # old launch files and Makefiles still pass it to xacro, which takes it
        click.echo("note: in-order processing is xacro's only one since ROS Melodic: "
                   "--inorder can be dropped", err=True)
    refuse_without(ctx, "--package", "a xacro FILE", name="packages",
                   present=bool(robot_args.files))
    refuse_overwriting(output, robot_args.files)
    if robot_args.files:
        source = robot_args.source()
    else:
        args = dict(robot_args.xacro_args)
        if robot_args.bundled and "hardware" in args:
            raise click.UsageError(f"give hardware:={args['hardware']} or --robot "
                                   f"{robot_args.bundled}, not both")
        args.setdefault("hardware", robot_args.bundled or DEFAULT_ROBOT)
        path = bundled_file(XACRO_SOURCE)
        source = RobotSource(path, str(path), tuple(args.items()), robot_args.packages)
    try:
        robot = read_description(source)
    except DescriptionError as exc:  # what xacro said before failing, as xacro shows it
        _show(w for w in exc.said_before if isinstance(w, LoadWarning))
        raise
    _show(robot.warnings)
    if output == "-":
        click.echo(robot.xml_text, nl=False)
    else:
        refuse_overwriting(output, robot.files)  # an include, too, is a source to keep
        write_atomic(output, robot.xml_text, make_parents=True)
