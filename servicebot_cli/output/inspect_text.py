"""``servicebot inspect`` for a terminal: each section as tables no wider than 100 columns.

:func:`show` is the one place that prints an inspection: notes on stderr, the picture, then
the sections in the format asked for.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

import click

from servicebot_cli.output import extension_tables as ext
from servicebot_cli.output import inspect_tables as core
from servicebot_cli.output.blocks import Table
from servicebot_cli.output.table import format_number, table
from servicebot_cli.output.tree_view import tree_table

if TYPE_CHECKING:
    from servicebot_cli.inspect.report import Inspection
    from servicebot_cli.inspect.run import Clamped, InspectResult

WIDTH = 100


def section_tables(inspection: Inspection, name: str) -> list[Table]:
    """The tables of section ``name`` (which must be present)."""
    i = inspection
    match name:
        case "tree" if i.tree is not None:
            return [tree_table(i.tree)]
        case "links" if i.links is not None:
            return core.links_tables(i.links)
        case "joints" if i.joints is not None:
            return core.joints_tables(i.joints)
        case "frames" if i.frames is not None:
            return core.frames_tables(i.frames)
        case "sensors" if i.sensors is not None:
            return ext.sensors_tables(i.sensors)
        case "plugins" if i.plugins is not None:
            return ext.plugins_tables(i.plugins)
        case "interfaces" if i.interfaces is not None:
            return ext.interfaces_tables(i.interfaces)
        case "topics" if i.topics is not None:
            return ext.topics_tables(i.topics)
        case "totals" if i.totals is not None:
            return core.totals_tables(i.totals)
    raise KeyError(f"section '{name}' is not in this inspection")


def text_lines(inspection: Inspection, title: Callable[[str], str] = str) -> Iterator[str]:
    """Every present section; ``title`` styles table titles (bold on a terminal)."""
    yield from _wrapped(f"{inspection.robot}: {inspection.file}{_args(inspection)}", "", title)
    for name in inspection.sections():
        for block in section_tables(inspection, name):
            yield ""
            yield from table_lines(block, title)


def table_lines(block: Table, title: Callable[[str], str] = str) -> Iterator[str]:
    """A title, then the table (or what to say when it is empty), then its notes."""
    if not block.rows:
        yield from _wrapped(f"{block.title}: {block.empty}", "", title)
    else:
        yield from _wrapped(block.title, "", title)
        yield from table(block.headers, block.rows, max_width=WIDTH, whole=block.whole)
    for note in block.notes:
        yield from _wrapped(f"note: {note}", "  ")


def _wrapped(text: str, indent: str, style: Callable[[str], str] = str) -> Iterator[str]:
    """``text`` in lines of at most WIDTH columns; long words (paths) are never split."""
    lines = textwrap.wrap(text, WIDTH, initial_indent=indent, subsequent_indent=indent + "  ",
                          break_long_words=False, break_on_hyphens=False)
    for line in lines or [""]:
        yield style(line)


def _args(inspection: Inspection) -> str:
    if not inspection.xacro_args:
        return ""
    return " " + " ".join(f"{k}:={v}" for k, v in inspection.xacro_args.items())


def clamp_note(clamped: Clamped) -> str:
    """``note: --clamp: joint 'j' 5 rad is above its upper limit; using 2.61799 rad``."""
    side = "above its upper" if clamped.limit == "upper" else "below its lower"
    why = f"puts '{clamped.because}', which mimics it, outside its limits" if clamped.because \
        else f"is {side} limit"
    return (f"note: --clamp: joint '{clamped.joint}' {format_number(clamped.given)} "
            f"{clamped.unit} {why}; using {format_number(clamped.used)} {clamped.unit}")


def inspection_lines(inspection: Inspection, fmt: str) -> Iterator[str]:
    """The sections as ``text``, ``json``, ``markdown``, or the tree as ``dot``/``mermaid``."""
    if fmt == "json":
        from servicebot_cli.common.jsonable import dumps

        yield dumps(inspection.to_json()).rstrip("\n")
    elif fmt == "markdown":
        from servicebot_cli.output.markdown import markdown_lines

        yield from markdown_lines(inspection)
    elif fmt in ("dot", "mermaid"):
        from servicebot_cli.output.graph import dot_lines, mermaid_lines

        tree = inspection.tree
        if tree is not None:
            yield from dot_lines(tree, inspection.robot) if fmt == "dot" else mermaid_lines(tree)
    else:
        yield from text_lines(inspection, lambda text: click.style(text, bold=True))


def show(result: InspectResult, fmt: str, render_path: str | None = None,
         view: str = "iso") -> None:
    """Clamping notes and render warnings on stderr, the picture to ``render_path``, the
    sections on stdout.

    Raises:
        RenderError: Nothing to draw.
        OutputError: The picture cannot be written.
    """  # noqa: D205
    for clamped in result.clamped:
        click.echo(clamp_note(clamped), err=True)
    if result.picture is not None and render_path is not None:
        from servicebot_cli.output.render import write_picture

        for problem in write_picture(result.picture, render_path, view):
            click.echo(f"warning: {problem}", err=True)
        click.echo(f"wrote {render_path}", err=True)
    if result.inspection is not None:
        for line in inspection_lines(result.inspection, fmt):
            click.echo(line)
