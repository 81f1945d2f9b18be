"""``fk --configs``: CSV or JSON Lines in, one pose line out per input line, streaming."""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys

import numpy as np
import pytest

from tests.conftest import REPO, assert_one_line_error

ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]


def write_csv(path, rows, header=ARM):
    path.write_text(",".join(header) + "\n" + "".join(",".join(map(str, r)) + "\n"
                                                      for r in rows))
    return path


def single_pose(run, values):
    joints = [f"-j{name}={value}" for name, value in zip(ARM, values, strict=True)]
    return json.loads(run("fk", *joints, "--format", "json").stdout)["poses"][0]


def test_csv_in_json_lines_out_matches_single_runs(run, tmp_path):
    rows = [[0.1, 0.2, 0.3, 0.4], [-1.0, 0.5, -0.5, 1.2]]
    configs = write_csv(tmp_path / "configs.csv", rows)
    result = run("fk", "--configs", configs, "--format", "json")
    assert result.exit_code == 0 and result.stderr == ""
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    assert [line["line"] for line in lines] == [2, 3]
    for line, values in zip(lines, rows, strict=True):
        [pose] = line["poses"]
        expected = single_pose(run, values)
        assert pose["position_m"] == pytest.approx(expected["position_m"], abs=1e-15)
        assert pose["rpy_rad"] == pytest.approx(expected["rpy_rad"], abs=1e-15)
        assert pose["quaternion_xyzw"] == pytest.approx(expected["quaternion_xyzw"], abs=1e-15)


def test_json_lines_in_csv_file_out(run, tmp_path):
    configs = tmp_path / "configs.jsonl"
    configs.write_text('{"arm_base_to_link1": 0.5}\n\n# a comment\n{"arm_link1_to_link2": 1}\n')
    out = tmp_path / "poses.csv"
    result = run("fk", "--configs", configs, "-o", out, "--deg", "-f", "arm_link4",
                 "-f", "arm_tool_link")
    assert result.exit_code == 0 and result.stdout == ""
    table = list(csv.DictReader(out.open()))
    assert list(table[0])[:4] == ["line", "arm_link4.x_m", "arm_link4.y_m", "arm_link4.z_m"]
    assert "arm_tool_link.yaw_deg" in table[0]
    assert [row["line"] for row in table] == ["1", "4"]
    assert float(table[0]["arm_tool_link.yaw_deg"]) == pytest.approx(0.5)  # --deg: 0.5 deg


def test_stdin_and_format_from_content(run):
    result = run("fk", "--configs", "-", input="arm_base_to_link1\n0.25\n")
    header, row = result.stdout.splitlines()
    assert header == "line,x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad,qx,qy,qz,qw"
    assert row.startswith("2,") and float(row.split(",")[6]) == pytest.approx(0.25)


def test_ik_results_feed_fk(run, tmp_path):
    solutions = tmp_path / "solutions.jsonl"
    solutions.write_text(json.dumps({"line": 1, "success": True, "joints": {
        "arm_link1_to_link2": 0.3}, "position_error_m": 0.0}) + "\n")
    table = tmp_path / "solutions.csv"
    table.write_text("line,success,arm_link1_to_link2,position_error_m,solve_time_s\n"
                     "2,true,0.3,0,0.001\n")
    for path in (solutions, table):
        result = run("fk", "--configs", path, "--format", "json")
        pitch = json.loads(result.stdout.splitlines()[0])["poses"][0]["rpy_rad"][1]
        assert pitch == pytest.approx(0.3)


def test_a_bad_line_stops_the_run_naming_the_line_and_leaves_no_file(run, tmp_path):
    configs = write_csv(tmp_path / "configs.csv", [[0, 0, 0, 0], [0, "x", 0, 0], [0, 2, 0, 0]])
    out = tmp_path / "poses.jsonl"
    result = run("fk", "--configs", configs, "-o", out)
    assert_one_line_error(result, 2, f"{configs}:3: joint 'arm_link1_to_link2' is 'x', "
                          "not a number", "--on-error skip")
    assert not out.exists() and list(tmp_path.iterdir()) == [configs]


