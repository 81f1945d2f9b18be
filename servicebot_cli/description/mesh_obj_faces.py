"""An OBJ's face lines read into each corner's vertex index and each face's corner count.

The text is the face lines' contents (after ``f``), joined by newlines. Two readers: one in a
few passes over the corners, for faces written as exporters write them (every corner a
decimal vertex index, then ``/texture/normal`` or nothing); one over the characters, for
anything else a number list can hold. Either says None where only a line-by-line reading
knows the answer (a negative index counts back from the vertices read so far). Pure.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.mesh_arrays import IntArray, MeshFormatError, numbers

_SPACE, _TAB, _NEWLINE, _SLASH, _ZERO = 32, 9, 10, 47, 48
_MOST_DIGITS = 18  # an int64 holds every number of 18 digits
_ODD_BLANKS = (b"\r", b"\x0b", b"\x0c")  # blanks to numpy, not corner separators to the fast reader

Corners = tuple[IntArray, IntArray]


def face_corners(text: bytes, count: int) -> Corners | None:
    """Every corner's vertex index (from 1) and the corner count of each of ``count`` lines.

    None when a corner is not a positive index.
    """
    if count == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    if not any(odd in text for odd in _ODD_BLANKS):
        fast = _plain_corners(text, count)
        if fast is not None:
            return fast
    return _any_corners(text, count)


def _plain_corners(text: bytes, count: int) -> Corners | None:
    """:func:`face_corners` of corners that are digits, then a slash or a blank; else None.

    Any other face text is left to the character reader, which decides what it holds.

    The digits of all corners are read side by side, one digit place per pass: a vertex
    index has at most a few digits.
    """
    chars = np.frombuffer(text + b"\n", dtype=np.uint8)  # a blank after the last digit
    blank = (chars == _SPACE) | (chars == _TAB) | (chars == _NEWLINE)
    after_blank = np.empty_like(blank)
    after_blank[0], after_blank[1:] = True, blank[:-1]
    starts = np.flatnonzero(~blank & after_blank)
    digits = chars - np.uint8(_ZERO)  # a digit's value; anything else 10 or more (uint8)
    values = digits[starts].astype(np.int64)
    if len(values) == 0 or values.max() > 9:
        return None
    places = starts + 1
    for _ in range(_MOST_DIGITS):
        following = digits[places]
        more = following < 10
        if not more.any():
            break
        values = np.where(more, values * 10 + following, values)
        places += more
    else:
        return None
    ends = chars[places]
    if not np.all((ends == _SLASH) | blank[places]) or values.min() < 1:
        return None
    return values, _corner_counts(starts, np.flatnonzero(chars[:-1] == _NEWLINE), count)


def _corner_counts(starts: IntArray, newlines: IntArray, count: int) -> IntArray:
    """How many of the corners starting at ``starts`` each of ``count`` lines holds."""
    if len(starts) % count == 0:  # the same number of corners on every line (triangles)?
        rows = starts.reshape(count, -1)
        if rows.shape[1] and np.all(rows[:-1, -1] < newlines) and np.all(newlines < rows[1:, 0]):
            return np.full(count, rows.shape[1], dtype=np.int64)
    return np.bincount(np.searchsorted(newlines, starts), minlength=count).astype(np.int64)


def _any_corners(text: bytes, count: int) -> Corners | None:
    """:func:`face_corners` of any face text, read one character at a time by numpy."""
    chars = np.frombuffer(text, np.uint8)
    blank = (chars == _SPACE) | (chars == _TAB) | (chars == _NEWLINE)
    if (chars == _SLASH).any():
        chars = _corner_vertices(chars, blank | (chars == ord("\r")) | (chars == ord("\f"))
                                 | (chars == ord("\v")))
        blank = (chars == _SPACE) | (chars == _TAB) | (chars == _NEWLINE)
    starts = ~blank & np.concatenate(([True], blank[:-1]))
    counts = np.bincount(np.cumsum(chars == _NEWLINE)[starts], minlength=count)
    try:
        indices = numbers(chars.tobytes(), np.int64)
    except MeshFormatError:
        return None
    if len(indices) != int(counts.sum()) or (len(indices) and indices.min() < 1):
        return None
    return indices, counts.astype(np.int64)


def _corner_vertices(chars: npt.NDArray[np.uint8], blank: npt.NDArray[np.bool_]
                     ) -> npt.NDArray[np.uint8]:
    """Face text without each corner's texture and normal indices: "7/2/5 8//6" -> "7 8".

    A character stays when it is blank or no slash stands between it and its corner's start.
    """
    slash = chars == _SLASH
    slashes = np.cumsum(slash, dtype=np.int64 if len(chars) >= 2**31 else np.int32)
    starts = np.flatnonzero(~blank & np.concatenate(([True], blank[:-1])))
    at_start = np.zeros(len(chars), slashes.dtype)  # the count before each corner's start
    if len(starts):
        at_start[starts[0]:] = np.repeat(slashes[starts] - slash[starts],
                                         np.diff(np.append(starts, len(chars))))
    kept: npt.NDArray[np.uint8] = chars[(slashes == at_start) | blank]
    return kept
