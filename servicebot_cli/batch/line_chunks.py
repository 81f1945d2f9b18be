"""Chunks of raw CSV lines, split into cells at once: what the chunked batch paths share.

A chunk of lines read with ``itertools.islice`` is numbered and stripped of blank and
comment lines in one go, and its cells split with one ``str.split``. A chunk that holds
anything the simple split could get wrong (a quote, a wrong field count) gives None, and
the caller reads it line by line (see :func:`~servicebot_cli.batch.reading.csv_rows`), where
every error names its line.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Sequence
from typing import IO

import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.reading import meaningful
from servicebot_cli.common.plain_float import plainly_written

FloatArray = npt.NDArray[np.float64]


def chunks(handle: IO[str], before: int, size: int) -> Iterator[list[tuple[int, str]]]:
    """The rest of ``handle`` (its lines follow line ``before``), ``size`` raw lines at a time.

    Each chunk is :func:`numbered`: its meaningful lines only (a chunk of comments is empty).
    """
    while raw := list(itertools.islice(handle, size)):
        yield numbered(raw, before)
        before += len(raw)


def numbered(raw: list[str], before: int) -> list[tuple[int, str]]:
    """``(line number, text)`` of the meaningful lines of ``raw``, which follow line ``before``."""
    text = "".join(raw)
    texts = text.splitlines()
    if "#" not in text and len(texts) == len(raw) and not any(map(str.isspace, raw)):
        return list(zip(range(before + 1, before + 1 + len(raw)), texts, strict=True))
    return [(before + k, line.rstrip("\r\n")) for k, line in enumerate(raw, start=1)
            if meaningful(line)]


def split_cells(texts: Sequence[str], delimiter: str, width: int) -> list[str] | None:
    """Every cell of ``texts``, row after row; None: a line the simple split cannot take.

    That is a quote anywhere, or a line without exactly ``width`` fields.
    """
    joined = delimiter.join(texts)
    cells = joined.split(delimiter)
    if '"' in joined or len(cells) != width * len(texts) or \
            set(map(str.count, texts, itertools.repeat(delimiter))) != {width - 1}:
        return None
    return cells


def numbers(cells: list[str], width: int, columns: Sequence[int]) -> FloatArray | None:
    """The cells of ``columns`` as finite floats, shape (rows, len(columns)); None otherwise.

    numpy reads each cell as ``float()`` does (surrounding blanks), a little faster; an
    empty cell, a word, ``1_000``, a digit beyond ASCII or a non-finite value gives None.
    """
    if not plainly_written(cells):  # float() reads them; no CSV writer means them
        return None
    try:
        if list(columns) == list(range(width)):  # every column, in the file's order
            given = np.array(cells, dtype=np.float64).reshape(-1, width)
        else:
            given = np.array([cells[k::width] for k in columns],
                             dtype=np.float64).reshape(len(columns), -1).T
    except ValueError:
        return None
    return given if np.isfinite(given).all() else None
