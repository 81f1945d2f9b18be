"""Typed reading of a located document: every bad field is named, with its line.

A :class:`Reader` walks a :class:`~.located.Located` document and turns
values into numbers, strings, lists and checked sub-objects, or raises one ScenarioError
naming the file, the line, the field and what is expected.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable, Sequence
from typing import TypeVar

from servicebot_cli.simulate.scenario.located import Located, Path, ScenarioError, Value

T = TypeVar("T")


class Reader:
    """Typed access to the values of a located document."""

    def __init__(self, located: Located) -> None:
        self.located = located

    def error(self, path: Path, message: str) -> ScenarioError:
        """The error for ``path``."""
        return self.located.error(path, message)

    def get(self, path: Path) -> Value:
        """The raw value at ``path`` (KeyError/IndexError when absent)."""
        value = self.located.value
        for part in path:
            if isinstance(value, dict) and isinstance(part, str):
                value = value[part]
            elif isinstance(value, list) and isinstance(part, int):
                value = value[part]
            else:
                raise KeyError(part)
        return value

    def has(self, path: Path) -> bool:
        """True when ``path`` is present and not null."""
        try:
            return self.get(path) is not None
        except (KeyError, IndexError, TypeError):
            return False

    def mapping(self, path: Path, allowed: Sequence[str], required: Sequence[str] = ()) -> None:
        """Check that ``path`` is a mapping with only ``allowed`` keys and all ``required``."""
        value = self.get(path) if path else self.located.value
        if not isinstance(value, dict):
            raise self.error(path, f"expected a mapping with keys {', '.join(allowed)}, "
                             f"got {_show(value)}")
        for key in value:
            if key not in allowed:
                close = difflib.get_close_matches(key, allowed, n=1, cutoff=0.6)
                hint = f"did you mean '{close[0]}'?" if close else f"known: {', '.join(allowed)}"
                raise self.error((*path, key), f"unknown field; {hint}")
        for key in required:
            if value.get(key) is None:
                raise self.error(path, f"'{key}' is required")

    def number(self, path: Path, default: float | None = None, *, minimum: float | None = None,
               positive: bool = False, maximum: float | None = None) -> float:
        """A finite number, optionally bounded; ``default`` when absent."""
        if not self.has(path):
            if default is None:
                raise self.error(path[:-1], f"'{path[-1]}' is required")
            return default
        value = self.get(path)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.error(path, f"expected a number, got {_show(value)}")
        try:
            number = float(value)
        except OverflowError:
            raise self.error(path, "expected a finite number, got an integer too large for "
                             "a float") from None
        if not math.isfinite(number):
            raise self.error(path, f"expected a finite number, got {value}")
        if positive and number <= 0:
            raise self.error(path, f"must be positive, got {number:g}")
        if minimum is not None and number < minimum:
            raise self.error(path, f"must be at least {minimum:g}, got {number:g}")
        if maximum is not None and number > maximum:
            raise self.error(path, f"must be at most {maximum:g}, got {number:g}")
        return number

    def string(self, path: Path, default: str | None = None,
               choices: Sequence[str] | None = None) -> str:
        """A string, optionally one of ``choices``."""
        if not self.has(path):
            if default is None:
                raise self.error(path[:-1], f"'{path[-1]}' is required")
            return default
        value = self.get(path)
        if not isinstance(value, str) or not value:
            raise self.error(path, f"expected a non-empty string, got {_show(value)}")
        if choices is not None and value not in choices:
            raise self.error(path, f"'{value}' is not one of: {', '.join(choices)}")
        return value

    def vector(self, path: Path, length: int | Sequence[int], default: Sequence[float] | None
               = None) -> tuple[float, ...]:
        """A list of ``length`` numbers (or one of several lengths)."""
        lengths = (length,) if isinstance(length, int) else tuple(length)
        if not self.has(path):
            if default is None:
                raise self.error(path[:-1], f"'{path[-1]}' is required")
            return tuple(default)
        value = self.get(path)
        if not isinstance(value, list) or len(value) not in lengths:
            want = " or ".join(str(n) for n in lengths)
            raise self.error(path, f"expected a list of {want} numbers, got {_show(value)}")
        return tuple(self.number((*path, i)) for i in range(len(value)))

    def pair(self, path: Path) -> tuple[float, float]:
        """A list of two numbers (a point on the floor)."""
        x, y = self.vector(path, 2)
        return x, y

    def triple(self, path: Path, default: tuple[float, float, float] | None = None
               ) -> tuple[float, float, float]:
        """A list of three numbers; ``default`` when absent."""
        x, y, z = self.vector(path, 3, default)
        return x, y, z

    def items(self, path: Path, read: Callable[[Path], T]) -> tuple[T, ...]:
        """Each element of the list at ``path`` read by ``read``; empty when absent."""
        if not self.has(path):
            return ()
        value = self.get(path)
        if not isinstance(value, list):
            raise self.error(path, f"expected a list, got {_show(value)}")
        return tuple(read((*path, i)) for i in range(len(value)))


def _show(value: Value) -> str:
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    if value is None:
        return "nothing"
    return repr(value)
