"""YAML and JSON documents as plain values, remembering where each value was written.

Scenario errors must name the field and its line. PyYAML's composed nodes carry start marks;
JSON is read by a small parser that records the same. Both give ``(value, positions)``:
plain dicts, lists, strings, numbers, booleans and None, and a map from each value's path
(a tuple of keys and indices) to its 1-based ``(line, column)``.
"""

from __future__ import annotations

import datetime
import functools
import json
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, NoReturn, TypeAlias

from servicebot_cli.common.errors import ServicebotError

if TYPE_CHECKING:
    from yaml import Node, SafeLoader  # type: ignore[import-untyped]  # PyYAML ships no types

Path = tuple[str | int, ...]
Positions = dict[Path, tuple[int, int]]
Scalar: TypeAlias = "str | int | float | bool | None | bytes | datetime.date"
"""A leaf value: what JSON or PyYAML's safe loader makes of a scalar."""
Value: TypeAlias = "dict[str, Value] | list[Value] | Scalar"
"""A document or any value inside one."""

MAX_DEPTH = 100
"""Deepest nesting of lists and mappings read; a scenario needs five or six levels."""
MAX_VALUES = 1_000_000
"""Most values a document may hold once YAML aliases are expanded (``*name`` repeats)."""


class ScenarioError(ServicebotError):
    """A scenario file that cannot be read, parsed or validated; names the file and line."""


@dataclass(frozen=True)
class Located:
    """A parsed document and where each of its values was written.

    Attributes:
        value: The document as plain Python values.
        positions: Path of each value to its 1-based ``(line, column)``.
        display: The file as the user named it.
    """

    value: Value
    positions: Positions
    display: str

    def where(self, path: Path) -> str:
        """``file:line`` of ``path``, or of its closest enclosing value that has a position."""
        for end in range(len(path), -1, -1):
            if path[:end] in self.positions:
                line, _ = self.positions[path[:end]]
                return f"{self.display}:{line}"
        return self.display

    def error(self, path: Path, message: str) -> ScenarioError:
        """A ScenarioError ``file:line: field: message``."""
        return ScenarioError(f"{self.where(path)}: {dotted(path) or 'scenario'}: {message}")


def dotted(path: Path) -> str:
    """``cmd_vel[2].linear_m_s`` for ``("cmd_vel", 2, "linear_m_s")``."""
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else part)
    return text


def parse(text: str, display: str, *, json_syntax: bool) -> Located:
    """Parse ``text`` as JSON or YAML.

    Raises:
        ScenarioError: Not well-formed, with the line and column of the problem.
    """
    if json_syntax:
        return _JsonParser(text, display).document()
    return _parse_yaml(text, display)


_BOOL, _INT, _FLOAT = (f"tag:yaml.org,2002:{kind}" for kind in ("bool", "int", "float"))
_MERGE = "tag:yaml.org,2002:merge"


