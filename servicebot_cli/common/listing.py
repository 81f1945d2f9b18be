"""Names listed in one line of a message: the first few, then how many more."""

from __future__ import annotations

from collections.abc import Sequence


def some_of(names: Sequence[str], most: int) -> str:
    """``a, b, c and 4 more``: the first ``most`` of ``names``, then the count of the rest."""
    shown = ", ".join(names[:most])
    return shown + (f" and {len(names) - most} more" if len(names) > most else "")
