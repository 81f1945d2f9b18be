"""``fk --configs`` on CSV goes a chunk at a time: the same bytes as the per-line path."""

from __future__ import annotations

import json

import numpy as np
import pytest

from servicebot_cli.batch.fk_chunks import CHUNK_LINES, jsonl_template, jsonl_text
from tests.conftest import assert_one_line_error

ARM = ("arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4")
LINES = CHUNK_LINES * 2 + 300  # three chunks, the last one short


def _configs(tmp_path, rng, *, deg=False, lines=LINES):
    """The same configurations as CSV (the chunked path) and JSON Lines (line by line)."""
    values = rng.uniform(-1.5, 1.5, (lines, len(ARM)))
    if deg:
        values = np.degrees(values)
    csv_path, jsonl_path = tmp_path / "q.csv", tmp_path / "q.jsonl"
    rows = values.tolist()
    csv_path.write_text(",".join(ARM) + "\n" + "".join(",".join(map(repr, r)) + "\n"
                                                        for r in rows))
    jsonl_path.write_text("".join(json.dumps(dict(zip(ARM, r, strict=True))) + "\n"
                                  for r in rows))
    return csv_path, jsonl_path


@pytest.mark.parametrize("options", [
    (),
    ("--deg",),
    ("-f", "arm_link2", "-f", "arm_tool_link", "--relative-to", "arm_link1"),
])
def test_chunks_write_the_same_bytes_as_the_per_line_path(run, tmp_path, options):
    csv_path, jsonl_path = _configs(tmp_path, np.random.default_rng(3), deg="--deg" in options)
    for output in ("fast.csv", "slow.csv"):
        source = csv_path if output == "fast.csv" else jsonl_path
        result = run("fk", "--configs", source, "-o", tmp_path / output, *options)
        assert result.exit_code == 0, result.stderr
    fast = (tmp_path / "fast.csv").read_text().splitlines()
    slow = (tmp_path / "slow.csv").read_text().splitlines()
    assert fast[0] == slow[0] and len(fast) == LINES + 1
    # the CSV's data starts on line 2 (after its header), the JSON Lines' on line 1
    assert [r.partition(",")[2] for r in fast] == [r.partition(",")[2] for r in slow]
    assert [r.partition(",")[0] for r in fast[1:]] == [str(n + 2) for n in range(LINES)]


def test_chunks_write_json_lines_as_the_per_line_path_does(run, tmp_path):
    csv_path, jsonl_path = _configs(tmp_path, np.random.default_rng(4), lines=50)
    fast = [json.loads(r) for r in run("fk", "--configs", csv_path, "--format", "json")
            .stdout.splitlines()]
    slow = [json.loads(r) for r in run("fk", "--configs", jsonl_path, "--format", "json")
            .stdout.splitlines()]
    assert [r.pop("line") for r in fast] == [r.pop("line") + 1 for r in slow]
    assert fast == slow and len(fast) == 50


def test_a_bad_line_in_a_later_chunk_is_named_by_its_line(run, tmp_path):
    csv_path, _ = _configs(tmp_path, np.random.default_rng(5))
    lines = csv_path.read_text().splitlines()
    bad = CHUNK_LINES + 700
    lines[bad - 1] = "0.1,0.2,x,0.3"
    lines.insert(50, "# a comment")  # shifts every later line by one
    lines.insert(60, "")
    csv_path.write_text("\n".join(lines) + "\n")
    result = run("fk", "--configs", csv_path, "-o", tmp_path / "out.csv")
    assert_one_line_error(result, code=2)
    assert f"q.csv:{bad + 2}: joint 'arm_link2_to_link3' is 'x', not a number" in result.stderr
    assert not (tmp_path / "out.csv").exists()
    skipped = run("fk", "--configs", csv_path, "-o", tmp_path / "out.csv", "--on-error", "skip")
    assert skipped.exit_code == 0
    assert f"skipped 1 of {LINES} lines" in skipped.stderr
    numbers = [int(r.split(",", 1)[0]) for r in
               (tmp_path / "out.csv").read_text().splitlines()[1:]]
    assert len(numbers) == LINES - 1 and bad + 2 not in numbers and numbers == sorted(numbers)
    assert 51 not in numbers and 61 not in numbers  # the comment and the blank line


def test_a_value_outside_its_limits_in_a_chunk_names_the_line_or_is_clamped(run, tmp_path):
    csv_path, _ = _configs(tmp_path, np.random.default_rng(6))
    lines = csv_path.read_text().splitlines()
    lines[4000] = "2.5,0,0,0"
    csv_path.write_text("\n".join(lines) + "\n")
    result = run("fk", "--configs", csv_path)
    assert_one_line_error(result, code=2)
    assert "q.csv:4001: joint 'arm_base_to_link1' = 2.5 rad is outside its limits" in \
        result.stderr
    clamped = run("fk", "--configs", csv_path, "--clamp")
    assert clamped.exit_code == 0
    assert f"--clamp moved 1 joint value onto a limit, on 1 of {LINES} lines" in clamped.stderr
    row = clamped.stdout.splitlines()[4000]
    assert row.startswith("4001,") and row.split(",")[-1] != ""


@pytest.mark.parametrize("options", [(), ("--deg", "-f", "arm_link2", "-f", "arm_tool_link")])
def test_chunks_write_json_lines_byte_for_byte_as_json_dumps(run, tmp_path, options):
    csv_path, jsonl_path = _configs(tmp_path, np.random.default_rng(5), deg="--deg" in options)
    fast = run("fk", "--configs", csv_path, "--format", "json", *options).stdout.splitlines()
    slow = run("fk", "--configs", jsonl_path, "--format", "json", *options).stdout.splitlines()
    assert len(fast) == len(slow) == LINES
    # the same text after the line number: the per-line path writes with json.dumps
    assert [r.partition(",")[2] for r in fast] == [r.partition(",")[2] for r in slow]
    assert [json.loads(r)["line"] for r in fast[:3]] == [2, 3, 4]


def test_the_json_lines_template_escapes_frame_names_as_json_dumps_does():
    frames = ['odd "frame" 100%', "tool"]
    poses = np.random.default_rng(6).normal(size=(2, 2, 10))
    text = jsonl_text([7, 8], poses, jsonl_template(frames, "deg"))
    expected = "".join(json.dumps({"line": line, "poses": [
        {"frame": frame, "position_m": p[0:3], "rpy_deg": p[3:6], "quaternion_xyzw": p[6:10]}
        for frame, p in zip(frames, row.tolist(), strict=True)]}) + "\n"
        for line, row in zip([7, 8], poses, strict=True))
    assert text == expected
