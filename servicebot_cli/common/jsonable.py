"""Stable JSON for scripts: dataclasses, numpy values and paths to plain JSON.

Keys keep the declaration order of dataclass fields (never sorted at random), floats that are
not finite become ``null`` (JSON has no NaN), and the output ends with a newline. Indented
documents without floats (``check``'s reports) are written by orjson, forty times as fast as
the json module's indenting encoder and the same text; a float is written as Python writes it
(``1e-05``, where orjson writes ``0.00001``), so documents holding one go through json.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Mapping
from enum import Enum
from pathlib import PurePath
from typing import Any


def to_jsonable(value: Any) -> Any:
    """``value`` as nested dicts, lists, strings, numbers, booleans and None."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {
            f.name: to_jsonable(getattr(value, f.name))
            for f in dataclasses.fields(value)
            if f.repr  # fields hidden from repr (XML elements, caches) stay out of JSON too
        }
    if isinstance(value, Enum):
        return to_jsonable(value.value)
    if isinstance(value, Mapping):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple | set | frozenset):
        return [to_jsonable(v) for v in value]
    if isinstance(value, PurePath):
        return str(value)
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return to_jsonable(value.tolist())
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    return value


def dumps(value: Any, *, indent: int | None = 2) -> str:
    """``value`` as JSON text with a trailing newline."""
    plain = to_jsonable(value)
    if indent == 2 and not _holds_float(plain):
        return dumps_plain(plain)
    return json.dumps(plain, indent=indent, ensure_ascii=False, allow_nan=False) + "\n"


def dumps_plain(plain: Any) -> str:
    """:func:`dumps` of a document already plain and without floats: nothing is walked.

    The document holds dicts (string keys), lists, tuples, strings, integers, booleans and
    None. ``check``'s report of a thousand files is such a document, and walking it took longer
    than writing it.
    """
    import orjson

    try:
        return orjson.dumps(plain, option=orjson.OPT_INDENT_2).decode() + "\n"
    except TypeError:  # an integer beyond 64 bits, a lone surrogate: json writes them
        return json.dumps(plain, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def _holds_float(plain: Any) -> bool:
    """Whether a float is anywhere in ``plain`` (nested dicts and lists)."""
    stack = [plain]
    while stack:
        item = stack.pop()
        kind = type(item)
        if kind is float:
            return True
        if kind is dict:
            stack.extend(item.values())
        elif kind is list:
            stack.extend(item)
    return False
