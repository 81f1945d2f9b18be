"""``servicebot sweep``: many simulations of one scenario, with expectations for CI."""

from __future__ import annotations

import sys

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import srdf_option
from servicebot_cli.commands.options import (
    OutputPath,
    RobotArgs,
    format_option,
    refuse_with,
    refuse_without,
    robot_arguments,
)

PLOT_SUFFIXES = (".png", ".svg", ".pdf")
KEEPABLE = ("csv", "bag", "plot")


class KeepList(click.ParamType[tuple[str, ...]]):
    """``bag,csv``: per-run outputs to keep, from :data:`KEEPABLE`."""

    name = "csv,bag,plot"

    def convert(self, value: str | tuple[str, ...], param: click.Parameter | None,
                ctx: click.Context | None) -> tuple[str, ...]:
        """Split and check the list."""
        if isinstance(value, tuple):
            return value
        names = tuple(dict.fromkeys(n.strip() for n in str(value).split(",") if n.strip()))
        unknown = [n for n in names if n not in KEEPABLE]
        if unknown or not names:
            self.fail(f"'{value}': keep any of {', '.join(KEEPABLE)}, comma-separated", param,
                      ctx)
        return names


@click.command(cls=Command)
@click.argument("sweep_file", metavar="SWEEP.yaml", type=click.Path(dir_okay=False))
@robot_arguments()
@click.option("-j", "--jobs", type=click.IntRange(min=1, max=1024),
              help="Local worker processes.  [default: the available cores]")
@click.option("--scheduler", metavar="tcp://HOST:8786",
              help="Run on this Dask cluster instead (pip install 'servicebot[cluster]').")
@click.option("--out", "out_dir", type=OutputPath(directory=True),
              help="Write runs.csv, summary.json and each run's record here; a re-run with "
              "the same DIR skips the runs already finished.")
@click.option("--keep", type=KeepList(), default=None,
              help="Keep each run's outputs under DIR/runs/KEY/: csv, bag, plot.")
@click.option("--plot", type=OutputPath(suffixes=PLOT_SUFFIXES, what="plot", named_format=True),
              metavar="FILE.png", help="Each metric against each swept value, over seeds.")
@click.option("--allow-collisions", is_flag=True,
              help="Run arm trajectory points that put links into each other or the floor "
              "(refused by default, as simulate refuses them).")
@srdf_option
@click.option("--progress/--no-progress", default=None,
              help="Progress bar on stderr  [default: on a terminal, outside CI].")
@format_option
def sweep(sweep_file: str, robot_args: RobotArgs, jobs: int | None, scheduler: str | None,
          out_dir: str | None, keep: tuple[str, ...] | None, plot: str | None,
          allow_collisions: bool, srdf: str | None, progress: bool | None, fmt: str) -> None:
    """Simulate a scenario over seeds, a grid of values and random draws; check expectations.

    SWEEP.yaml names the scenario, the seeds, the values to sweep (dotted scenario fields,
    e.g. slip.track_factor) and what every run must meet (e.g. 'collisions == 0'). Every
    value is checked before the first run. Each run is a `servicebot simulate` with those
    values. Exit 0 when every run meets every expectation, 1 with a table of the runs that
    do not, 2 on bad input.

    \b
    Examples:
      servicebot sweep sweep.yaml --out results
      servicebot sweep sweep.yaml --out results --keep csv --plot sweep.png
      servicebot sweep sweep.yaml --scheduler tcp://cluster:8786 --out results
    """
    from servicebot_cli.common.errors import AnswerIsNo
    from servicebot_cli.output.sweep_text import failure_line, show_sweep
    from servicebot_cli.sweep import session
    from servicebot_cli.sweep.engine import available_cores

    ctx = click.get_current_context()
    refuse_with(ctx, "--jobs", "--scheduler", present=scheduler is not None,
                why="the cluster's workers run the sweep")
    refuse_without(ctx, "--keep", "--out DIR", present=out_dir is not None)
    request = session.SweepRequest(
        sweep_file, robot_args.source(), jobs=jobs or available_cores(), scheduler=scheduler,
        out_dir=out_dir, keep=keep or (), plot=plot,
        progress=progress, allow_collisions=allow_collisions, srdf=srdf)
    report = session.run(request, stderr=sys.stderr)
    for note in report.notes:
        click.echo(note, err=True)
    show_sweep(report, fmt)
    if report.failed:
        raise AnswerIsNo(failure_line(report, fmt))

