"""``ik --targets`` on CSV goes a chunk at a time: the same rows as the per-line path."""

from __future__ import annotations

import json

import numpy as np
import pytest

from servicebot_cli.batch.ik_chunks import CHUNK_LINES
from servicebot_cli.batch.line_chunks import numbers
from servicebot_cli.kinematics.rotations import matrices_from_quaternions, matrix_from_quaternion
from servicebot_cli.kinematics.target_table import table_targets, target_layout
from servicebot_cli.kinematics.targets import row_target
from tests.conftest import assert_one_line_error

ARM = ("arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4")
LINES = CHUNK_LINES * 2 + 40  # three chunks, the last one short
FAST = ("--solutions", "1", "--allow-collisions", "--seed", "3")
POSE = ("x_m", "y_m", "z_m", "roll_rad", "pitch_rad", "yaw_rad", "qx", "qy", "qz", "qw")


def _poses(run, tmp_path, count, rng):
    """fk poses of ``count`` random arm configurations: rows of :data:`POSE` values."""
    configs = tmp_path / "configs.csv"
    values = rng.uniform(-1.2, 1.2, (count, len(ARM)))
    configs.write_text(",".join(ARM) + "\n" + "".join(",".join(map(repr, r)) + "\n"
                                                      for r in values.tolist()))
    result = run("fk", "--configs", configs, "--format", "json")
    assert result.exit_code == 0, result.stderr
    return [[*p["position_m"], *p["rpy_rad"], *p["quaternion_xyzw"]]
            for p in (json.loads(line)["poses"][0] for line in result.stdout.splitlines())]


def _inputs(tmp_path, rows, columns, names=None):
    """The same targets as CSV (the chunked path) and JSON Lines (line by line).

    ``columns`` picks from :data:`POSE`; ``names`` renames them in the files.
    """
    keep = [POSE.index(c) for c in columns]
    picked = [[row[k] for k in keep] for row in rows]
    columns = names or columns
    csv_path, jsonl_path = tmp_path / "targets.csv", tmp_path / "targets.jsonl"
    csv_path.write_text(",".join(columns) + "\n" + "".join(",".join(map(repr, r)) + "\n"
                                                          for r in picked))
    jsonl_path.write_text("".join(json.dumps(dict(zip(columns, r, strict=True))) + "\n"
                                  for r in picked))
    return csv_path, jsonl_path


def _same_rows(run, tmp_path, csv_path, jsonl_path, *options):
    """Solve both inputs to CSV; the rows agree but for solve_time_s (and the line offset)."""
    outputs = []
    for source, name in ((csv_path, "fast.csv"), (jsonl_path, "slow.csv")):
        result = run("ik", "--targets", source, "-o", tmp_path / name, *options)
        assert result.exit_code in (0, 1), result.stderr
        outputs.append([r.split(",") for r in (tmp_path / name).read_text().splitlines()])
    fast, slow = outputs
    time = fast[0].index("solve_time_s")
    assert fast[0] == slow[0] and len(fast) == len(slow)
    for f, s in zip(fast[1:], slow[1:], strict=True):
        assert int(f[0]) == int(s[0]) + 1  # the CSV's data starts on line 2
        assert f[1:time] + f[time + 1:] == s[1:time] + s[time + 1:]
    return fast


@pytest.mark.parametrize("columns", [POSE[:3] + POSE[6:], POSE[:3], POSE[2::-1],
                                     POSE[6:] + POSE[:3]])  # in another order too
def test_chunks_write_the_rows_of_the_per_line_path(run, tmp_path, columns):
    rows = _poses(run, tmp_path, LINES, np.random.default_rng(1))
    rows[CHUNK_LINES + 5][0] = 3.0  # out of reach: a failed row amid rows from a template
    fast = _same_rows(run, tmp_path, *_inputs(tmp_path, rows, columns), *FAST)
    assert len(fast) == LINES + 1 and fast[CHUNK_LINES + 6][1] == "false"
    assert sum(r[1] == "true" for r in fast[1:]) >= LINES * 0.9


