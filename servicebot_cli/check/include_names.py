"""Include filenames computed from a file's own constants, read as xacro would read them.

RoverSimulation's robot includes its parts as ``$(find ${package_name})/urdf/part.xacro``,
``package_name`` being a property of the same file with a plain value. Read as written, the
name named no file: the parts were checked alone, as robots, and failed (SB006) where xacro
expands the robot. A ``${NAME}`` or ``$(arg NAME)`` in a filename is replaced here by each
value the file gives NAME (a ``<xacro:property value>``, or an ``<xacro:arg default>``, as
xacro takes it when no argument is passed) that is plain text, or a ``$(find PKG)`` and
plain text: a name given two values names both files (xacro takes the one defined before the
include). Anything else (an expression, a value from another file) names nothing. Pure.
"""

from __future__ import annotations

import itertools
import re

_DEFINITION = re.compile(rb"<xacro:(property|arg)\b([^>]*?)/?>", re.DOTALL)
_ATTRIBUTE = re.compile(rb"([\w:.-]+)\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_USE = re.compile(r"\$\{\s*([A-Za-z_]\w*)\s*\}|\$\(arg\s+([A-Za-z_]\w*)\s*\)")
_FIND = re.compile(r"\$\(find\s+[^)\s$]+\s*\)")
_MOST_NAMES = 16  # files one include may name, its constants' values combined

Values = dict[str, tuple[str, ...]]


def constants(text: bytes) -> tuple[Values, Values]:
    """The properties and arguments of ``text``, each with its plain values, in order.

    Plain: no ``$`` but a ``$(find PKG)``, no ``&`` (an escape) and no edge blanks.
    """
    found: dict[str, dict[str, dict[str, None]]] = {"property": {}, "arg": {}}
    for kind, attributes in _DEFINITION.findall(text):
        values = {name.decode(): (double or single).decode("utf-8", "replace")
                  for name, double, single in _ATTRIBUTE.findall(attributes)}
        name = values.get("name")
        value = values.get("value" if kind == b"property" else "default")
        if name is not None and value is not None and _plain(value):
            found[kind.decode()].setdefault(name, {})[value] = None
    return ({name: tuple(values) for name, values in found["property"].items()},
            {name: tuple(values) for name, values in found["arg"].items()})


def substituted(target: str, properties: Values, arguments: Values) -> list[str]:
    """Every name ``target`` makes with its ``${NAME}`` and ``$(arg NAME)`` replaced.

    None where one of them is given no plain value.
    """
    uses = list(_USE.finditer(target))
    if not uses:
        return [target]
    choices = []
    for use in uses:
        name, arg = use.groups()
        values = properties.get(name) if name is not None else arguments.get(arg)
        if not values:
            return []
        choices.append(values)
    names = []
    for picked in itertools.islice(itertools.product(*choices), _MOST_NAMES):
        parts, at = [], 0
        for use, value in zip(uses, picked, strict=True):
            parts += [target[at:use.start()], value]
            at = use.end()
        result = "".join(parts) + target[at:]
        if "${" not in result and "$(arg" not in result:
            names.append(result)
    return names


def _plain(value: str) -> bool:
    return ("$" not in _FIND.sub("", value) and "&" not in value
            and value.strip() == value)
