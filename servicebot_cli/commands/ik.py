"""``servicebot ik``: joint values that put a frame at a target."""

from __future__ import annotations

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import (
    batch_options,
    clamp_option,
    deg_option,
    pick_frame,
)
from servicebot_cli.commands.options import (
    JointValue,
    Number,
    RobotArgs,
    format_option,
    robot_arguments,
)


@click.command(cls=Command)
@robot_arguments()
@click.option("-f", "--frame", metavar="FRAME", default=None,
              help="The frame to move (default: the arm's tool frame).")
@click.option("--position", nargs=3, type=Number("M"), metavar="X Y Z", default=None,
              help="Target position [m] in the root link's frame (with --with-base: the "
              "frame where the root link stands now).")
@click.option("--rpy", nargs=3, type=Number("ANGLE"), metavar="R P Y", default=None,
              help="Target roll, pitch, yaw [rad, or deg with --deg] (URDF convention).")
@click.option("--quat", nargs=3 + 1, type=Number(), metavar="X Y Z W", default=None,
              help="Target orientation as a quaternion (normalised for you).")
@click.option("--orientation-axes", metavar="AXES", default=None,
              help="Which angles matter: all (default with --rpy/--quat), none, or a comma "
              "list of roll, pitch, yaw (e.g. pitch). The others are left free.")
@click.option("--seed", "seeds", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="Start from these joint values (repeatable; others at zero, or their "
              "nearest limit). The solution nearest the seed is returned.")
@click.option("--random-seed", type=click.IntRange(min=0), default=None, metavar="N",
              help="Seed of the random restarts: the same number gives the same answer.")
@click.option("--with-base", is_flag=True,
              help="Also move the mobile base (planar x, y, yaw): say where the robot should "
              "stand. It stays put when the arm alone reaches.")
@click.option("--tol-m", type=Number("M", positive=True), default=1e-6, metavar="M",
              show_default=True, help="Accepted position error [m].")
@click.option("--tol-rad", type=Number("RAD", positive=True), default=1e-6,
              metavar="RAD",
              show_default=True, help="Accepted orientation error [rad].")
@click.option("--max-attempts", type=click.IntRange(min=1), default=100, show_default=True,
              metavar="N",
              help="Attempts: the seed, then random restarts within the limits.")
@click.option("--solutions", type=click.IntRange(min=1), default=3, show_default=True,
              metavar="N",
              help="Converged solutions to compare before returning the one nearest the seed.")
@deg_option
@clamp_option
@batch_options("--targets", help="Batch: one target per line (CSV or JSON Lines, the column "
               "names of fk's output; - for stdin); each solve starts from the previous "
               "solution.")
@format_option
def ik(robot_args: RobotArgs, frame: str | None, position: tuple[float, ...] | None,
       rpy: tuple[float, ...] | None, quat: tuple[float, ...] | None,
       orientation_axes: str | None, seeds: tuple[tuple[str, float], ...],
       random_seed: int | None, with_base: bool, tol_m: float, tol_rad: float,
       max_attempts: int, solutions: int, deg: bool, clamp: bool, targets: str | None,
       output: str | None, on_error: str, fmt: str) -> None:
    """Inverse kinematics: joint values that put a frame at a target.

    Joint limits are always respected and continuous joints wrap. Exit code 0 when the
    target is reached, 1 when not (the best try is printed, with a hint: out of reach by
    how much, or an orientation the joints cannot make), 2 for bad input.

    \b
    Examples:
      servicebot ik --position 0.5 0.2 0.4
      servicebot ik --position 0.4 0.1 0.2 --rpy 0 90 0 --deg --orientation-axes pitch
      servicebot ik --position 2.0 1.0 0.5 --with-base --format json
      servicebot ik --targets path.csv -o joints.jsonl --random-seed 1
    """
    from servicebot_cli.description.loader import load

    robot = load(robot_args.source())  # a bad robot file is the first thing to report
    from servicebot_cli.commands import _ik_run
    from servicebot_cli.kinematics.inverse import IkSettings
    from servicebot_cli.kinematics.targets import make_target, parse_axes

    if rpy is not None and quat is not None:
        raise click.UsageError("give --rpy or --quat, not both")
    if position is not None and targets is not None:
        raise click.UsageError("give --position or --targets, not both")
    if position is None and targets is None:
        raise click.UsageError("give a target: --position X Y Z, or a --targets file")
    if targets is None and output is not None:
        raise click.UsageError("--output is for batch results (--targets); redirect stdout")
    settings = IkSettings(tol_m, tol_rad, max_attempts, solutions=solutions)
    run = _ik_run.setup(robot, pick_frame(robot, frame), seeds, with_base=with_base,
                        settings=settings, random_seed=random_seed, deg=deg, clamp=clamp)
    axes = parse_axes(orientation_axes, targets is not None or rpy is not None or quat is not None)
    if targets is not None:
        _ik_run.batch(run, targets, axes=axes, output=output, fmt=fmt, on_error=on_error)
        return
    _ik_run.single(run, make_target(position, rpy=rpy, quat=quat, deg=deg, axes=axes), fmt)
