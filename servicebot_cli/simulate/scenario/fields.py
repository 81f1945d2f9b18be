"""Dotted field paths into a scenario document, and documents with values put in place.

``slip.track_factor`` and ``cmd_vel[2].linear_m_s`` name a value the way scenario errors do
(:func:`~servicebot_cli.simulate.scenario.located.dotted`). Putting a value in place never
checks it: the scenario reader does, once the whole document is built.
"""

from __future__ import annotations

import copy
import re
from collections.abc import Mapping

from servicebot_cli.simulate.scenario.located import Path, Value, dotted

# a name, a ROS name (a topic: the key of a summary's ``messages``) or an index
_PART = re.compile(r"([A-Za-z_]\w*|/[\w/~]+)|\[(\d+)\]")


class FieldPathError(ValueError):
    """A field path that is not ``name(.name|[index])*``, or that the document cannot take.

    Attributes:
        path: The path that the document cannot take (empty for a malformed path).
    """

    def __init__(self, message: str, path: Path = ()) -> None:
        super().__init__(message)
        self.path = path


def parse_field(text: str) -> Path:
    """``("cmd_vel", 2, "linear_m_s")`` for ``cmd_vel[2].linear_m_s``.

    A part may be a ROS name, slashes and all: ``messages./scan`` is ``("messages", "/scan")``.

    Raises:
        FieldPathError: Not a dotted path of names and ``[index]``.
    """
    parts: list[str | int] = []
    pos = 0
    while pos < len(text):
        if parts and text[pos] == ".":
            pos += 1
        match = _PART.match(text, pos)
        if match is None or (match.group(2) is not None and not parts):
            raise FieldPathError(f"'{text}' is not a field path like slip.track_factor or "
                                 "cmd_vel[0].linear_m_s")
        parts.append(match.group(1) if match.group(1) is not None else int(match.group(2)))
        pos = match.end()
    if not parts:
        raise FieldPathError("an empty field path; give one like slip.track_factor")
    return tuple(parts)


def with_values(document: Value, values: Mapping[Path, Value]) -> Value:
    """A copy of ``document`` with each value of ``values`` at its path.

    Missing mappings on the way are created; list elements must exist.

    Raises:
        FieldPathError: A path through a value that is not a mapping or a list, or an
            index past the end of a list.
    """
    result = copy.deepcopy(document) if document is not None else {}
    for path, value in values.items():
        try:
            _put(result, path, copy.deepcopy(value))
        except FieldPathError as exc:
            raise FieldPathError(str(exc), path) from None
    return result


def _put(document: Value, path: Path, value: Value) -> None:
    node = document
    for i, part in enumerate(path):
        last = i == len(path) - 1
        if isinstance(part, int):
            if not isinstance(node, list):
                raise FieldPathError(f"{dotted(path[:i])} is not a list")
            if part >= len(node):
                raise FieldPathError(f"{dotted(path[:i])} has {len(node)} elements, "
                                     f"no [{part}]")
            if last:
                node[part] = value
            else:
                node = node[part]
            continue
        if not isinstance(node, dict):
            raise FieldPathError(f"{dotted(path[:i]) or 'the scenario'} is not a mapping")
        if last:
            node[part] = value
        else:
            if node.get(part) is None:
                node[part] = {}
            node = node[part]

