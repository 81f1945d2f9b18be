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
import typing
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from servicebot_cli.simulate.scenario.fields import FieldPathError, parse_field

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

    def holds(self, summary: Mapping[str, Any]) -> bool:
        """Whether ``summary`` meets the expectation (False when the field has no value)."""
        value = self.value(summary)
        return value is not None and not math.isnan(value) \
            and OPERATORS[self.op](value, self.number)


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
    """Follow ``path`` through the summary's TypedDicts; open dicts and lists end the check."""
    from servicebot_cli.simulate.summary import Summary

    hints: dict[str, Any] | None = typing.get_type_hints(Summary)
    for depth, part in enumerate(path):
        if hints is None:
            return
        if isinstance(part, int):
            return
        if part not in hints:
            where = ".".join(str(p) for p in path[:depth]) or "the summary"
            close = difflib.get_close_matches(part, list(hints), n=1, cutoff=0.6)
            hint = f"did you mean '{close[0]}'?" if close else f"known: {', '.join(hints)}"
            raise ExpectationError(f"'{part}' is not a field of {where}; {hint}")
        hints = _typed_dict_hints(hints[part])


def _typed_dict_hints(annotation: Any) -> dict[str, Any] | None:
    """The fields of a TypedDict annotation (or of ``X | None``); None for anything else."""
    for candidate in (annotation, *typing.get_args(annotation)):
        if typing.is_typeddict(candidate):
            return typing.get_type_hints(candidate)
    return None
