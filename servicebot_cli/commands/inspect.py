"""``servicebot inspect``: what a robot description holds.

As text, data (JSON), Markdown, a graph (dot, Mermaid), a picture (``--render``) and a diff.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import JointValue, RobotArgs, robot_arguments
from servicebot_cli.common.errors import ExitCode
from servicebot_cli.inspect import SECTIONS

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FORMATS = ("text", "json", "markdown", "dot", "mermaid")
VIEWS = ("iso", "front", "side", "top")


@click.command(cls=Command)
@robot_arguments()
@click.option("--section", "sections", multiple=True, type=click.Choice(SECTIONS),
              metavar="NAME", help=f"Show only this part (repeatable): {', '.join(SECTIONS)}.")
@click.option("--format", "fmt", type=click.Choice(FORMATS), default="text", show_default=True,
              help="text tables, json for programs, markdown, or the tree as a dot or "
              "mermaid graph.")
@click.option("--render", "render_path", metavar="FILE.png",
              help="Draw the robot into FILE (.png, .svg or .pdf), written atomically.")
@click.option("--joint", "joints", type=JointValue(), multiple=True, metavar="NAME=VALUE",
              help="Joint position [rad or m] for --render and the totals (repeatable; "
              "others are zero).")
@click.option("--clamp", is_flag=True, help="Clamp --joint values into their limits instead "
              "of refusing them.")
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
    _check_combination(sections, fmt, render_path, joints, diff)
    if diff:
        ctx.exit(_run_diff(robot_args, fmt))
    from servicebot_cli.description.loader import load

    source = robot_args.source()
    robot = load(source)
    values = _configuration(robot, joints, clamp)
    if render_path is not None:
        _render(robot, render_path, values, clamp, source.resolver(), view)
        if not sections:
            return
    _show(robot, sections or SECTIONS, fmt, values, clamp, source.resolver(), controllers)


def _check_combination(sections: tuple[str, ...], fmt: str, render_path: str | None,
                       joints: tuple[tuple[str, float], ...], diff: bool) -> None:
    """Refuse options that mean nothing together, before anything is loaded."""
    if diff and (sections or render_path or joints):
        raise click.UsageError("--diff compares whole descriptions; drop --section, --render "
                               "and --joint")
    if fmt in ("dot", "mermaid") and (diff or set(sections) - {"tree"}):
        raise click.UsageError(f"--format {fmt} draws the kinematic tree only; drop --section "
                               "and --diff, or use --format text|json|markdown")


def _configuration(robot: RobotDescription, joints: tuple[tuple[str, float], ...],
                   clamp: bool) -> dict[str, float]:
    """The ``--joint`` values (clamped with ``--clamp``), checked before any work."""
    from servicebot_cli.common.errors import NameNotFound, OutOfLimits
    from servicebot_cli.inspect.poses import checked_values

    fixed = {j.name for j in robot.joints if not j.movable}
    try:
        for name, _ in joints:
            if name in fixed:
                raise OutOfLimits(f"joint '{name}' is fixed; only movable joints take a value "
                                  f"({', '.join(robot.joint_space.names)})")
        return checked_values(robot, dict(joints), clamp=clamp)
    except (NameNotFound, OutOfLimits) as exc:
        raise click.BadParameter(str(exc), param_hint="'--joint'") from None


def _render(robot: RobotDescription, path: str, values: dict[str, float], clamp: bool,
            resolver: Any, view: str) -> None:
    from servicebot_cli.output.render import render_robot

    for problem in render_robot(robot, path, values, clamp=clamp, resolver=resolver, view=view):
        click.echo(f"warning: {problem}", err=True)
    click.echo(f"wrote {path}", err=True)


def _show(robot: RobotDescription, sections: tuple[str, ...], fmt: str,
          values: dict[str, float], clamp: bool, resolver: Any, controllers: Path | None) -> None:
    from servicebot_cli.inspect.report import Request, inspect_robot

    wanted = ("tree",) if fmt in ("dot", "mermaid") else sections
    request = Request(tuple(wanted), values, clamp, resolver, controllers)
    inspection = inspect_robot(robot, request)
    for line in _lines(inspection, fmt):
        click.echo(line)


def _lines(inspection: Any, fmt: str) -> Any:
    if fmt == "json":
        from servicebot_cli.common.jsonable import dumps

        return [dumps(inspection.to_json()).rstrip("\n")]
    if fmt == "markdown":
        from servicebot_cli.output.markdown import markdown_lines

        return markdown_lines(inspection)
    if fmt in ("dot", "mermaid"):
        from servicebot_cli.output.graph import dot_lines, mermaid_lines

        tree = inspection.tree
        return dot_lines(tree, inspection.robot) if fmt == "dot" else mermaid_lines(tree)
    from servicebot_cli.output.inspect_text import text_lines

    return text_lines(inspection, lambda text: click.style(text, bold=True))


def _run_diff(robot_args: RobotArgs, fmt: str) -> int:
    """Compare the two descriptions named; print the differences; 0 if equal, else 1."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.inspect.diff import compare
    from servicebot_cli.output import diff_view

    sources = robot_args.sources()
    if len(sources) == 1:
        sources.insert(0, RobotSource.bundled())
    if len(sources) != 2:
        raise click.UsageError(f"--diff compares two descriptions, got {len(sources)}: "
                               "servicebot inspect A [NAME:=VALUE]... --diff B [NAME:=VALUE]...")
    result = compare(load(sources[0]), load(sources[1]))
    if fmt == "json":
        from servicebot_cli.common.jsonable import dumps

        click.echo(dumps(diff_view.diff_json(result)), nl=False)
    elif fmt == "markdown":
        for line in diff_view.diff_markdown(result):
            click.echo(line)
    else:
        for line in diff_view.diff_lines(result, lambda text, c: click.style(text, fg=c)):
            click.echo(line)
    return ExitCode.OK if result.equal else ExitCode.FAILED
