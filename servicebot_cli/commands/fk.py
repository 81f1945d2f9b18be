"""``servicebot fk``: where frames are for given joint values."""

from __future__ import annotations

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import (
    batch_options,
    clamp_option,
    deg_option,
    pick_frame,
)
from servicebot_cli.commands.options import JointValue, RobotArgs, format_option, robot_arguments


@click.command(cls=Command)
@robot_arguments()
@click.option("-j", "--joint", "joints", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="A joint's value [rad, or deg with --deg; m for prismatic joints] "
              "(repeatable; unnamed joints stay at zero).")
@click.option("-f", "--frame", "frames", multiple=True, metavar="FRAME",
              help="A frame (link) to place (repeatable; default: the arm's tool frame).")
@click.option("--relative-to", metavar="FRAME", default=None,
              help="Express poses in this frame (default: the root link).")
@click.option("--all-frames", is_flag=True, help="Every link and fixed frame, as one table.")
@deg_option
@clamp_option
@batch_options("--configs", help="Batch: one configuration per line (CSV with a header of "
               "joint names, or JSON Lines of {name: value}; - for stdin); one pose line per "
               "input line.")
@format_option
def fk(robot_args: RobotArgs, joints: tuple[tuple[str, float], ...], frames: tuple[str, ...],
       relative_to: str | None, all_frames: bool, deg: bool, clamp: bool, configs: str | None,
       output: str | None, on_error: str, fmt: str) -> None:
    """Forward kinematics: the pose of frames for given joint values.

    Prints position [m], roll-pitch-yaw (URDF convention: fixed axes X, Y, Z), the
    quaternion (x y z w) and the 4x4 matrix of each frame, in the root link's frame
    unless --relative-to says otherwise. Continuous joints take an angle like any other.

    \b
    Examples:
      servicebot fk -j arm_link1_to_link2=0.5 -j arm_link2_to_link3=-0.3
      servicebot fk --deg -j arm_base_to_link1=45 --frame arm_link4 --format json
      servicebot fk --all-frames --relative-to arm_base_link
      servicebot fk --configs configs.csv -o poses.jsonl
    """
    from servicebot_cli.description.loader import load

    robot = load(robot_args.source())  # a bad robot file is the first thing to report
    from servicebot_cli.commands import _fk_run

    if all_frames and frames:
        raise click.UsageError("give --frame or --all-frames, not both")
    if configs is not None and joints:
        raise click.UsageError("give --joint values or a --configs file, not both")
    chosen = _fk_run.all_frames(robot) if all_frames else \
        [pick_frame(robot, f) for f in frames] or [pick_frame(robot, None)]
    reference = pick_frame(robot, relative_to or robot.root_link or "")
    if configs is not None:
        _fk_run.batch(robot, chosen, reference, configs, output=output, fmt=fmt, deg=deg,
                      clamp=clamp, on_error=on_error)
        return
    if output is not None:
        raise click.UsageError("--output is for batch results (--configs); redirect stdout")
    _fk_run.single(robot, chosen, reference, joints, fmt=fmt, deg=deg, clamp=clamp,
                   as_table=all_frames)
