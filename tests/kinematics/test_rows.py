"""Batch input rows and IK targets as users write them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.batch.reading import BatchInputError, open_source
from servicebot_cli.common.files import OutputError
from servicebot_cli.kinematics.rotations import matrix_from_rpy
from servicebot_cli.kinematics.targets import BadTarget, make_target, parse_axes, row_target
from servicebot_cli.kinematics.user_joints import BadNumber
from servicebot_cli.output.batch_rows import output_kind


def rows_of(path):
    source, handle = open_source(str(path))
    with handle:
        return source, list(source.rows)


def test_csv_rows_keep_their_line_numbers_and_errors(tmp_path):
    path = tmp_path / "in.txt"  # no telling extension: the content decides
    path.write_bytes(b"# joints\na, b\n\n1,2\n1\n3,\xff\n")
    source, rows = rows_of(path)
    assert source.kind == "csv" and source.columns == ("a", "b")
    assert [(r.line, r.values, r.error) for r in rows] == [
        (4, {"a": "1", "b": "2"}, ""), (5, {}, "has 1 fields, the header has 2"),
        (6, {"a": "3", "b": "\ufffd"}, "")]  # bad bytes become one bad value, not a crash


def test_json_lines_by_content_and_tsv_by_extension(tmp_path):
    jsonl = tmp_path / "in.data"
    jsonl.write_text('{"a": 1}\n{"a": \n"text"\n')
    source, rows = rows_of(jsonl)
    assert source.kind == "jsonl"
    assert [r.error.split(":")[0] for r in rows] == ["", "not JSON", "is a JSON string, not an "
                                                     "object of names and values"]
    tsv = tmp_path / "in.tsv"
    tsv.write_text("a\tb\n1\t2\n")
    assert rows_of(tsv)[1][0].values == {"a": "1", "b": "2"}


def test_unreadable_inputs(tmp_path):
    with pytest.raises(BatchInputError, match="is a directory"):
        open_source(str(tmp_path))
    (tmp_path / "blank.csv").write_text("\n# nothing\n")
    with pytest.raises(BatchInputError, match="has no data lines"):
        open_source(str(tmp_path / "blank.csv"))


def test_output_kind_from_extension_or_format():
    assert output_kind("a.CSV", "json") == "csv" and output_kind("a.ndjson", "text") == "jsonl"
    assert output_kind(None, "json") == "jsonl" and output_kind("-", "text") == "csv"
    with pytest.raises(OutputError, match="name it .csv or .jsonl"):
        output_kind("a.out", "text")


@pytest.mark.parametrize(("text", "axes"), [
    (None, None), ("none", ()), ("all", ("roll", "pitch", "yaw")), ("pitch", ("pitch",)),
    ("yaw, Roll", ("roll", "yaw")),
])
def test_orientation_axes(text, axes):
    assert parse_axes(text, True) == axes


def test_targets_from_rpy_degrees_and_quaternions_agree():
    by_rpy = make_target([0.1, 0.2, 0.3], rpy=[10, 20, 30], deg=True)
    assert by_rpy.rotation == pytest.approx(matrix_from_rpy(np.radians([10, 20, 30])))
    assert by_rpy.axes == ("roll", "pitch", "yaw")
    position_only = make_target([0.1, 0.2, 0.3])
    assert position_only.rotation is None and position_only.axes == ()
    with pytest.raises(BadTarget, match="not a finite number"):
        make_target([0.1, math.inf, 0.3])


def test_row_targets_take_fk_column_names_with_or_without_a_frame_prefix():
    flat = row_target({"line": "2", "arm.x_m": "1", "arm.y_m": "2", "arm.z_m": "3",
                       "arm.roll_deg": "0", "arm.pitch_deg": "90", "arm.yaw_deg": "0",
                       "other.x_m": "9"}, "arm", deg=False, axes=None)
    assert list(flat.position_m) == [1, 2, 3]
    assert flat.rotation == pytest.approx(matrix_from_rpy(np.array([0, math.pi / 2, 0])))
    assert row_target({"x": 1, "y": 2, "z": 3}, "arm", deg=False, axes=None).rotation is None
    with pytest.raises(BadNumber, match="'z_m' is true, not a number"):
        row_target({"x_m": 1, "y_m": 2, "z_m": True}, "arm", deg=False, axes=None)
    with pytest.raises(BadTarget, match="'position_m' has 2 numbers, not 3"):
        row_target({"position_m": [1, 2]}, "arm", deg=False, axes=None)
    with pytest.raises(BadTarget, match="no frame 'arm'"):
        row_target({"poses": [{"frame": "a"}, {"frame": "b"}]}, "arm", deg=False, axes=None)
