"""Text from a user's files made safe to print as one line of a report.

A name may hold a line break (``&#10;`` in an XML attribute, ``\\n`` or U+2028 in YAML): printed
as it is, a finding spills onto a second line that starts with whatever the name holds, and
a CI log reads a line that starts with ``::`` as a GitHub workflow command. Line breaks and
other control characters are shown as escapes instead (``\\n``, ``\\x1b``, ``\\u2028``).
"""

from __future__ import annotations

_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\t"}
_ESCAPES = str.maketrans({
    **{chr(c): _NAMED.get(chr(c), f"\\x{c:02x}") for c in (*range(0x20), *range(0x7f, 0xa0))},
    "\u2028": "\\u2028", "\u2029": "\\u2029",
})


def one_line(text: str) -> str:
    """``text`` with its line breaks and control characters (a tab aside) escaped."""
    return text.translate(_ESCAPES) if not text.isprintable() else text
