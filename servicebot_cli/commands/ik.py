"""``servicebot ik``: joint values that put a frame at a target."""

from __future__ import annotations

import time
from typing import Literal

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import (
    RandomSeed,
    batch_options,
    clamp_option,
    deg_option,
    echo_notes,
    format_option,
    refuse_format_with_file,
    srdf_option,
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


class IkCommand(Command):
    """``ik``: ``--seed NAME=VALUE`` (start values, before ``--start``) points at ``--start``.

    Checked before Click's parse, so ``--seed a=1 --seed b=2`` gets the way out rather than
    "given 2 times".
    """

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Refuse start values given to ``--seed``, then parse as :class:`Command` does."""
        for index, arg in enumerate(args):
            if arg == "--":
                break
            value = args[index + 1] if arg == "--seed" and index + 1 < len(args) else \
                arg.removeprefix("--seed=") if arg.startswith("--seed=") else None
            if value is not None and "=" in value:
                RandomSeed().fail(RandomSeed.joint_value_message(value), ctx=ctx,
                                  param=self._seed_param())
        return super().parse_args(ctx, args)

    def _seed_param(self) -> click.Parameter | None:
        return next((p for p in self.params if p.name == "seed"), None)


@click.command(cls=IkCommand)
@robot_arguments()
@click.option("-f", "--frame", type=FrameName(), metavar="FRAME", default=None,
              help="The frame to move (default: the arm's tool frame).")
@click.option("--position", nargs=3, type=Number("M"), metavar="X Y Z", default=None,
              help="Target position [m] in the root link's frame, or --relative-to's (with "
              "--with-base: the frame where the root link stands now).")
@click.option("--relative-to", type=FrameName(), metavar="FRAME", default=None,
              help="Targets are given in this link's frame (a camera's, the arm base's), "
              "where it stands at the start configuration (default: the root link).")
@click.option("--rpy", nargs=3, type=Number("ANGLE"), metavar="R P Y", default=None,
              help="Target roll, pitch, yaw [rad, or deg with --deg] (URDF convention).")
@click.option("--quat", nargs=3 + 1, type=Number(), metavar="X Y Z W", default=None,
              help="Target orientation as a quaternion (normalised for you).")
@click.option("--orientation-axes", metavar="AXES", default=None,
              help="Which angles matter: all (default with --rpy/--quat), none, or a comma "
              "list of roll, pitch, yaw (e.g. pitch). The others are left free.")
@click.option("--start", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="Start from these joint values (repeatable; others at zero, or their "
              "nearest limit). The solution nearest the start is returned.")
@click.option("--seed", type=RandomSeed(), default=None, metavar="N",
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
              help="Attempts: the start, then random restarts within the limits.")
@click.option("--timeout-s", type=Number("S", positive=True), default=None, metavar="S",
              help="Give up on a target after S seconds of search (each target of a batch), "
              "printing the best try (exit 1). A target beyond the arm's reach ends at once.")
@click.option("--solutions", type=click.IntRange(min=1), default=3, show_default=True,
              metavar="N",
              help="Converged solutions to compare before returning the one nearest the start.")
@click.option("--allow-collisions", is_flag=True,
              help="Accept answers whose links intersect each other or, on a wheeled "
              "base, the floor (by default such answers are refused and the search goes "
              "on).")
@srdf_option
@deg_option
@clamp_option
@batch_options("--targets", help="Batch: one target per line (CSV or JSON Lines, the column "
               "names of fk's output; - for stdin); each solve starts from the previous "
               "solution.")
@format_option
@click.pass_context
def ik(ctx: click.Context, robot_args: RobotArgs, frame: str | None,
       position: tuple[float, float, float] | None, relative_to: str | None,
       rpy: tuple[float, float, float] | None,
       quat: tuple[float, float, float, float] | None, orientation_axes: str | None,
       start: tuple[tuple[str, float], ...], seed: int | None, with_base: bool, tol_m: float,
       tol_rad: float, max_attempts: int, timeout_s: float | None, solutions: int,
       allow_collisions: bool,
       srdf: str | None, deg: bool, clamp: bool, targets: str | None, output: str | None,
       on_error: Literal["stop", "skip"], fmt: str) -> None:
    """Inverse kinematics: joint values that put a frame at a target.

    Joint limits are always respected, continuous joints wrap, and a joint that follows
    another (<mimic>) moves with it. An answer whose links intersect each other (the URDF's
    collision geometry), or the floor on a wheeled base, is refused and the search goes on;
    a fixed arm may reach below its base. Exit code 0 when the target is reached, 1 when not
    (the best try is printed, with a hint: out of reach by how much, an orientation the
    joints cannot make, or the two links that would collide), 2 for bad input.

    \b
    Examples:
      servicebot ik --position 0.5 0.2 0.4
      servicebot ik --position 0.4 0.1 0.2 --rpy 0 90 0 --deg --orientation-axes pitch
      servicebot ik --position 2.0 1.0 0.5 --with-base --format json
      servicebot ik --relative-to arm_base_link --position 0.4 0 0.2
      servicebot ik --targets path.csv -o joints.jsonl --seed 1
    """
    if rpy is not None and quat is not None:
        raise click.UsageError("give --rpy or --quat, not both")
    if position is not None and targets is not None:
        raise click.UsageError("give --position or --targets, not both")
    if position is None and targets is None:
        raise click.UsageError("give a target: --position X Y Z, or a --targets file")
    for option in ("--output", "--on-error"):
        refuse_without(ctx, option, "--targets FILE", present=targets is not None)
    refuse_without(ctx, "--clamp", "--start NAME=VALUE", present=bool(start))
    refuse_format_with_file(ctx, output)
    refuse_with(ctx, "--srdf", "--allow-collisions", present=allow_collisions,
                why="which checks no pair")
    from servicebot_cli.common.errors import AnswerIsNo
    from servicebot_cli.kinematics.ik_problem import CollisionOptions, IkProblem
    from servicebot_cli.kinematics.inverse import IkSettings
    from servicebot_cli.output import ik_report

    problem = IkProblem(robot_args.source(), frame, start, seed, with_base,
                        IkSettings(tol_m, tol_rad, max_attempts, solutions=solutions), deg, clamp,
                        CollisionOptions(not allow_collisions, srdf), timeout_s, relative_to)
    if position is not None:
        from servicebot_cli.kinematics.ik import IkRequest, TargetSpec, run

        answer = run(IkRequest(problem, TargetSpec(position, rpy, quat, orientation_axes)),
                     clock=time.perf_counter)
        echo_notes(answer.notes)
        click.echo(ik_report.ik_output(answer, fmt), nl=False)
        if not answer.success:
            raise AnswerIsNo(ik_report.refusal(answer))
    elif targets is not None:
        from servicebot_cli.batch import ik as batch
        from servicebot_cli.output.batch_rows import RowFile

        summary = batch.run(batch.IkBatchRequest(problem, targets, orientation_axes, on_error),
                            RowFile(output, fmt), warn=warn, clock=time.perf_counter)
        if summary.failed:
            raise AnswerIsNo(ik_report.batch_refusal(summary))
