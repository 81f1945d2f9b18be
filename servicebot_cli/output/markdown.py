"""``servicebot inspect --format markdown``: a report to paste into an issue or a README.

The tree is a Mermaid diagram (GitHub draws it); every other section is Markdown tables.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from servicebot_cli.output.blocks import Table
from servicebot_cli.output.graph import mermaid_lines
from servicebot_cli.output.inspect_text import section_tables
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.inspect.report import Inspection


_MARKUP = str.maketrans({c: "\\" + c for c in "\\`*<>&|~"})
"""What Markdown (and the HTML it passes through) reads as markup: escaped to stand for itself.
A note's ``<inertial>`` vanished as an unknown HTML tag, a link named ``_frame_`` came out in
italics, one named ``tool<img src=x onerror=...>`` was a live element."""
_EDGE_UNDERSCORE = re.compile(r"(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])")
"""An underscore that may open or close emphasis; one inside a word (base_link) cannot."""
_LINK_END = re.compile(r"\](?=[(\[])")
"""A ``]`` that would close a link's text (``[x](url)``, ``[x][ref]``); ``[kg]`` is none."""


def text(value: object) -> str:
    """``value`` as Markdown text that shows it as written, on one line."""
    shown = str(value).replace("\n", " ").translate(_MARKUP)
    return _LINK_END.sub(r"\\]", _EDGE_UNDERSCORE.sub(r"\\_", shown))


def _code(value: object) -> str:
    """``value`` as an inline code span, fenced by more backticks than it holds."""
    shown = str(value).replace("\n", " ")
    longest = max((len(run) for run in re.findall("`+", shown)), default=0)
    fence, pad = "`" * (longest + 1), " " if longest else ""
    return f"{fence}{pad}{shown}{pad}{fence}"


def _cell(value: object) -> str:
    if value is None:
        return "-"
    if isinstance(value, float | int) and not isinstance(value, bool):
        return format_number(value)
    return text(value) or " "


def markdown_table(headers: Sequence[str], rows: Sequence[Sequence[object]]) -> Iterator[str]:
    """A GitHub-flavoured Markdown table; numeric columns right-aligned."""
    numeric = [all(isinstance(r[i], float | int) or r[i] is None for r in rows) and
               any(r[i] is not None for r in rows) for i in range(len(headers))]
    yield "| " + " | ".join(_cell(h) for h in headers) + " |"
    yield "|" + "|".join("---:" if n else "---" for n in numeric) + "|"
    for row in rows:
        yield "| " + " | ".join(_cell(v) for v in row) + " |"


def _block(block: Table) -> Iterator[str]:
    yield f"### {text(block.title)}"
    yield ""
    if block.rows:
        yield from markdown_table(block.headers, block.rows)
    else:
        yield f"_{text(block.empty)}_"
    if block.notes:
        yield ""
        yield from (f"- {text(note)}" for note in block.notes)
    yield ""


def markdown_lines(inspection: Inspection) -> Iterator[str]:
    """The whole report."""
    yield f"# {text(inspection.robot)}"
    yield ""
    args = " ".join(_code(f"{k}:={v}") for k, v in inspection.xacro_args.items())
    yield f"From {_code(inspection.file)}" + (f" with {args}" if args else "") + "."
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
