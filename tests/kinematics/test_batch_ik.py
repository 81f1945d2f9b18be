"""``ik --targets``: targets per line (fk's own output works), warm starts, failures, policy."""

from __future__ import annotations

import csv
import json
import math

import pytest

from tests.conftest import assert_one_line_error

ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]


def poses_of(run, tmp_path, rows, *extra):
    """fk --configs over ``rows`` of arm joint values: fk's CSV output file."""
    configs = tmp_path / "configs.csv"
    configs.write_text(",".join(ARM) + "\n" + "".join(",".join(map(str, r)) + "\n"
                                                      for r in rows))
    out = tmp_path / "poses.csv"
    assert run("fk", "--configs", configs, "-o", out, *extra).exit_code == 0
    return out


def test_fk_output_feeds_ik_and_fk_confirms_every_answer(run, tmp_path):
    path = [[0.1 * k, 0.3 - 0.05 * k, 0.5, -0.2] for k in range(8)]
    poses = poses_of(run, tmp_path, path)
    out = tmp_path / "solutions.jsonl"
    result = run("ik", "--targets", poses, "-o", out, "--seed", "2")
    assert result.exit_code == 0 and result.stdout == "" and result.stderr == ""
    answers = [json.loads(line) for line in out.read_text().splitlines()]
    assert [a["line"] for a in answers] == list(range(2, 10))
    assert all(a["success"] for a in answers)
    check = run("fk", "--configs", out, "--format", "json")  # ik results feed fk back
    targets = list(csv.DictReader(poses.open()))
    for line, target in zip(check.stdout.splitlines(), targets, strict=True):
        pose = json.loads(line)["poses"][0]
        want = [float(target[k]) for k in ("x_m", "y_m", "z_m")]
        assert pose["position_m"] == pytest.approx(want, abs=1e-6)
        assert pose["quaternion_xyzw"] == pytest.approx(
            [float(target[k]) for k in ("qx", "qy", "qz", "qw")], abs=1e-5)


def test_warm_start_follows_the_path(run, tmp_path):
    """Along a smooth path each answer starts from the last: joints move a little each time."""
    path = [[0.02 * k, 0.4, -0.6, 0.3] for k in range(10)]
    poses = poses_of(run, tmp_path, path)
    result = run("ik", "--targets", poses, "--orientation-axes", "none", "--format", "json",
                 "--start", "arm_link1_to_link2=0.4", "--start", "arm_link2_to_link3=-0.6",
                 "--start", "arm_link3_to_link4=0.3", "--solutions", "1")
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    yaw = [a["joints"]["arm_base_to_link1"] for a in answers]
    assert yaw == pytest.approx([0.02 * k for k in range(10)], abs=1e-5)
    assert all(a["attempts"] == 1 for a in answers)  # each converged from the last one


def test_csv_out_and_targets_without_orientation(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x,y,z\n0.5,0.2,0.4\n0.3,-0.3,0.6\n")
    result = run("ik", "--targets", targets, "--seed", "0")
    table = list(csv.DictReader(result.stdout.splitlines()))
    assert list(table[0]) == ["line", "success", "front_left_wheel_joint",
                              "front_right_wheel_joint", "rear_left_wheel_joint",
                              "rear_right_wheel_joint", *ARM, "position_error_m",
                              "orientation_error_rad", "iterations", "attempts", "solutions",
                              "solve_time_s", "hint"]
    assert [row["success"] for row in table] == ["true", "true"]
    assert table[0]["orientation_error_rad"] == ""


def test_json_lines_targets_in_every_spelling(run, tmp_path):
    fk = json.loads(run("fk", "-j", "arm_base_to_link1=0.38", "-j", "arm_link1_to_link2=0.2",
                        "-j", "arm_link2_to_link3=0.4", "--format", "json").stdout)
    pose = fk["poses"][0]
    (x, y, z), rpy = pose["position_m"], pose["rpy_rad"]
    targets = tmp_path / "targets.jsonl"
    targets.write_text("\n".join(json.dumps(t) for t in [
        {"x_m": x, "y_m": y, "z_m": z, "roll_rad": rpy[0], "pitch_rad": rpy[1],
         "yaw_rad": rpy[2]},
        {"position": [x, y, z], "rpy_deg": [math.degrees(a) for a in rpy]},
        fk,  # fk's own JSON: its "poses"
        {"position_m": [x, y, z], "quaternion_xyzw": pose["quaternion_xyzw"]},
    ]) + "\n")
    result = run("ik", "--targets", targets, "--orientation-axes", "pitch", "--format", "json",
                 "--seed", "0")
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert result.exit_code == 0 and [a["success"] for a in answers] == [True] * 4
    targets.write_text('{"position_m": [0.5, 0.2, 0.4]}\n')
    assert_one_line_error(run("ik", "--targets", targets, "--orientation-axes", "pitch"), 2,
                          f"{targets}:1: orientation axes are given but the target has no "
                          "orientation")


def test_with_base_columns(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n3,1,0.5\n")
    table = list(csv.DictReader(run("ik", "--targets", targets, "--with-base", "--deg",
                                    "--seed", "0").stdout.splitlines()))
    assert {"base_x_m", "base_y_m", "base_yaw_deg"} <= set(table[0])
    assert table[0]["success"] == "true" and float(table[0]["base_x_m"]) > 1


def test_a_target_not_reached_still_gets_a_line_and_exit_1(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n0.5,0.2,0.4\n4,0,0\n0.3,0.3,0.5\n")
    result = run("ik", "--targets", targets, "--format", "json", "--max-attempts", "3")
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert [a["success"] for a in answers] == [True, False, True]
    assert answers[1]["hint"].startswith("out of reach: the target is")
    assert_one_line_error(result, 1, f"1 of 3 targets not reached (line 3 of {targets})")


def test_bad_lines_stop_or_are_skipped(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m,qx,qy,qz,qw\n0.5,0.2,0.4,0,0,0,1\n0.5,oops,0.4,0,0,0,1\n"
                       "0.5,0.2,0.4,0,0,0,0\n")
    out = tmp_path / "out.jsonl"
    stopped = run("ik", "--targets", targets, "-o", out, "--orientation-axes", "none")
    assert_one_line_error(stopped, 2, f"{targets}:3: 'y_m' is 'oops', not a number")
    assert not out.exists()
    skipped = run("ik", "--targets", targets, "-o", out, "--orientation-axes", "none",
                  "--on-error", "skip")
    assert skipped.exit_code == 0
    assert skipped.stderr.splitlines()[-1] == f"skipped 2 of 3 lines of {targets}"
    assert "length 0" in skipped.stderr.splitlines()[1]
    assert len(out.read_text().splitlines()) == 1


def test_fk_output_with_several_frames_uses_the_asked_frame(run, tmp_path):
    poses = poses_of(run, tmp_path, [[0.2, 0.1, 0.3, 0.0]], "-f", "arm_link4", "-f",
                     "arm_tool_link")
    result = run("ik", "--targets", poses, "-f", "arm_link4", "--format", "json",
                 "--seed", "0")
    answer = json.loads(result.stdout)
    assert answer["success"] and answer["position_error_m"] <= 1e-6
