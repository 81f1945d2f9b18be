"""A format-neutral table: a title, headers, rows and notes, rendered as text or Markdown."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Table:
    """One table of a section.

    Attributes:
        title: Shown above the table.
        headers: Column titles, with units in brackets.
        rows: Cell values; numbers are formatted by the renderer.
        notes: Lines shown under the table.
        empty: What to say when there are no rows.
        whole: Columns cut last when the table is too wide (the tree's link names).
    """

    title: str
    headers: tuple[str, ...]
    rows: list[tuple[object, ...]] = field(default_factory=list)
    notes: tuple[str, ...] = ()
    empty: str = "none"
    whole: tuple[int, ...] = ()
