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
# what a list JSON may read as numpy does holds only these (JSON's strings, literals and
# nesting need others); index lists take no fraction or exponent either
_FLOAT_CHARS = b"0123456789.eE+-,"
_INT_CHARS = b"0123456789+-,"
_INT64_MIN = -(2**63)


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
    """``text`` read as a JSON array, or None when JSON would read it otherwise than numpy.

    What JSON refuses (a sign or a point JSON does not write: ``+1``, ``.5``, ``1.``;
    ``01``, ``nan``) goes to numpy; so do blank runs, once joined, if JSON then refuses.
    """
    try:
        data = text.encode("ascii") if isinstance(text, str) else text
    except UnicodeEncodeError:
        return None
    if b"," in data:
        return None  # a comma is no separator to numpy
    data = data.strip().translate(_BLANKS_TO_COMMAS)
    if data.translate(None, _FLOAT_CHARS if dtype is np.float64 else _INT_CHARS):
        return None  # JSON's strings, literals and nesting; a float where indices are wanted
    try:
        try:
            values = orjson.loads(b"[" + data + b"]")
        except orjson.JSONDecodeError:
            if b",," not in data:
                return None
            while b",," in data:  # blank runs: one separator each
                data = data.replace(b",,", b",")
            values = orjson.loads(b"[" + data + b"]")
        if dtype is np.float64:
            floats = np.fromiter(values, dtype=dtype, count=len(values))
            if (floats == 0).any() and (b"-0," in data or data.endswith(b"-0")):
                return None  # JSON reads "-0" as the integer 0, numpy as -0.0
            return floats
        # OverflowError beyond int64, but below it orjson reads a float, which rounds to -2**63
        indices = np.array(values, dtype=np.int64)
        return indices if not len(indices) or indices.min() > _INT64_MIN else None
    except (orjson.JSONDecodeError, OverflowError, ValueError, TypeError):
        return None