@functools.cache
def _yaml_loader() -> type[SafeLoader]:
    """PyYAML's safe loader, reading booleans and numbers as YAML 1.2's core schema does.

    PyYAML follows YAML 1.1: ``1e2`` (an exponent without a dot) is a string, ``010`` is 8
    (octal), ``1:30`` is 90 (base 60), ``1_0`` is 10 and ``yes``/``on`` are true. YAML 1.2,
    JSON and every person writing a scenario read ``1e2`` as a number, ``010`` as 10, and the
    others as the strings they are (which the scenario then refuses as no number).
    """
    import yaml

    base = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's parser when built with it

    class Loader(base):  # type: ignore[misc, valid-type]  # PyYAML ships no types
        """SafeLoader with YAML 1.2's core schema for booleans, integers and floats."""

    Loader.yaml_implicit_resolvers = {
        first: [(tag, regexp) for tag, regexp in resolvers if tag not in (_BOOL, _INT, _FLOAT)]
        for first, resolvers in base.yaml_implicit_resolvers.items()}
    Loader.add_implicit_resolver(_BOOL, re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
                                 list("tTfF"))
    Loader.add_implicit_resolver(_INT, re.compile(r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$"),
                                 list("-+0123456789"))
    Loader.add_implicit_resolver(
        _FLOAT, re.compile(r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
                           r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$"),
        list("-+0123456789."))
    Loader.add_constructor(_INT, _core_int)
    return Loader


def _core_int(loader: SafeLoader, node: Node) -> int:
    """An integer as YAML 1.2 writes it: decimal (``010`` is 10), ``0o`` octal, ``0x`` hex."""
    text = str(loader.construct_scalar(node))
    if text.startswith(("0o", "0x")):
        return int(text[2:], 8 if text[1] == "o" else 16)
    return int(text)


def _parse_yaml(text: str, display: str) -> Located:
    import yaml  # PyYAML ships no types

    try:
        node = yaml.compose(text, Loader=_yaml_loader())
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        line = f":{mark.line + 1}" if mark is not None else ""
        raise ScenarioError(f"{display}{line}: not valid YAML: {exc.problem}") from None
    except yaml.YAMLError as exc:
        raise ScenarioError(f"{display}: not valid YAML: {exc}") from None
    except RecursionError:  # PyYAML's own composer, where libyaml is not built
        raise ScenarioError(f"{display}: lists and mappings nested over {MAX_DEPTH} deep; "
                            "is it the right file?") from None
    positions: Positions = {}
    if node is None:
        return Located({}, positions, display)
    walk = _YamlWalk(_yaml_loader()(text), display)
    return Located(walk.value(node, (), positions), positions, display)


class _YamlWalk:
    """Composed YAML nodes to plain values, bounded: aliases (``*name``) share nodes.

    An alias inside the value it names would recurse forever, and aliases of aliases
    (YAML's billion laughs) expand exponentially; both are refused with their line.
    """

    def __init__(self, constructor: SafeLoader, display: str) -> None:
        self.constructor, self.display = constructor, display
        self.count = 0
        self.open: set[int] = set()  # ids of the collections being walked

    def value(self, node: Node, path: Path, positions: Positions) -> Value:
        line = node.start_mark.line + 1
        self.count += 1
        if self.count > MAX_VALUES:
            raise ScenarioError(f"{self.display}:{line}: {dotted(path) or 'document'}: aliases "
                                f"(*name) expand the document past {MAX_VALUES} values; write "
                                "out what they repeat")
        if len(path) > MAX_DEPTH:
            raise ScenarioError(f"{self.display}:{line}: {dotted(path)}: lists and mappings "
                                f"nested over {MAX_DEPTH} deep; is it the right file?")
        if id(node) in self.open:
            raise ScenarioError(f"{self.display}:{line}: {dotted(path) or 'document'}: an alias "
                                "(*name) inside the value it names repeats forever; write the "
                                "value out")
        self.open.add(id(node))
        try:
            return _yaml_value(node, path, positions, self)
        finally:
            self.open.discard(id(node))


def _yaml_value(node: Node, path: Path, positions: Positions, walk: _YamlWalk) -> Value:
    import yaml

    constructor, display = walk.constructor, walk.display
    positions[path] = (node.start_mark.line + 1, node.start_mark.column + 1)
    if isinstance(node, yaml.MappingNode):
        result: dict[str, Value] = {}
        merged: list[dict[str, Value]] = []  # YAML's merge keys (<<: *defaults)
        for key_node, value_node in node.value:
            where = f"{display}:{key_node.start_mark.line + 1}: {dotted(path) or 'document'}"
            if not isinstance(key_node, yaml.ScalarNode):
                raise ScenarioError(f"{where}: a key that is a list or mapping; keys are names")
            if key_node.tag == _MERGE:
                merged += _merged(walk.value(value_node, path, {}), where)
                continue
            try:
                key = str(constructor.construct_object(key_node, deep=True))
            except yaml.YAMLError as exc:  # a tag no constructor knows (!foo key)
                raise ScenarioError(f"{where}: a key YAML cannot read: {exc.problem}") from None
            if key in result:
                raise ScenarioError(
                    f"{display}:{key_node.start_mark.line + 1}: {dotted((*path, key))}: "
                    "given twice; keep one"
                )
            result[key] = walk.value(value_node, (*path, key), positions)
        for mapping in merged:  # keys written in the mapping itself win, as YAML merges
            result = {**mapping, **result}
        return result
    if isinstance(node, yaml.SequenceNode):
        return [walk.value(item, (*path, i), positions) for i, item in enumerate(node.value)]
    line = node.start_mark.line + 1
    try:
        scalar: Scalar = constructor.construct_object(node, deep=True)
    except yaml.YAMLError as exc:
        raise ScenarioError(f"{display}:{line}: {dotted(path)}: {exc}") from None
    except ValueError:  # an integer of more digits than Python converts
        raise ScenarioError(f"{display}:{line}: {dotted(path)}: expected a finite number, "
                            "got an integer too long to read") from None
    return scalar


def _merged(value: Value, where: str) -> list[dict[str, Value]]:
    """The mappings a merge key (``<<:``) brings: one, or a list of them, first first."""
    mappings = value if isinstance(value, list) else [value]
    if not all(isinstance(m, dict) for m in mappings):
        raise ScenarioError(f"{where}: a merge key (<<) takes a mapping or a list of them")
    return [m for m in reversed(mappings) if isinstance(m, dict)]  # the first wins


_NUMBER = re.compile(r"-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][-+]?\d+)?")
_WHITESPACE = re.compile(r"[ \t\n\r]*")
_LITERALS = {"true": True, "false": False, "null": None}
_DECODER = json.JSONDecoder()


class _JsonParser:
    """Strict JSON (RFC 8259) with the position of every value."""

    def __init__(self, text: str, display: str) -> None:
        self.text, self.display, self.pos = text, display, 0
        self.positions: Positions = {}

    def document(self) -> Located:
        value = self.value(())
        self.skip()
        if self.pos != len(self.text):
            self.fail("extra data after the document")
        return Located(value, self.positions, self.display)

    def fail(self, reason: str) -> NoReturn:
        line = self.text.count("\n", 0, self.pos) + 1
        raise ScenarioError(f"{self.display}:{line}: not valid JSON: {reason}")

    def skip(self) -> None:
        blank = _WHITESPACE.match(self.text, self.pos)
        assert blank is not None  # the pattern matches the empty string
        self.pos = blank.end()

    def value(self, path: Path) -> Value:
        self.skip()
        line = self.text.count("\n", 0, self.pos) + 1
        column = self.pos - (self.text.rfind("\n", 0, self.pos) + 1) + 1
        self.positions[path] = (line, column)
        char = self.text[self.pos:self.pos + 1]
        if len(path) >= MAX_DEPTH and char in "{[":
            self.fail(f"lists and objects nested over {MAX_DEPTH} deep; is it the right file?")
        if char == "{":
            return self.object(path)
        if char == "[":
            return self.array(path)
        if char == '"':
            return self.string()
        for word, literal in _LITERALS.items():
            if self.text.startswith(word, self.pos):
                self.pos += len(word)
                return literal
        match = _NUMBER.match(self.text, self.pos)
        if not match:
            self.fail(f"unexpected {char!r}" if char else "unexpected end of file")
        self.pos = match.end()
        try:
            number: int | float = json.loads(match.group())
        except ValueError:  # an integer of more digits than Python converts
            self.fail("a number too long to read")
        return number

    def string(self) -> str:
        try:
            text, self.pos = _DECODER.raw_decode(self.text, self.pos)
        except json.JSONDecodeError as exc:
            self.fail(exc.msg)
        return str(text)

    def object(self, path: Path) -> dict[str, Value]:
        result: dict[str, Value] = {}
        self.pos += 1
        self.skip()
        if self.text.startswith("}", self.pos):
            self.pos += 1
            return result
        while True:
            self.skip()
            if not self.text.startswith('"', self.pos):
                self.fail("expected a quoted key")
            key = self.string()
            if key in result:
                self.fail(f"{dotted((*path, key))}: given twice; keep one")
            self.skip()
            if not self.text.startswith(":", self.pos):
                self.fail(f"expected ':' after key {key!r}")
            self.pos += 1
            result[key] = self.value((*path, key))
            if self.separator("}"):
                return result

    def array(self, path: Path) -> list[Value]:
        result: list[Value] = []
        self.pos += 1
        self.skip()
        if self.text.startswith("]", self.pos):
            self.pos += 1
            return result
        while True:
            result.append(self.value((*path, len(result))))
            if self.separator("]"):
                return result

    def separator(self, close: str) -> bool:
        """Consume ``,`` (False: more follows) or ``close`` (True: done)."""
        self.skip()
        char = self.text[self.pos:self.pos + 1]
        self.pos += 1
        if char == close:
            return True
        if char != ",":
            self.fail(f"expected ',' or '{close}'" + (f", found {char!r}" if char else ""))
        return False
