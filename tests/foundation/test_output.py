"""Shared renderers: tables that fit the terminal, JSON that scripts can rely on."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from servicebot_cli.common.jsonable import dumps, dumps_plain
from servicebot_cli.output.table import format_number, table


def test_table_aligns_numbers_right_and_text_left():
    lines = table(["joint", "lower_rad"], [["a", -1.57], ["longer_name", 0.5]])
    assert lines == [
        "joint        lower_rad",
        "-----------  ---------",
        "a                -1.57",
        "longer_name        0.5",
    ]


def test_table_truncates_text_not_numbers_to_fit():
    rows = [["x" * 150, 123456.0], ["short", 1.0]]
    lines = table(["name", "value"], rows, max_width=40)
    assert all(len(line) <= 40 for line in lines)
    assert lines[2].endswith("123456") and "…" in lines[2]


def test_format_number():
    assert format_number(0.1 + 0.2) == "0.3"
    assert format_number(-0.0) == "0"
    assert format_number(math.nan) == "nan"
    assert format_number(None) == "-"
    assert format_number(20.35) == "20.35"
    assert format_number(7) == "7"


@dataclass(frozen=True)
class _Result:
    position_m: np.ndarray
    error_m: float
    path: Path
    hidden: object = field(default=None, repr=False)


def test_json_is_plain_ordered_and_has_no_nan():
    text = dumps(_Result(np.array([1.0, 2.0]), math.nan, Path("/tmp/x")))
    assert text.endswith("\n")
    assert list(json.loads(text)) == ["position_m", "error_m", "path"]
    assert json.loads(text) == {"position_m": [1.0, 2.0], "error_m": None, "path": "/tmp/x"}


_JSON_LEAVES = st.none() | st.booleans() | st.integers(-2**70, 2**70) | st.text()
_JSON_TREES = st.recursive(_JSON_LEAVES, lambda inner: st.lists(inner, max_size=4)
                           | st.dictionaries(st.text(), inner, max_size=4), max_leaves=30)


@settings(max_examples=300, deadline=None)
@given(_JSON_TREES)
def test_documents_without_floats_are_written_as_the_json_module_writes_them(document):
    """Such documents go through orjson: every byte must still be the json module's."""
    assert dumps(document) == json.dumps(document, indent=2, ensure_ascii=False) + "\n"
    assert dumps_plain(document) == dumps(document)  # as check writes its report


def test_documents_with_floats_keep_pythons_float_text():
    assert dumps({"a": [1, {"b": 1e-05}]}) == '{\n  "a": [\n    1,\n    {\n      "b": 1e-05\n' \
        '    }\n  ]\n}\n'
    assert dumps({"a": "\x00\u2028é", "b": []}) == '{\n  "a": "\\u0000\u2028é",\n  "b": []\n}\n'


def test_columns_line_up_with_wide_and_combining_characters():
    """A CJK link name takes two terminal columns a character: the columns after it slid."""
    from servicebot_cli.output.table import width

    rows = [("底盘", 1.0), ("base_link", 2.5), ("cafe\u0301", 3),
            ("アーム関節リンク名前がとても長い", 4)]
    lines = table(["link", "mass [kg]"], rows, max_width=30)
    ends = {width(line) for line in lines[2:]}
    assert ends == {width(lines[1])}  # every row as wide as the rule: the numbers line up
    assert lines[-1].split()[0].endswith("…") and width(lines[-1].split()[0]) <= 21
    assert width("底盘") == 4 and width("cafe\u0301") == 4
