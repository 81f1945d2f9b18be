"""``servicebot inspect A --diff B`` as text, Markdown or JSON.

Text groups the differences by element, one line per field: ``~`` changed, ``-`` only in A,
``+`` only in B (coloured on a terminal), wrapped to 100 columns.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from servicebot_cli.output.markdown import markdown_table
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.inspect.diff import Difference, DiffResult

WIDTH = 100
DIFF_SCHEMA = "servicebot.inspect.diff/1"
MARKS = {"changed": "~", "removed": "-", "added": "+"}
COLOURS = {"changed": "yellow", "removed": "red", "added": "green"}


def value_text(value: Any) -> str:
    """A field value for people: numbers to 6 significant digits, lists space-separated."""
    if value is None:
        return "(none)"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float | int):
        return format_number(value)
    if isinstance(value, list | tuple):
        return " ".join(value_text(v) for v in value)
    return str(value)


def _field_name(diff: Difference) -> str:
    """``limits velocity [rad/s]``; empty for a whole element."""
    if not diff.field:
        return ""
    return diff.field.replace(".", " ") + (f" [{diff.unit}]" if diff.unit else "")


def _field_text(diff: Difference) -> str:
    if not diff.field:
        return "only in A" if diff.change == "removed" else "only in B"
    field = _field_name(diff)
    if diff.change == "changed":
        return f"{field}: {value_text(diff.a)} -> {value_text(diff.b)}"
    return f"{field}: {value_text(diff.a if diff.change == 'removed' else diff.b)}"


def summary(result: DiffResult) -> str:
    """``27 differences: 13 changed, 12 only in A, 2 only in B`` or ``no differences``."""
    if result.equal:
        return "no differences"
    counts = {c: sum(d.change == c for d in result.differences) for c in MARKS}
    n = len(result.differences)
    return (f"{n} difference{'s' if n != 1 else ''}: {counts['changed']} changed, "
            f"{counts['removed']} only in A, {counts['added']} only in B")


def diff_lines(result: DiffResult,
               colour: Callable[[str, str], str] = lambda text, _: text) -> Iterator[str]:
    """Text: who is A and B, each element's differences, then a summary line."""
    yield f"A: {result.a}"
    yield f"B: {result.b}"
    element = None
    for diff in result.differences:
        if diff.element != element:
            element = diff.element
            yield element
        text = f"{MARKS[diff.change]} {_field_text(diff)}"
        for line in textwrap.wrap(text, WIDTH, initial_indent="  ", subsequent_indent="      ",
                                  break_long_words=False, break_on_hyphens=False):
            yield colour(line, COLOURS[diff.change])
    yield summary(result)


def diff_markdown(result: DiffResult) -> Iterator[str]:
    """Markdown: a table of every difference."""
    yield f"# Differences between `{result.a}` (A) and `{result.b}` (B)"
    yield ""
    if result.differences:
        rows = [(d.element, _field_name(d) or "(whole element)",
                 value_text(d.a) if d.a is not True else "present",
                 value_text(d.b) if d.b is not True else "present")
                for d in result.differences]
        yield from markdown_table(("element", "field", "A", "B"), rows)
        yield ""
    yield summary(result) + "."


def diff_json(result: DiffResult) -> dict[str, Any]:
    """The documented JSON form."""
    return {
        "schema": DIFF_SCHEMA, "a": result.a, "b": result.b, "equal": result.equal,
        "differences": [{"element": d.element, "field": d.field, "change": d.change,
                         "a": d.a, "b": d.b, "unit": d.unit} for d in result.differences],
    }


def show(result: DiffResult, fmt: str) -> None:
    """Print the differences as text (coloured on a terminal), Markdown or JSON."""
    import click

    if fmt == "json":
        from servicebot_cli.common.jsonable import dumps

        click.echo(dumps(diff_json(result)), nl=False)
        return
    lines = diff_markdown(result) if fmt == "markdown" else diff_lines(
        result, lambda text, colour: click.style(text, fg=colour))
    for line in lines:
        click.echo(line)