def test_skip_goes_on_and_says_what_it_skipped(run, tmp_path):
    configs = write_csv(tmp_path / "configs.csv", [[0, 0, 0, 0], [0, "x", 0, 0], [0, 2, 0, 0],
                                                   [0, 0, 0], [1, 1, 1, 1]])
    result = run("fk", "--configs", configs, "--on-error", "skip", "--format", "json")
    assert result.exit_code == 0
    assert [json.loads(line)["line"] for line in result.stdout.splitlines()] == [2, 6]
    assert result.stderr.splitlines() == [
        f"skipped {configs}:3: joint 'arm_link1_to_link2' is 'x', not a number",
        f"skipped {configs}:4: joint 'arm_link1_to_link2' = 2 rad is outside its limits "
        "[-1.57, 1.57] rad; give a value inside them, or --clamp",
        f"skipped {configs}:5: has 3 fields, the header has 4",
        f"skipped 3 of 5 lines of {configs}",
    ]


@pytest.mark.parametrize(("args", "content", "needle"), [
    (["fk", "--configs"], "", "has no data lines"),
    (["fk", "--configs"], "0.1,0.2\n", "must be a header of names"),
    (["fk", "--configs"], "arm_link1_to_link2,arm_link1_to_link2\n0,0\n", "appears twice"),
    (["fk", "--configs"], "arm_link1_to_lnk2\n0\n", "no joint 'arm_link1_to_lnk2'; did you mean"),
    (["ik", "--targets"], "x_m,y_m,z_m,colour\n1,2,3,red\n",
     "column 'colour' is not a target column"),
    (["ik", "--targets"], "x_m,y_m\n1,2\n", "the line has no position (x_m y_m z_m)"),
    (["ik", "--targets"], "x_m,y_m,z_m,roll\n0.5,0,0.5,1\n", "'roll' is given without the rest"),
])
def test_bad_files(run, tmp_path, args, content, needle):
    path = tmp_path / "in.csv"
    path.write_text(content)
    assert_one_line_error(run(*args, path), 2, needle)


def test_missing_input_and_unwritable_output(run, tmp_path):
    assert_one_line_error(run("fk", "--configs", tmp_path / "nope.csv"), 2, "no such file")
    configs = write_csv(tmp_path / "c.csv", [[0, 0, 0, 0]])
    assert_one_line_error(run("fk", "--configs", configs, "-o", tmp_path / "no" / "x.csv"), 2,
                          "does not exist")
    assert_one_line_error(run("fk", "--configs", configs, "-o", tmp_path / "x.txt"), 2,
                          "'--output'", "files end in .csv or .tsv or .jsonl")
    assert_one_line_error(run("fk", "--configs", configs, "-j", "arm_base_to_link1=0"), 2,
                          "not both")


_STREAM = """
import resource, sys
from servicebot_cli.cli import main
try:
    main(["fk", "--configs", sys.argv[1], "-o", sys.argv[2]], prog_name="servicebot")
except SystemExit as end:
    assert end.code == 0, end.code
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024)
"""


def peak_bytes(tmp_path, lines):
    """Peak resident memory of ``fk --configs`` over ``lines`` random configurations."""
    rng = np.random.default_rng(0)
    configs, out = tmp_path / f"configs{lines}.csv", tmp_path / f"poses{lines}.jsonl"
    with configs.open("w") as handle:
        handle.write(",".join(ARM) + "\n")
        for start in range(0, lines, 10_000):
            block = rng.uniform(-1.5, 1.5, size=(min(10_000, lines - start), len(ARM)))
            np.savetxt(buffer := io.StringIO(), block, delimiter=",", fmt="%.9f")
            handle.write(buffer.getvalue())
    result = subprocess.run([sys.executable, "-c", _STREAM, str(configs), str(out)],
                            capture_output=True, text=True, cwd=REPO, timeout=600)
    assert result.returncode == 0, result.stderr
    with out.open() as handle:
        assert sum(1 for _ in handle) == lines
    return int(result.stdout)


def test_two_hundred_thousand_lines_stream_in_bounded_memory(tmp_path):
    """200k lines need no more memory than 2k: their results alone would be over 60 MB."""
    small, large = peak_bytes(tmp_path, 2_000), peak_bytes(tmp_path, 200_000)
    assert large - small < 16_000_000, (small, large)