def test_roll_pitch_yaw_in_degrees_and_the_defaults_agree_too(run, tmp_path):
    rows = _poses(run, tmp_path, 60, np.random.default_rng(2))
    for row in rows:
        row[3:6] = np.degrees(row[3:6]).tolist()
    names = ("x_m", "y_m", "z_m", "roll_deg", "pitch_deg", "yaw_deg")
    _same_rows(run, tmp_path, *_inputs(tmp_path, rows, POSE[:6], names), "--seed", "4")


def test_a_bad_line_in_a_later_chunk_is_named_and_the_others_solved_alike(run, tmp_path):
    rows = _poses(run, tmp_path, CHUNK_LINES + 30, np.random.default_rng(3))
    csv_path, _ = _inputs(tmp_path, rows, POSE[:3])
    lines = csv_path.read_text().splitlines()
    bad = CHUNK_LINES + 12
    lines[bad - 1] = "0.1,x,0.3"
    csv_path.write_text("\n".join(lines) + "\n")
    result = run("ik", "--targets", csv_path, "-o", tmp_path / "out.csv", *FAST)
    assert_one_line_error(result, code=2)
    assert f"targets.csv:{bad}: 'y_m' is 'x', not a number" in result.stderr
    skipped = run("ik", "--targets", csv_path, "-o", tmp_path / "out.csv", "--on-error",
                  "skip", *FAST)
    assert skipped.exit_code == 0, skipped.stderr
    numbers = [int(r.split(",", 1)[0])
               for r in (tmp_path / "out.csv").read_text().splitlines()[1:]]
    assert len(numbers) == CHUNK_LINES + 29 and bad not in numbers
    assert numbers == sorted(numbers)


def test_many_quaternions_make_the_matrices_of_one_at_a_time_bit_for_bit():
    rng = np.random.default_rng(7)
    quaternions = np.concatenate([rng.normal(size=(3000, 4)) * scale
                                  for scale in (1.0, 1e-4, 1e4)])
    many = matrices_from_quaternions(quaternions)
    one_by_one = np.array([matrix_from_quaternion(q) for q in quaternions])
    assert many is not None and many.view(np.int64).tolist() == \
        one_by_one.view(np.int64).tolist()
    quaternions[17] = 0.0
    assert matrices_from_quaternions(quaternions) is None


@pytest.mark.parametrize("header", [
    ("x_m", "y_m", "z_m", "qx", "qy", "qz", "qw"),
    ("line", "tool.x", "tool.y", "tool.z", "other.x_m", "roll", "pitch", "yaw"),
    ("z_m", "y_m", "x_m", "yaw_deg", "pitch_deg", "roll_deg"),
    ("x_m", "y_m", "z_m"),
])
@pytest.mark.parametrize("deg", [False, True])
def test_a_header_layout_gives_the_targets_of_row_target(header, deg):
    rng = np.random.default_rng(8)
    values = rng.uniform(-2, 2, size=(20, len(header)))
    layout = target_layout(header, "tool", deg=deg)
    assert layout is not None
    cells = [repr(v) for v in values.ravel().tolist()]  # as the chunked reader splits them
    targets = table_targets(layout, numbers(cells, len(header), layout.columns), None)
    assert targets is not None
    for row, target in zip(values, targets, strict=True):
        expected = row_target(dict(zip(header, map(repr, row.tolist()), strict=True)), "tool",
                              deg=deg, axes=None)
        assert target.axes == expected.axes
        assert target.position_m.tolist() == expected.position_m.tolist()
        assert (target.rotation is None) == (expected.rotation is None)
        if expected.rotation is not None:
            assert target.rotation.tolist() == expected.rotation.tolist()


@pytest.mark.parametrize("header", [
    ("x_m", "y_m", "z_m", "qx", "qy"),  # half a quaternion: row_target says so
    ("x_m", "y_m", "tool.x_m", "z_m"),  # x_m twice
    ("x_m", "y_m", "qx", "qy", "qz", "qw"),  # no position
])
def test_headers_row_target_refuses_go_line_by_line(header):
    assert target_layout(header, "tool", deg=False) is None
