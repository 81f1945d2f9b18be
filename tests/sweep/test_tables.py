"""runs.parquet, read back by pyarrow, holds what runs.csv holds, typed; without pyarrow the
sweep still works and leaves no stale runs.parquet behind."""

from __future__ import annotations

import csv
import json
import math
import subprocess
import sys

import pytest

from servicebot_cli.sweep.metrics import describe

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

# The first axis's first value is an empty room, so the first runs have no closest obstacle
# (no closest_time_s); its second puts one cylinder back. [0, 0.5] is an int and a float;
# sample draws text.
SWEEP = """\
seeds: [3]
set: {duration_s: 3}
grid:
  world: [{}, {cylinders: [{center_m: [1.0, 0.95], radius_m: 0.15, height_m: 0.8}]}]
  initial_pose.yaw_rad: [0, 0.5]
sample: {n: 1, controller.saturation: {choice: [per-wheel]}}
expect: [collisions == 0, final_pose.yaw_rad < 0.25]
"""


def _from_text(text: str, arrow_type: pa.DataType) -> object:
    """A CSV field as the value of the Parquet column's type; empty is null."""
    if text == "":
        return None
    if pa.types.is_integer(arrow_type):
        return int(text)
    if pa.types.is_floating(arrow_type):
        return float(text)
    if pa.types.is_boolean(arrow_type):
        return {"True": True, "False": False}[text]
    assert pa.types.is_string(arrow_type), arrow_type
    return text


def _same(a: object, b: object) -> bool:
    both_nan = isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)
    return both_nan or (a == b and type(a) is type(b))


def test_parquet_and_csv_hold_the_same_typed_rows(run, write_sweep, tmp_path):
    out = tmp_path / "out"
    result = run("sweep", write_sweep(SWEEP), "--out", out, "--jobs", "2")
    assert result.exit_code == 1, result.stderr  # yaw 0.5 fails the second expectation
    with open(out / "runs.csv", newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        texts = list(reader)
    table = pq.read_table(out / "runs.parquet")
    assert table.column_names == header
    assert table.num_rows == len(texts) == 4
    schema = {field.name: field.type for field in table.schema}
    for i, name in enumerate(header):
        column = table.column(name).to_pylist()
        from_csv = [_from_text(row[i], schema[name]) for row in texts]
        assert all(_same(a, b) for a, b in zip(from_csv, column, strict=True)), \
            (name, from_csv, column)

    types = {name: str(t) for name, t in schema.items()}
    for name in ("run", "point", "draw", "seed", "collisions", "self_collisions"):
        assert types[name] == "int64", name
    assert types["initial_pose.yaw_rad"] == types["distance_m"] == "double"
    assert types["passed"] == "bool"
    assert types["key"] == types["world"] == types["controller.saturation"] == "string"
    rows = table.to_pylist()
    assert [r["initial_pose.yaw_rad"] for r in rows] == [0.0, 0.5, 0.0, 0.5]
    assert [r["closest_time_s"] is None for r in rows] == [True, True, False, False]
    assert [r["failed_expectations"] for r in rows] == \
        [None, "final_pose.yaw_rad < 0.25", None, "final_pose.yaw_rad < 0.25"]
    assert [r["passed"] for r in rows] == [True, False, True, False]
    assert [r["seed"] for r in rows] == [3] * 4
    assert header.index("closest_time_s") == header.index("min_obstacle_distance_m") + 1
    assert header[-2:] == ["passed", "failed_expectations"]
    # ints are written as ints, floats as floats
    assert {row[header.index("collisions")] for row in texts} == {"0"}
    assert [row[header.index("initial_pose.yaw_rad")] for row in texts] == \
        ["0.0", "0.5", "0.0", "0.5"]


NO_PYARROW = ("import sys; sys.modules['pyarrow'] = None; "
              "from servicebot_cli.cli import main; main(prog_name='servicebot')")


def _without_pyarrow(*args: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", NO_PYARROW, *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def test_without_pyarrow_runs_csv_is_written_and_no_stale_parquet_stays(
        run, write_sweep, tmp_path):
    out = tmp_path / "out"
    small = {"seeds": 1, "set": {"duration_s": 2}}
    first = run("sweep", write_sweep(small), "--out", out)
    assert first.exit_code == 0, first.stderr
    assert first.stdout.startswith("service_robot, scenario default, 1 run (1 grid point")
    assert pq.read_table(out / "runs.parquet").num_rows == 1

    grown = _without_pyarrow("sweep", write_sweep({**small, "seeds": 2}), "--out", out)
    assert grown.returncode == 0, grown.stderr
    assert not (out / "runs.parquet").exists()  # it held 1 run of 2: out of date
    notes = [ln for ln in grown.stderr.splitlines() if ln.startswith("note:")]
    assert notes == [f"note: removed {out / 'runs.parquet'}, an earlier sweep's table: "
                     "pyarrow is not installed to rewrite it; pip install "
                     "'servicebot[parquet]' (pyarrow)"]
    with open(out / "runs.csv", newline="") as f:
        assert [r["seed"] for r in csv.DictReader(f)] == ["0", "1"]

    again = _without_pyarrow("sweep", write_sweep({**small, "seeds": 2}), "--out", out)
    assert again.returncode == 0, again.stderr
    assert "(2 found done)" in again.stdout
    assert "note:" not in again.stderr and "Traceback" not in again.stderr


def test_a_room_without_obstacles_gives_infinite_clearance_not_a_crash(run, write_sweep,
                                                                       tmp_path):
    sweep = write_sweep({"seeds": 2, "set": {"duration_s": 2, "world": {}},
                         "expect": ["min_obstacle_distance_m > 0.3"]})
    out = tmp_path / "out"
    result = run("sweep", sweep, "--out", out, "--format", "json", "--plot", tmp_path / "p.png")
    assert result.exit_code == 0, result.stderr
    stats = json.loads(result.stdout)["points"][0]["metrics"]["min_obstacle_distance_m"]
    assert stats == dict.fromkeys(("mean", "std", "min", "median", "p95", "max"))  # inf: null
    with open(out / "runs.csv", newline="") as f:
        assert {r["min_obstacle_distance_m"] for r in csv.DictReader(f)} == {"inf"}
    assert pq.read_table(out / "runs.parquet").column("min_obstacle_distance_m").to_pylist() \
        == [math.inf, math.inf]


def test_statistics_of_infinite_and_missing_values():
    inf, nan = math.inf, math.nan
    assert describe([1.0, inf]) == {"mean": inf, "std": pytest.approx(nan, nan_ok=True),
                                    "min": 1.0, "median": inf, "p95": inf, "max": inf}
    assert describe([inf, inf])["p95"] == inf
    assert describe([nan, 2.0]) == {"mean": 2.0, "std": 0.0, "min": 2.0, "median": 2.0,
                                    "p95": 2.0, "max": 2.0}
    assert describe([1.0, 2.0, 3.0, 10.0])["p95"] == pytest.approx(8.95)  # numpy's linear
