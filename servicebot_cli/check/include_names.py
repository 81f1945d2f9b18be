"""Include filenames computed from a file's own constants, read as xacro would read them.

RoverSimulation's robot includes its parts as ``$(find ${package_name})/urdf/part.xacro``,
``package_name`` being a property of the same file with a plain value. Read as written, the
name named no file: the parts were checked alone, as robots, and failed (SB006) where xacro
expands the robot. A ``${NAME}`` or ``$(arg NAME)`` in a filename is replaced here by the
value the file gives NAME (a ``<xacro:property value>``, or an ``<xacro:arg default>``, as
xacro takes it when no argument is passed), when that value is plain text and the only one
the file gives. Anything else (an expression, a value from another file, two values) leaves
the name unread, as before. Pure.
"""

from __future__ import annotations

import re

_DEFINITION = re.compile(rb"<xacro:(property|arg)\b([^>]*?)/?>", re.DOTALL)
_ATTRIBUTE = re.compile(rb"([\w:.-]+)\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_USE = re.compile(r"\$\{\s*([A-Za-z_]\w*)\s*\}|\$\(arg\s+([A-Za-z_]\w*)\s*\)")


def constants(text: bytes) -> tuple[dict[str, str], dict[str, str]]:
    """The properties and arguments of ``text`` that have one plain value each.

    Plain: no ``$`` (no expression or substitution), no ``&`` (an escape) and no edge blanks.
    """
    found: dict[str, dict[str, set[str]]] = {"property": {}, "arg": {}}
    for kind, attributes in _DEFINITION.findall(text):
        values = {name.decode(): (double or single).decode("utf-8", "replace")
                  for name, double, single in _ATTRIBUTE.findall(attributes)}
        name = values.get("name")
        value = values.get("value" if kind == b"property" else "default")
        if name is not None and value is not None:
            found[kind.decode()].setdefault(name, set()).add(value)
    properties, arguments = ({name: values.pop() for name, values in table.items()
                              if len(values) == 1 and _plain(next(iter(values)))}
                             for table in (found["property"], found["arg"]))
    return properties, arguments


def substituted(target: str, properties: dict[str, str], arguments: dict[str, str]) -> str | None:
    """``target`` with its ``${NAME}`` and ``$(arg NAME)`` replaced; None where one is unknown."""
    unknown = False

    def value(use: re.Match[str]) -> str:
        nonlocal unknown
        name, arg = use.groups()
        found = properties.get(name) if name is not None else arguments.get(arg)
        if found is None:
            unknown = True
            return use[0]
        return found

    result = _USE.sub(value, target)
    if unknown or "${" in result or "$(arg" in result:
        return None
    return result


def _plain(value: str) -> bool:
    return "$" not in value and "&" not in value and value.strip() == value
