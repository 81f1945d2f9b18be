"""``servicebot inspect``: what a robot description holds.

As text, data (JSON), Markdown, a graph (dot, Mermaid), a picture (``--render``) and a diff.
The command turns its options into a request, calls :func:`servicebot_cli.inspect.run.run`
and hands the result to ``output/``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import (
    JointValue,
    OutputPath,
    RobotArgs,
    given,
    refuse_without,
    robot_arguments,
)
from servicebot_cli.inspect import SECTIONS

if TYPE_CHECKING:
    from servicebot_cli.inspect.run import DiffRequest

FORMATS = ("text", "json", "markdown", "dot", "mermaid")
VIEWS = ("iso", "front", "side", "top")
PICTURE_SUFFIXES = (".png", ".svg", ".pdf")


@click.command(cls=Command)
@robot_arguments()
@click.option("--section", "sections", multiple=True, type=click.Choice(SECTIONS),
              metavar="NAME", help=f"Show only this part (repeatable): {', '.join(SECTIONS)}.")
@click.option("--format", "fmt", type=click.Choice(FORMATS), default="text", show_default=True,
              help="text tables, json for programs, markdown, or the tree as a dot or "
              "mermaid graph.")
@click.option("--render", "render_path", metavar="FILE.png",
              type=OutputPath(PICTURE_SUFFIXES, what="picture", named_format=True),
              help="Draw the robot into FILE (.png, .svg or .pdf), written atomically.")
@click.option("--joint", "joints", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="Joint position [rad or m] for --render and the totals (repeatable; "
              "others are zero).")
@click.option("--clamp", is_flag=True, help="Clamp --joint values into their limits instead "
              "of refusing them (a note on stderr says what was clamped).")
@click.option("--view", type=click.Choice(VIEWS), default="iso", show_default=True,
              help="Camera for --render.")
@click.option("--diff", is_flag=True, help="Compare two descriptions: inspect A [NAME:=VALUE]... "
              "--diff B [NAME:=VALUE]...; exit 1 when they differ.")
@click.option("--controllers", type=click.Path(dir_okay=False, path_type=Path),
              metavar="FILE", help="The ros2_control controller YAML, for the topics (default: "
              "the one gazebo_ros2_control names, else controllers.yaml beside FILE).")
@click.pass_context
def inspect(ctx: click.Context, robot_args: RobotArgs, sections: tuple[str, ...], fmt: str,
            render_path: str | None, joints: tuple[tuple[str, float], ...], clamp: bool,
            view: str, diff: bool, controllers: Path | None) -> None:
    """Show what a robot description holds.

    Its kinematic tree, links, joints, fixed frames, sensors, plugins, ros2_control
    interfaces, topics and totals; or a picture of it (--render), or what differs from
    another description (--diff).

    \b
    Examples:
      servicebot inspect                                  # the bundled simulation robot
      servicebot inspect --section totals --format json
      servicebot inspect --format dot | dot -Tpng -o tree.png
      servicebot inspect --render robot.png --joint arm_link1_to_link2=0.8
      servicebot inspect --robot sim --diff robots/service_robot_real.urdf.xml
      servicebot inspect robots/service_robot.urdf.xacro --diff \\
          robots/service_robot.urdf.xacro hardware:=real
    """
    from servicebot_cli.inspect.run import InspectRequest, JointValueError, run

    shown = _shown(ctx, sections, fmt, render_path, joints, diff)
    if diff:
        _compare(_diff_request(robot_args), fmt)
        return
    request = InspectRequest(robot_args.source(), shown, joints, clamp, render_path is not None,
                             controllers)
    try:
        result = run(request)
    except JointValueError as exc:
        raise click.BadParameter(str(exc), param_hint="'--joint'") from None
    from servicebot_cli.output.inspect_text import show

    show(result, fmt, render_path, view)


def _shown(ctx: click.Context, sections: tuple[str, ...], fmt: str, render_path: str | None,
           joints: tuple[tuple[str, float], ...], diff: bool) -> tuple[str, ...]:
    """The sections to print; refuses options that mean nothing together or do nothing."""
    graph = fmt in ("dot", "mermaid")
    idle = [flag for flag, name in (("--section", "sections"), ("--render", "render_path"),
                                    ("--joint", "joints"), ("--controllers", "controllers"))
            if given(ctx, name)]
    if diff and idle:
        raise click.UsageError(f"--diff compares whole descriptions; drop {' and '.join(idle)}")
    if graph and (diff or set(sections) - {"tree"}):
        raise click.UsageError(f"--format {fmt} draws the kinematic tree only; drop --section "
                               "and --diff, or use --format text|json|markdown")
    if render_path is not None and not sections and given(ctx, "fmt"):
        raise click.UsageError(f"--format {fmt} has no effect with --render and no --section "
                               "(nothing is printed); add --section NAME or drop --format")
    shown = ("tree",) if graph else sections or (() if render_path or diff else SECTIONS)
    refuse_without(ctx, "--view", "--render FILE.png", present=render_path is not None)
    refuse_without(ctx, "--clamp", "--joint NAME=VALUE", present=bool(joints))
    refuse_without(ctx, "--joint", "--render FILE.png or --section totals", name="joints",
                   present=render_path is not None or "totals" in shown)
    refuse_without(ctx, "--controllers", "--section topics", present="topics" in shown)
    repeated = sorted({name for name, _ in joints if [n for n, _ in joints].count(name) > 1})
    if repeated:
        raise click.BadParameter(f"joint '{repeated[0]}' is given twice; give each joint once",
                                 param_hint="'--joint'")
    return tuple(shown)


def _diff_request(robot_args: RobotArgs) -> DiffRequest:
    """A and B from the command line; with one file, A is the bundled robot."""
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.inspect.run import DiffRequest

    sources = robot_args.sources()
    if len(sources) == 1:
        sources.insert(0, RobotSource.bundled())
    if len(sources) != 2:
        raise click.UsageError(f"--diff compares two descriptions, got {len(sources)}: "
                               "servicebot inspect A [NAME:=VALUE]... --diff B [NAME:=VALUE]...")
    return DiffRequest(sources[0], sources[1])


def _compare(request: DiffRequest, fmt: str) -> None:
    """Print the differences; the answer is no (exit 1) when there are any."""
    from servicebot_cli.common.errors import AnswerIsNo
    from servicebot_cli.inspect.run import run
    from servicebot_cli.output import diff_view

    result = run(request)
    diff_view.show(result, fmt)
    if not result.equal:
        raise AnswerIsNo("")  # the summary (or "equal": false) already says so
