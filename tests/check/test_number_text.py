"""Number lists read through JSON give numpy.fromstring's bits, or fall back to it.

numpy.fromstring is the reference: every list either gives the same array, bit for bit
(-0.0 included), or both refuse it.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from servicebot_cli.description.number_text import NumberListError, numbers, plain_numbers
from tests.check.corpus import erd_root, pybullet_urdfs


def _reference(text: str | bytes, dtype: type) -> np.ndarray | None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            return np.fromstring(text, dtype=dtype, sep=" ")
        except (ValueError, DeprecationWarning):
            return None


def _same(text: str | bytes, dtype: type) -> None:
    expected = _reference(text, dtype)
    try:
        got = numbers(text, dtype)
    except NumberListError:
        assert expected is None, text
        return
    assert expected is not None, text
    assert got.dtype == expected.dtype
    assert got.tobytes() == expected.tobytes(), text


EDGES = ["-0", "0 -0 1", "+1 2", "1 +2", ".5 1", "1. 2", "nan 1", "inf", "1,2 3", "true 1",
         "1 null", "[1]", "1\t2\n3\r\n4  5\f6\v7", "1e400", "-1e400", "1e-400", "1e-0 2",
         "12345678901234567890", "-3.25E+2 1e+05 2E-3", "00.5", "0x10", "1 2 ", "1.5",
         "0.1 0.2 0.30000000000000004", "9007199254740993", "4.9e-324",
         "2.2250738585072011e-308", "123456789012345678901234567890.5", "1e5", "٣ 1", "1 ２",
         "\"1\" 2", "1 {}", "false 0", "1 2e3", "1 -9223372036854775809",
         "-9223372036854775808 1", "9223372036854775807", "9223372036854775808 1",
         "18446744073709551616", "-" + "9" * 30,
         # blank runs joined only after JSON refused them; "-0" found only among zeros
         "1  -0", "-0\n  1", "0  0 -0", "1\n    2\n    -0 ", "3 -0 0.5", "1 -0.0  2",
         "1 \x00 2", "1 e 2", "- 1", "1-2", "1e", "1  +2", "1 2  .5", "0 1e-0"]


@pytest.mark.parametrize("dtype", [np.float64, np.int64])
@pytest.mark.parametrize("text", EDGES)
def test_edge_cases_read_as_numpy_reads_them(text, dtype):
    _same(text, dtype)
    _same(text.encode("utf-8"), dtype)


def test_plain_lists_take_the_json_path():
    assert plain_numbers("0.5 -1.25e-05 3\n4", np.float64) is not None
    assert plain_numbers("0 1 2\t3", np.int64) is not None
    assert plain_numbers("-0 1", np.float64) is None
    assert plain_numbers("1.0 2", np.int64) is None


_FORMATS = st.sampled_from(["{!r}", "{:.7g}", "{:.9e}", "{:.3f}", "{:g}", "{:.17g}"])
_BLANKS = st.sampled_from([" ", "  ", "\n", "\t", "\r\n", " \n "])


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.floats(allow_nan=False, allow_infinity=False), _FORMATS, _BLANKS),
                min_size=1, max_size=40), _BLANKS, _BLANKS)
def test_written_floats_read_back_as_numpy_reads_them(items, lead, trail):
    text = lead + "".join(fmt.format(value) + blank for value, fmt, blank in items) + trail
    _same(text, np.float64)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(-2**70, 2**70), min_size=1, max_size=40), _BLANKS)
def test_written_integers_read_back_as_numpy_reads_them(values, blank):
    text = blank.join(str(v) for v in values)
    _same(text, np.int64)
    _same(text, np.float64)


_DAE_LISTS = re.compile(rb"<(float_array|p|vcount)\b[^>]*>([^<]*)<")
_OBJ_VERTEX = re.compile(rb"^v[ \t]+([^\r\n]*)", re.MULTILINE)


def _mesh_files() -> list[Path]:
    roots = [erd_root()]
    if pybullet_urdfs():
        import pybullet_data

        roots.append(Path(pybullet_data.getDataPath()))
    found = sorted({p for root in roots for p in root.rglob("*")
                    if p.suffix.lower() in (".dae", ".obj") and p.is_file()})
    return found[::7]  # a seventh of the corpus's meshes keeps this under a few seconds


def test_real_mesh_number_lists_read_as_numpy_reads_them():
    files = _mesh_files()
    assert len(files) > 50
    lists = 0
    for path in files:
        data = path.read_bytes()
        if path.suffix.lower() == ".dae":
            for kind, text in _DAE_LISTS.findall(data):
                _same(text, np.float64 if kind == b"float_array" else np.int64)
                lists += 1
        else:
            _same(b" ".join(_OBJ_VERTEX.findall(data)), np.float64)
            lists += 1
    assert lists > 200


def test_lists_read_at_once_in_several_threads_are_each_their_own():
    """Each thread reads with its own parser: a parser serves one list at a time."""
    from concurrent.futures import ThreadPoolExecutor

    texts = [" ".join(str(k * 1000 + i) + ".5" for i in range(20_000)) for k in range(8)]
    with ThreadPoolExecutor(4) as pool:
        read = list(pool.map(numbers, texts * 4))
    for k, values in enumerate(read):
        assert values[0] == (k % 8) * 1000 + 0.5 and len(values) == 20_000


def test_a_refused_list_leaves_the_parser_ready_for_the_next():
    assert plain_numbers("1 true", np.float64) is None  # a JSON literal: not a number to numpy
    assert plain_numbers("1 2.5", np.int64) is None  # a float where indices are wanted
    assert plain_numbers("1 [2 3]", np.float64) is None  # nesting, which would be flattened
    assert numbers("4 5 6").tolist() == [4.0, 5.0, 6.0]
