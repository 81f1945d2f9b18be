"""The type of JSON values: what batch lines hold when read and what result rows hold."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TypeAlias

JsonValue: TypeAlias = (
    "str | int | float | bool | None | Sequence[JsonValue] | Mapping[str, JsonValue]"
)
"""A JSON value: a string, number, boolean, null, array or object."""

JsonObject: TypeAlias = dict[str, JsonValue]
"""A JSON object: a batch input line, or one result row."""
