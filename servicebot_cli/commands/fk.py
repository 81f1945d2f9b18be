"""``servicebot fk``: where frames are for given joint values."""

from __future__ import annotations

from typing import Literal

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import (
    batch_options,
    clamp_option,
    deg_option,
    echo_notes,
    format_option,
    refuse_format_with_file,
    warn,
)
from servicebot_cli.commands.options import (
    FrameName,
    JointValue,
    Number,
    RobotArgs,
    refuse_with,
    refuse_without,
    robot_arguments,
)

MOST_BASE_M = 1e6
"""How far from the origin ``--base`` may stand, as ik's targets may [m]."""

@click.command(cls=Command)
@robot_arguments()
@click.option("-j", "--joint", "joints", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="A joint's value [rad, or deg with --deg; m for prismatic joints] "
              "(repeatable; unnamed joints stay at zero, and a <mimic> joint follows its "
              "leader unless given).")
@click.option("-f", "--frame", "frames", type=FrameName(), multiple=True, metavar="FRAME",
              help="A frame (link) to place (repeatable; default: the arm's tool frame).")
@click.option("--relative-to", type=FrameName(), metavar="FRAME", default=None,
              help="Express poses in this frame (default: the root link).")
@click.option("--all-frames", is_flag=True, help="Every link and fixed frame, as one table.")
@click.option("--base", nargs=3, type=Number(), metavar="X Y YAW", default=None,
              help="Where the mobile base stands in the world: x, y [m] and yaw [rad, or deg "
              "with --deg]; poses are then in the world frame.")
@deg_option
@clamp_option
@batch_options("--configs", help="Batch: one configuration per line (CSV with a header of "
               "joint names, or JSON Lines of {name: value}; - for stdin); one pose line per "
               "input line.")
@format_option
@click.pass_context
def fk(ctx: click.Context, robot_args: RobotArgs, joints: tuple[tuple[str, float], ...],
       frames: tuple[str, ...], relative_to: str | None, all_frames: bool,
       base: tuple[float, float, float] | None, deg: bool,
       clamp: bool, configs: str | None, output: str | None,
       on_error: Literal["stop", "skip"], fmt: str) -> None:
    """Forward kinematics: the pose of frames for given joint values.

    Prints position [m], roll-pitch-yaw (URDF convention: fixed axes X, Y, Z), the
    quaternion (x y z w) and the 4x4 matrix of each frame, in the root link's frame
    unless --relative-to says otherwise. Continuous joints take an angle like any other.

    \b
    Examples:
      servicebot fk -j arm_link1_to_link2=0.5 -j arm_link2_to_link3=-0.3
      servicebot fk --deg -j arm_base_to_link1=45 --frame arm_link4 --format json
      servicebot fk --all-frames --relative-to arm_base_link
      servicebot fk --base 2.0 1.0 90 --deg -j arm_base_to_link1=30
      servicebot fk --configs configs.csv -o poses.jsonl
    """
    if all_frames and frames:
        raise click.UsageError("give --frame or --all-frames, not both")
    if configs is not None and joints:
        raise click.UsageError("give --joint values or a --configs file, not both")
    for option in ("--output", "--on-error"):
        refuse_without(ctx, option, "--configs FILE", present=configs is not None)
    refuse_without(ctx, "--clamp", "--joint NAME=VALUE or --configs FILE",
                   present=bool(joints) or configs is not None)
    refuse_format_with_file(ctx, output)
    refuse_with(ctx, "--base", "--relative-to", present=relative_to is not None,
                why="where the robot stands cancels out between two of its frames")
    from servicebot_cli.kinematics.fk import FrameQuery

    if base is not None and max(abs(base[0]), abs(base[1])) > MOST_BASE_M:
        raise click.BadParameter(f"x and y are metres within +-{MOST_BASE_M:g} (a double "
                                 "that far out has no room left for the arm's millimetres)",
                                 param_hint="--base")
    query = FrameQuery(robot_args.source(), frames, all_frames, relative_to, deg, clamp, base)
    if configs is None:
        from servicebot_cli.kinematics.fk import FkRequest, run
        from servicebot_cli.output.poses import fk_output

        result = run(FkRequest(query, joints))
        echo_notes(result.notes)
        click.echo(fk_output(result, fmt), nl=False)
        return
    from servicebot_cli.batch import fk as batch
    from servicebot_cli.output.batch_rows import RowFile

    batch.run(batch.FkBatchRequest(query, configs, on_error), RowFile(output, fmt), warn=warn)
