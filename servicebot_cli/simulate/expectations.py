"""Expectations over a run's summary: ``FIELD OP NUMBER``, parsed without ``eval``.

``odometry_drift.final_position_m < 0.5``, ``collisions == 0``, ``distance_m >= 3``.
FIELD is a dotted path into the summary (``[i]`` indexes a list; a list compared whole is its
length, so ``collisions`` is the number of collisions); OP is one of ``< <= > >= == !=``;
NUMBER is a finite decimal number. Field names are checked against the summary's keys
before any run. A field without a value in a run (``null``) fails the expectation.

One parser for ``simulate --expect`` and the ``expect:`` list of a sweep file.
"""

from __future__ import annotations

import difflib
import math
import operator
import re
import types
import typing
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from servicebot_cli.simulate.scenario.fields import FieldPathError, parse_field
from servicebot_cli.simulate.scenario.located import dotted

OPERATORS: dict[str, Callable[[float, float], bool]] = {
    "<=": operator.le, ">=": operator.ge, "==": operator.eq, "!=": operator.ne,
    "<": operator.lt, ">": operator.gt,
}
_EXPECTATION = re.compile(r"^\s*(?P<field>[^<>=!\s]+)\s*(?P<op><=|>=|==|!=|<|>)\s*"
                          r"(?P<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*$")


class ExpectationError(ValueError):
    """An expectation that is not ``FIELD OP NUMBER`` or names a field the summary lacks."""


@dataclass(frozen=True)
class Expectation:
    """A parsed expectation.

    Attributes:
        text: As written.
        field: The summary field's path.
        op: The comparison operator.
        number: The number compared with.
    """

    text: str
    field: tuple[str | int, ...]
    op: str
    number: float

    def value(self, summary: Mapping[str, Any]) -> float | None:
        """The field's value in ``summary`` (a list's length); None when absent or null."""
        node: Any = summary
        for part in self.field:
            if isinstance(part, int) and isinstance(node, list) and part < len(node):
                node = node[part]
            elif isinstance(part, str) and isinstance(node, Mapping) and part in node:
                node = node[part]
            else:
                return None
        if isinstance(node, list):
            return float(len(node))
        if isinstance(node, bool) or not isinstance(node, int | float):
            return None
        return float(node)

    def why_no_value(self, summary: Mapping[str, Any]) -> str:
        """What the field is in ``summary`` where it has no value: absent (and what is), null."""
        node: Any = summary
        for depth, part in enumerate(self.field):
            where = dotted(self.field[:depth]) or "the summary"
            if isinstance(node, Mapping) and isinstance(part, str) and part not in node:
                held = ", ".join(map(str, node)) or "nothing"
                return f"no value: the run has no '{part}' in {where}, which holds {held}"
            if isinstance(node, list) and (isinstance(part, str) or part >= len(node)):
                return f"no value: {where} holds {len(node)} items"
            if isinstance(node, Mapping) and isinstance(part, int):
                return f"no value: {where} is keyed by name"
            if isinstance(node, Mapping):
                node = node[part]
            elif isinstance(node, list) and isinstance(part, int):
                node = node[part]
            else:
                return f"no value: {where} is {_shown(node)}, with nothing below it"
        return "no value: null" if node is None else \
            f"no value: {dotted(self.field)} is {_shown(node)}, not a number"

    def holds(self, summary: Mapping[str, Any]) -> bool:
        """Whether ``summary`` meets the expectation (False when the field has no value)."""
        value = self.value(summary)
        return value is not None and not math.isnan(value) \
            and OPERATORS[self.op](value, self.number)


def _shown(value: Any) -> str:
    """A summary value as an expectation's failure names it: null, a number, a mapping."""
    if value is None:
        return "null"
    if isinstance(value, Mapping):
        return "a mapping of " + (", ".join(map(str, value)) or "nothing")
    return repr(value)


def parse_expectation(text: str) -> Expectation:
    """Parse ``FIELD OP NUMBER`` and check FIELD against the summary's keys.

    Raises:
        ExpectationError: Malformed, a number that is not finite, or an unknown field.
    """
    match = _EXPECTATION.match(text)
    if match is None:
        raise ExpectationError(f"'{text}' is not FIELD OP NUMBER, e.g. 'collisions == 0' "
                               "(OP is one of < <= > >= == !=)")
    number = float(match.group("number"))
    if not math.isfinite(number):
        raise ExpectationError(f"'{match.group('number')}' is not a finite number")
    try:
        path = parse_field(match.group("field"))
    except FieldPathError:
        raise ExpectationError(f"'{match.group('field')}' is not a summary field like "
                               "odometry_drift.final_position_m") from None
    _check_field(path)
    return Expectation(text.strip(), path, match.group("op"), number)


