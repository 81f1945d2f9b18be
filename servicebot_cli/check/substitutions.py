"""Values a launch file fills in before ROS reads a parameters file. Pure."""

from __future__ import annotations

import re

_PLACEHOLDER = re.compile(r"<[A-Za-z_][A-Za-z0-9_]*>")
_LEADING = re.compile(r"((?:\$\(var [^()]*\)|\$\{[^{}]*\}|<[A-Za-z_][A-Za-z0-9_]*>)+)"
                      r"([A-Za-z0-9_]+)")


def substituted(text: str) -> bool:
    """Whether a launch file fills ``text`` in.

    ``$(var ...)``, a ``${NAME}`` template, or a ``<NAME>`` placeholder that nav2_common's
    ReplaceString rewrites (``<prefix>joint1``).
    """
    return "$(" in text or "${" in text or ("<" in text and bool(_PLACEHOLDER.search(text)))


def leading_substitution(text: str) -> tuple[str, str] | None:
    """``(what the launch file fills in, the rest)`` for a name it prefixes, else None.

    ``$(var tf_prefix)elbow_joint`` gives ``("$(var tf_prefix)", "elbow_joint")``.
    """
    found = _LEADING.fullmatch(text)
    return None if found is None else (found[1], found[2])
