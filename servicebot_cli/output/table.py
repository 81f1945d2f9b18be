"""Plain-text tables that fit a terminal width, for every command's text output.

Numbers are right-aligned, text left-aligned. When the table is wider than ``max_width``,
the widest text columns are truncated with an ellipsis, never the numbers.
"""

from __future__ import annotations

import math
import unicodedata
from collections.abc import Sequence

from servicebot_cli.output.one_line import one_line

ELLIPSIS = "…"


def format_number(value: float | None, digits: int = 6) -> str:
    """A number for people: ``digits`` significant digits, no exponent for ordinary sizes."""
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value == 0:
        return "0"
    text = f"{value:.{digits}g}"
    return "0" if text in ("-0", "0") else text


def _cell(value: object) -> str:
    if isinstance(value, float | int) and not isinstance(value, bool):
        return format_number(value)
    if value is None:
        return "-"
    return one_line(str(value))  # a name's line break would break the table


def width(text: str) -> int:
    """Columns ``text`` takes in a terminal.

    Two for a wide character (CJK), none for a combining mark, one for the others.
    """
    if text.isascii():
        return len(text)
    return sum(0 if unicodedata.combining(c) else 2 if unicodedata.east_asian_width(c) in "WF"
               else 1 for c in text)


def _cut(text: str, columns: int) -> str:
    """``text`` cut to ``columns`` terminal columns, an ellipsis last."""
    kept, used = [], 0
    for char in text:
        used += width(char)
        if used > columns - 1:
            break
        kept.append(char)
    return "".join(kept) + ELLIPSIS


def _is_numeric(column: Sequence[object]) -> bool:
    present = [v for v in column if v is not None]
    return bool(present) and all(
        isinstance(v, float | int) and not isinstance(v, bool) for v in present
    )


def table(
    headers: Sequence[str], rows: Sequence[Sequence[object]], *, max_width: int = 100, gap: int = 2,
    whole: Sequence[int] = (),
) -> list[str]:
    """Lines of a table: a header, a rule, then one line per row.

    Args:
        headers: Column titles.
        rows: Cell values; floats are formatted with :func:`format_number`.
        max_width: Widest line allowed [characters].
        gap: Spaces between columns.
        whole: Columns cut only when the others cannot be cut any more.
    """
    columns = list(zip(*rows, strict=True)) if rows else [() for _ in headers]
    numeric = [_is_numeric(col) for col in columns]
    cells = [[_cell(v) for v in row] for row in rows]
    widths = [max([width(h), *(width(r[i]) for r in cells)]) for i, h in enumerate(headers)]
    overflow = sum(widths) + gap * (len(widths) - 1) - max_width
    while overflow > 0:
        candidates = [i for i in range(len(widths)) if not numeric[i] and widths[i] > 8
                      and i not in whole] or [
            i for i in whole if not numeric[i] and widths[i] > 8]
        if not candidates:
            break
        widest = max(candidates, key=lambda i: widths[i])
        # down to the next widest, so that two wide columns share the cut
        next_width = max((widths[i] for i in candidates if i != widest), default=8)
        cut = min(overflow, widths[widest] - max(next_width, 8) or 1)
        widths[widest] -= cut
        overflow -= cut

    def fit(text: str, i: int) -> str:
        if width(text) > widths[i]:
            text = _cut(text, widths[i])
        pad = " " * (widths[i] - width(text))
        return pad + text if numeric[i] else text + pad

    spacer = " " * gap
    lines = [spacer.join(fit(h, i) for i, h in enumerate(headers)).rstrip()]
    lines.append(spacer.join("-" * w for w in widths))
    lines.extend(spacer.join(fit(c, i) for i, c in enumerate(row)).rstrip() for row in cells)
    return lines
