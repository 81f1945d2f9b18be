"""CSV rows put together in bulk read as numpy's own text of every number, line by line."""

from __future__ import annotations

import csv
import io

import numpy as np

from servicebot_cli.simulate.files.csv_out import _rows, _shortest_text


def _one_by_one(columns) -> str:
    matrix = np.column_stack([np.asarray(c, dtype=float) for c in columns])
    return "".join(",".join(str(v) for v in row) + "\n" for row in matrix.astype(str).tolist())


def test_rows_match_numpy_text_of_each_number():
    rng = np.random.default_rng(5)
    special = np.array([0.0, -0.0, np.inf, -np.inf, np.nan, 5e-324, 1e16, 1e-5, 0.1, 1.0,
                        -1.7976931348623157e308, 123456789.0])
    columns = [np.arange(500) * 0.01,  # 0.0, 0.01, ... with their rounding
               rng.choice(special, 500),
               np.round(rng.uniform(0.1, 12.0, 500) / 0.015) * 0.015,  # repeats, like ranges
               rng.normal(0.0, 1e-3, 500)]
    text = _rows(columns)
    assert text == _one_by_one(columns)
    back = [[float(x) for x in row] for row in csv.reader(io.StringIO(text))]
    assert np.array_equal(np.array(back), np.column_stack(columns), equal_nan=True)
    assert "-0.0" in text and "5e-324" in text


def test_one_column_one_row_and_none():
    assert _rows([np.array([0.25, 0.25, -0.0])]) == "0.25\n0.25\n-0.0\n"
    assert _rows([np.array([1.5]), np.array([2.0])]) == "1.5,2.0\n"
    assert _rows([np.zeros(0), np.zeros(0)]) == ""
    assert _rows([]) == ""


# numbers are written by orjson (Ryu) where its text is numpy's, by numpy elsewhere
EDGES = [0.0, -0.0, 1.0, 0.1, -2.5, 1e-4, -1e-4, 9.999999999999999e-05, 1e-5, 5e-324,
         123456789012345.6, 9999999999999998.0, 1e16, -1e16, 1.7976931348623157e308,
         np.inf, -np.inf, np.nan, 2.4281565503824527e-05, 1.7752556706671923]


def test_the_text_is_numpys_and_reads_back_to_the_same_float():
    rng = np.random.default_rng(7)
    values = np.concatenate([EDGES, rng.uniform(0.12, 12, 2000), rng.normal(size=2000) * 1e-3,
                             rng.normal(size=2000) * 1e12])
    text = _shortest_text(values)
    assert [t.decode() for t in text] == [str(v) for v in values.astype(str)]
    finite = np.isfinite(values)
    assert np.array_equal(text[finite].astype(np.float64).view(np.int64),
                          values[finite].view(np.int64))  # the same bits, -0.0 included


def test_rows_of_only_exponents_or_only_plain_numbers():
    assert _rows([np.array([1e-5, np.inf]), np.array([-np.inf, 2e20])]) == \
        "1e-05,-inf\ninf,2e+20\n"
    assert _rows([np.array([0.5, 1.25]), np.array([3.0, -0.0])]) == "0.5,3.0\n1.25,-0.0\n"
