"""``servicebot inspect --format markdown``: a report to paste into an issue or a README.

The tree is a Mermaid diagram (GitHub draws it); every other section is Markdown tables.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from servicebot_cli.output.blocks import Table
from servicebot_cli.output.graph import mermaid_lines
from servicebot_cli.output.inspect_text import section_tables
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.inspect.report import Inspection


def _cell(value: object) -> str:
    if value is None:
        return "-"
    if isinstance(value, float | int) and not isinstance(value, bool):
        return format_number(value)
    text = str(value).replace("|", "\\|").replace("\n", " ")
    return text or " "


def markdown_table(headers: Sequence[str], rows: Sequence[Sequence[object]]) -> Iterator[str]:
    """A GitHub-flavoured Markdown table; numeric columns right-aligned."""
    numeric = [all(isinstance(r[i], float | int) or r[i] is None for r in rows) and
               any(r[i] is not None for r in rows) for i in range(len(headers))]
    yield "| " + " | ".join(_cell(h) for h in headers) + " |"
    yield "|" + "|".join("---:" if n else "---" for n in numeric) + "|"
    for row in rows:
        yield "| " + " | ".join(_cell(v) for v in row) + " |"


def _block(block: Table) -> Iterator[str]:
    yield f"### {block.title}"
    yield ""
    if block.rows:
        yield from markdown_table(block.headers, block.rows)
    else:
        yield f"_{block.empty}_"
    if block.notes:
        yield ""
        yield from (f"- {note}" for note in block.notes)
    yield ""


def markdown_lines(inspection: Inspection) -> Iterator[str]:
    """The whole report."""
    yield f"# {inspection.robot}"
    yield ""
    args = " ".join(f"`{k}:={v}`" for k, v in inspection.xacro_args.items())
    yield f"From `{inspection.file}`" + (f" with {args}" if args else "") + "."
    yield ""
    for name in inspection.sections():
        yield f"## {name.capitalize()}"
        yield ""
        if name == "tree" and inspection.tree is not None:
            yield "```mermaid"
            yield from mermaid_lines(inspection.tree)
            yield "```"
            yield ""
            continue  # the diagram carries the tree table's content
        for block in section_tables(inspection, name):
            yield from _block(block)
