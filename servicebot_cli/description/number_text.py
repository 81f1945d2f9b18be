"""Whitespace-separated number lists (mesh files' vertices and indices) read into arrays.

Turning text into numbers is most of what reading a mesh costs. A list written the way
exporters write it (plain decimal numbers between blanks) is read as a JSON array by
simdjson, straight into a buffer of doubles or int64 with no Python object per number: ten
times as fast as ``numpy.fromstring`` and correctly rounded like it (the same bits: a test
compares them on meshes of the corpus). Any other list ("+" before a number, ``.5``, ``1.``,
``nan``, commas, letters, ``-0`` whose sign JSON drops, a float in an index list) goes to
``numpy.fromstring``, which also decides what is not a number list.
"""

from __future__ import annotations

import threading
import warnings
from typing import Literal

import numpy as np
import simdjson

_BLANKS_TO_COMMAS = bytes.maketrans(b" \t\n\r\f\v", b",,,,,,")
_BUFFER_TYPES: dict[type, Literal["d", "i"]] = {np.float64: "d", np.int64: "i"}
_PARSERS = threading.local()  # a parser keeps its buffers between documents, in one thread


class NumberListError(ValueError):
    """Text that is not a whitespace-separated list of numbers of the wanted type."""


def numbers(text: str | bytes | None, dtype: type = np.float64) -> np.ndarray:
    """The numbers of ``text`` as a 1-D array of ``dtype`` (float64 or int64).

    Raises:
        NumberListError: An item that is not a number of that type.
    """
    if not text or text.isspace():
        return np.zeros(0, dtype=dtype)
    fast = plain_numbers(text, dtype)
    if fast is not None:
        return fast
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns, then stops, at the first non-number
        try:
            return np.fromstring(text, dtype=dtype, sep=" ")
        except (ValueError, DeprecationWarning):
            raise NumberListError("a number list holding something that is not a number") from None


def plain_numbers(text: str | bytes, dtype: type = np.float64) -> np.ndarray | None:
    """``text`` read as a JSON array, or None when JSON would read it otherwise than numpy.

    None also tells a list that is not written plainly: its numbers are still numbers to
    :func:`numbers`, but other readers may take them otherwise (Assimp and ``.5``).

    What JSON refuses (a sign or a point JSON does not write: ``+1``, ``.5``, ``1.``;
    ``01``, ``nan``; strings, literals, objects) goes to numpy; so do blank runs, once
    joined, if JSON then refuses. A ``[`` would nest arrays, which the buffer flattens.
    """
    try:
        data = text.encode("ascii") if isinstance(text, str) else text
    except UnicodeEncodeError:
        return None
    if b"," in data or b"[" in data:
        return None  # a comma is no separator to numpy
    data = data.translate(_BLANKS_TO_COMMAS)
    values = _parsed(data, dtype)
    if values is None:  # blanks before or after the numbers, or runs of them, first?
        joined = data.strip(b",")
        while b",," in joined:  # blank runs: one separator each
            joined = joined.replace(b",,", b",")
        if joined == data:
            return None
        data = joined
        values = _parsed(data, dtype)
        if values is None:
            return None
    if dtype is np.float64 and (values == 0).any() and (b"-0," in data or data.endswith(b"-0")):
        return None  # JSON reads "-0" as the integer 0, numpy as -0.0
    return values


def _parsed(items: bytes, dtype: type) -> np.ndarray | None:
    """The comma-separated ``items`` as a ``dtype`` array; None where JSON refuses them."""
    parser = getattr(_PARSERS, "parser", None)
    if parser is None:
        parser = _PARSERS.parser = simdjson.Parser()
    try:
        document = parser.parse(b"[" + items + b"]")
    except (ValueError, RuntimeError):  # not JSON; an integer beyond 64 bits
        return None
    try:
        if not isinstance(document, simdjson.Array):  # pragma: no cover - always "[...]"
            return None
        values: np.ndarray = np.frombuffer(document.as_buffer(of_type=_BUFFER_TYPES[dtype]),
                                           dtype)
    except (ValueError, TypeError):  # beyond the type's range, or a value of another type
        return None
    finally:
        del document  # the parser is free for the next list only once its document is gone
    return values