def _check_field(path: tuple[str | int, ...]) -> None:
    """Follow ``path`` through the summary's types, to something that can be a number.

    A TypedDict's fields are known; a mapping's keys are a run's own (``messages./scan``),
    any name passing unless every run has the same ones (``controller``'s); a list's items
    are not followed. The field must end where a number or a list (its length) can be.
    """
    from servicebot_cli.simulate.summary import Summary

    node: Any = Summary
    for depth, part in enumerate(path):
        where = dotted(path[:depth]) or "the summary"
        hints = _typed_dict_hints(node)
        value = _mapping_value(node)
        if hints is not None:
            if isinstance(part, int):
                raise ExpectationError(f"{where} is no list: name one of its fields, "
                                       f"{', '.join(hints)}")
            if part not in hints:
                raise ExpectationError(f"'{part}' is not a field of {where}; "
                                       f"{_closest(part, hints)}")
            node = hints[part]
        elif value is not None:
            if isinstance(part, int):
                raise ExpectationError(f"{where} is keyed by name, not by [{part}]: write "
                                       f"{where}.NAME (a topic as {where}./scan)")
            known = _known_keys().get(path[:depth])
            if known is not None and part not in known:
                raise ExpectationError(f"'{part}' is not a key of {where}; "
                                       f"{_closest(part, known)}")
            if known is not None and known[part] is str and path[depth + 1:] == ("value",):
                raise ExpectationError(f"{dotted(path)} is text, not a number")
            node = value
        elif (item := _list_item(node)) is not None:
            if isinstance(part, str):
                raise ExpectationError(f"{where} is a list: compare {where} (its length) or an "
                                       f"item, {where}[0]" + (
                                           f".{part}" if _typed_dict_hints(item) else ""))
            node = item
        else:
            raise ExpectationError(f"{where} is a value, with nothing below it: compare "
                                   f"{where} itself")
    _refuse_no_number(dotted(path), node)


def _refuse_no_number(field: str, annotation: Any) -> None:
    """Refuse a field whose type can hold no number: text, or a group of fields or keys."""
    hints = _typed_dict_hints(annotation)
    if hints is not None:
        raise ExpectationError(f"{field} holds fields, not a number: compare one of them, "
                               f"e.g. {field}.{next(iter(hints))}")
    if _mapping_value(annotation) is not None:
        example = "/scan" if field == "messages" else "NAME"
        raise ExpectationError(f"{field} holds a value per name, not a number: compare one, "
                               f"e.g. {field}.{example}")
    kinds = _kinds(annotation)
    if kinds and all(kind is str for kind in kinds):
        raise ExpectationError(f"{field} is text, not a number")


def _closest(name: str, names: Iterable[str]) -> str:
    """``did you mean 'X'?`` for the name of ``names`` closest to ``name``, else them all."""
    known = list(names)
    close = difflib.get_close_matches(name, known, n=1, cutoff=0.6)
    return f"did you mean '{close[0]}'?" if close else f"known: {', '.join(known)}"


def _list_item(annotation: Any) -> Any:
    """The item type of a ``list[T]`` annotation (or of ``... | None``); None if none."""
    return _type_argument(annotation, list, 0)


def _type_argument(annotation: Any, origin: type, index: int) -> Any:
    """Argument ``index`` of ``annotation`` (or of a member of its union) whose origin is
    ``origin``: ``list[T]``'s T, ``dict[K, V]``'s V; None if it is none of those.
    """  # noqa: D205
    for kind in _kinds(annotation):
        if typing.get_origin(kind) is origin:
            return typing.get_args(kind)[index]
    return None


def _kinds(annotation: Any) -> tuple[Any, ...]:
    """The types ``annotation`` may be: a union's members but None, else itself."""
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        return tuple(a for a in typing.get_args(annotation) if a is not type(None))
    return (annotation,)


def _known_keys() -> dict[tuple[str | int, ...], dict[str, Any]]:
    """The keys every run's summary has in a mapping, by its path, with their values' types:
    ``controller``'s fields.
    """  # noqa: D205
    import dataclasses

    from servicebot_cli.simulate.scenario.definition import Controller

    hints = typing.get_type_hints(Controller)
    return {("controller",): {f.name: hints[f.name] for f in dataclasses.fields(Controller)}}


def _mapping_value(annotation: Any) -> Any:
    """The value type of a ``dict[str, V]`` annotation (or of ``... | None``); None if none."""
    return _type_argument(annotation, dict, 1)


def _typed_dict_hints(annotation: Any) -> dict[str, Any] | None:
    """The fields of a TypedDict annotation (or of ``X | None``); None for anything else."""
    for candidate in _kinds(annotation):
        if typing.is_typeddict(candidate):
            return typing.get_type_hints(candidate)
    return None
