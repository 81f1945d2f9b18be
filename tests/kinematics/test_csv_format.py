"""``fk`` and ``ik`` single answers as CSV, read back by pyarrow and held against the JSON."""

from __future__ import annotations

import io
import json

import pyarrow.csv as pa_csv
import pytest

from tests.conftest import assert_one_line_error
from tests.kinematics.robots import UR5


def read_csv(text: str) -> list[dict[str, object]]:
    """Rows of CSV text as pyarrow reads them (its own parser, its own type inference)."""
    table = pa_csv.read_csv(io.BytesIO(text.encode()))
    return table.to_pylist()


@pytest.mark.parametrize("deg", [False, True])
def test_fk_csv_has_a_row_per_frame_with_the_json_numbers(run, deg):
    args = ["fk", "-j", "arm_base_to_link1=0.5", "-j", "arm_link1_to_link2=-0.4", "-f",
            "arm_link2", "-f", "arm_tool_link", *(["--deg"] if deg else [])]
    rows = read_csv(run(*args, "--format", "csv").stdout)
    poses = json.loads(run(*args, "--format", "json").stdout)["poses"]
    unit = "deg" if deg else "rad"
    assert [r["frame"] for r in rows] == ["arm_link2", "arm_tool_link"]
    for row, pose in zip(rows, poses, strict=True):
        assert [row["x_m"], row["y_m"], row["z_m"]] == pose["position_m"]
        assert [row[f"{a}_{unit}"] for a in ("roll", "pitch", "yaw")] == \
            pytest.approx(pose[f"rpy_{unit}"], abs=1e-15)
        assert [row[k] for k in ("qx", "qy", "qz", "qw")] == \
            pytest.approx(pose["quaternion_xyzw"], abs=1e-15)


def test_ik_csv_is_one_row_with_the_json_answer(run):
    args = ["ik", "--position", "0.4", "0.1", "0.3", "--seed", "1"]
    (row,) = read_csv(run(*args, "--format", "csv").stdout)
    answer = json.loads(run(*args, "--format", "json").stdout)
    assert row["success"] is True and answer["success"] is True
    for name, value in answer["joints"].items():
        assert row[name] == value
    assert row["position_error_m"] == answer["position_error_m"] <= 1e-6
    assert row["orientation_error_rad"] is None  # position only: an empty cell
    assert row["attempts"] == answer["attempts"]


def test_ik_csv_of_a_mobile_base_and_a_fixed_arm(run):
    (row,) = read_csv(run("ik", "--position", "2", "1", "0.5", "--with-base", "--seed", "1",
                          "--format", "csv", "--deg").stdout)
    assert row["success"] is True
    assert {"base_x_m", "base_y_m", "base_yaw_deg"} <= set(row)
    (row,) = read_csv(run("ik", UR5, "--position", "0.3", "0.2", "0.4", "--rpy", "3.14", "0",
                          "0", "--seed", "2", "--format", "csv").stdout)
    assert row["success"] is True and row["orientation_error_rad"] <= 1e-6
    assert "shoulder_pan_joint" in row


def test_ik_csv_of_a_target_not_reached_has_the_best_try_and_the_hint(run):
    result = run("ik", "--position", "2", "1", "0.5", "--seed", "1", "--format", "csv")
    assert_one_line_error(result, 1, "out of reach")
    (row,) = read_csv(result.stdout)
    assert row["success"] is False
    assert row["position_error_m"] == pytest.approx(1.43, abs=0.01)
    assert "out of reach" in row["hint"]


def test_csv_on_stdout_for_a_batch_and_refused_beside_an_output_file(run, tmp_path):
    targets = tmp_path / "t.csv"
    targets.write_text("x_m,y_m,z_m\n0.4,0.1,0.3\n0.4,0.0,0.4\n")
    rows = read_csv(run("ik", "--targets", targets, "--seed", "1", "--format", "csv").stdout)
    assert [r["line"] for r in rows] == [2, 3] and all(r["success"] for r in rows)
    result = run("ik", "--targets", targets, "--format", "csv", "-o", tmp_path / "out.csv")
    assert_one_line_error(result, 2, "--format")
    assert not (tmp_path / "out.csv").exists()
