"""``servicebot inspect`` for a terminal: each section as tables no wider than 100 columns."""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from servicebot_cli.output import extension_tables as ext
from servicebot_cli.output import inspect_tables as core
from servicebot_cli.output.blocks import Table
from servicebot_cli.output.table import table
from servicebot_cli.output.tree_view import tree_table

if TYPE_CHECKING:
    from servicebot_cli.inspect.report import Inspection

WIDTH = 100


def section_tables(inspection: Inspection, name: str) -> list[Table]:
    """The tables of section ``name`` (which must be present)."""
    value = getattr(inspection, name)
    if name == "tree":
        return [tree_table(value)]
    makers: dict[str, Callable[[object], list[Table]]] = {
        "links": core.links_tables, "joints": core.joints_tables,
        "frames": core.frames_tables, "sensors": ext.sensors_tables,
        "plugins": ext.plugins_tables, "interfaces": ext.interfaces_tables,
        "topics": ext.topics_tables, "totals": core.totals_tables,
    }
    return makers[name](value)


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
        yield from table(block.headers, block.rows, max_width=WIDTH)
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
