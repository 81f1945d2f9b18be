"""fk's and ik's options: --start and --seed, --clamp notes, outputs and inputs checked first."""

from __future__ import annotations

import csv
import json

import pytest

from servicebot_cli.commands.kinematics_options import OUTPUT_SUFFIXES
from servicebot_cli.output.batch_rows import OUTPUT_SUFFIXES as WRITTEN_SUFFIXES
from tests.conftest import assert_one_line_error

TARGET = ["--position", "0.5", "0.2", "0.4"]


@pytest.mark.parametrize("args", [
    ["--seed", "arm_link1_to_link2=0.4"],
    ["--seed=arm_link1_to_link2=0.4"],
    ["--seed", "arm_link1_to_link2=0.4", "--seed", "arm_link2_to_link3=-0.6"],
])
def test_a_start_value_given_to_seed_points_at_start(run, args):
    line = assert_one_line_error(run("ik", *TARGET, *args), 2, "'--seed'",
                                 "is a joint value, not a random seed",
                                 "use --start arm_link1_to_link2=0.4")
    assert "given 2 times" not in line


@pytest.mark.parametrize(("value", "needle"), [("x", "'x' is not a whole number"),
                                               ("-1", "-1 is negative")])
def test_seed_is_a_whole_number_from_zero(run, value, needle):
    assert_one_line_error(run("ik", *TARGET, "--seed", value), 2, "'--seed'", needle)


def test_random_seed_is_gone(run):
    assert_one_line_error(run("ik", *TARGET, "--random-seed", "1"), 2, "--random-seed")


def test_fk_clamp_says_what_it_clamped(run):
    result = run("fk", "-j", "arm_link1_to_link2=2", "-j", "arm_base_to_link1=0.1", "--clamp")
    assert result.exit_code == 0
    assert result.stderr == ("note: --clamp: joint 'arm_link1_to_link2' = 2 rad is outside its "
                             "limits; using its upper limit 1.57 rad\n")
    within = run("fk", "-j", "arm_link1_to_link2=1", "--clamp")
    assert within.exit_code == 0 and within.stderr == ""


def test_ik_clamp_says_which_start_values_it_clamped(run):
    result = run("ik", *TARGET, "--start", "arm_link1_to_link2=-2", "--clamp", "--seed", "1",
                 "--format", "json")
    assert result.exit_code == 0 and json.loads(result.stdout)["success"]
    assert result.stderr == ("note: --clamp: joint 'arm_link1_to_link2' = -2 rad is outside its "
                             "limits; using its lower limit -1.57 rad\n")


def test_batch_clamp_gives_a_count_at_the_end(run, tmp_path):
    configs = tmp_path / "configs.csv"
    configs.write_text("arm_link1_to_link2\n2\n0\n-2\n")
    result = run("fk", "--configs", configs, "--clamp")
    assert result.exit_code == 0 and len(result.stdout.splitlines()) == 4
    assert result.stderr == (f"note: --clamp moved 2 joint values onto a limit, on 2 of 3 "
                             f"lines of {configs}\n")


@pytest.mark.parametrize(("args", "needle"), [
    (["fk", "--clamp"], "--clamp has no effect without --joint NAME=VALUE or --configs FILE"),
    (["fk", "--on-error", "skip"], "--on-error has no effect without --configs FILE"),
    (["fk", "-o", "-"], "--output has no effect without --configs FILE"),
    (["ik", *TARGET, "--clamp"], "--clamp has no effect without --start NAME=VALUE"),
    (["ik", *TARGET, "--on-error", "skip"], "--on-error has no effect without --targets FILE"),
    (["fk", "--configs", "-", "-o", "out.csv", "--format", "json"],
     "--format has no effect with --output FILE"),
])
def test_options_without_effect_are_refused(run, args, needle):
    assert_one_line_error(run(*args), 2, needle)


@pytest.mark.parametrize(("output", "needle"), [
    ("poses.txt", "files end in .csv or .tsv or .jsonl"),
    ("no_such_dir/poses.csv", "directory 'no_such_dir' does not exist"),
    ("a_directory.csv", "is a directory; give a file name"),
])
def test_a_bad_output_is_refused_before_any_work(run, tmp_path, monkeypatch, output, needle):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_directory.csv").mkdir()
    # the robot file does not exist either: the output is checked first, before any loading
    for command in (["fk", "no_such_robot.urdf", "--configs", "-"],
                    ["ik", "no_such_robot.urdf", "--targets", "-"]):
        result = run(*command, "-o", output, input="arm_link1_to_link2\n0\n")
        assert_one_line_error(result, 2, "'--output'", needle)
    assert [p.name for p in tmp_path.iterdir()] == ["a_directory.csv"]


@pytest.mark.parametrize(("command", "flag"), [("fk", "--configs"), ("ik", "--targets")])
def test_batch_input_is_dash_or_a_readable_file(run, tmp_path, command, flag):
    assert_one_line_error(run(command, flag, tmp_path / "nope.csv"), 2, f"'{flag}'",
                          "no such file; give a CSV or JSON Lines file, or - for stdin")
    assert_one_line_error(run(command, flag, tmp_path), 2, f"'{flag}'", "is a directory")


def test_the_output_suffixes_accepted_are_the_ones_written():
    assert OUTPUT_SUFFIXES == WRITTEN_SUFFIXES


def test_tsv_output_is_tab_separated(run, tmp_path):
    configs = tmp_path / "configs.tsv"
    configs.write_text("arm_base_to_link1\tarm_link1_to_link2\n0.25\t0\n")
    out = tmp_path / "poses.tsv"
    assert run("fk", "--configs", configs, "-o", out).exit_code == 0
    [row] = list(csv.DictReader(out.open(), delimiter="\t"))
    assert float(row["yaw_rad"]) == pytest.approx(0.25) and row["line"] == "2"
