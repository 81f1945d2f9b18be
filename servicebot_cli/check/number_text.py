"""Whitespace-separated number lists (mesh files' vertices and indices) read into arrays.

Turning text into numbers is most of what reading a mesh costs. A list written the way
exporters write it (plain decimal numbers, one blank between them) is read as a JSON array by
orjson, three times as fast as ``numpy.fromstring`` and correctly rounded like it (the same
bits: a test compares them on meshes of the corpus). Any other list ("+" before a number,
``.5``, ``1.``, ``nan``, commas, letters, ``-0`` whose sign JSON drops, a float in an index
list) goes to ``numpy.fromstring``, which also decides what is not a number list.
"""

from __future__ import annotations

import warnings

import numpy as np
import orjson

_BLANKS_TO_COMMAS = bytes.maketrans(b" \t\n\r\f\v", b",,,,,,")
# what JSON reads in an array besides numbers (true, false, null, strings, nesting): one of
# these characters is in each; index lists take no fraction or exponent either
_NOT_FLOATS = (b"t", b"f", b"n", b'"', b"[", b"{")
_NOT_INTS = (*_NOT_FLOATS, b".", b"e", b"E")


class NumberListError(ValueError):
    """Text that is not a whitespace-separated list of numbers of the wanted type."""


def numbers(text: str | bytes | None, dtype: type = np.float64) -> np.ndarray:
    """The numbers of ``text`` as a 1-D array of ``dtype`` (float64 or int64).

    Raises:
        NumberListError: An item that is not a number of that type.
    """
    if not text or not text.strip():
        return np.zeros(0, dtype=dtype)
    fast = _as_json(text, dtype)
    if fast is not None:
        return fast
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns, then stops, at the first non-number
        try:
            return np.fromstring(text, dtype=dtype, sep=" ")
        except (ValueError, DeprecationWarning):
            raise NumberListError("a number list holding something that is not a number") from None


def _as_json(text: str | bytes, dtype: type) -> np.ndarray | None:
    """``text`` read as a JSON array, or None when JSON would read it otherwise than numpy."""
    try:
        data = text.encode("ascii") if isinstance(text, str) else text
    except UnicodeEncodeError:
        return None
    if b"," in data:
        return None
    data = data.strip().translate(_BLANKS_TO_COMMAS)
    while b",," in data:
        data = data.replace(b",,", b",")
    if any(c in data for c in (_NOT_FLOATS if dtype is np.float64 else _NOT_INTS)):
        return None  # JSON's strings, literals and nesting; a float where indices are wanted
    if b",+" in data or data.startswith(b"+"):
        return None  # a sign before a number is not JSON
    if b"-0," in data or data.endswith(b"-0"):
        return None  # JSON reads "-0" as the integer 0, numpy as -0.0
    try:
        values = orjson.loads(b"[" + data + b"]")
        if dtype is np.float64:
            return np.fromiter(values, dtype=dtype, count=len(values))
        indices = np.array(values)  # int64 unless orjson made a float of an integer below
        return indices if indices.dtype == np.int64 else None  # -2**63 (or uint64 above)
    except (orjson.JSONDecodeError, OverflowError, ValueError, TypeError):
        return None
