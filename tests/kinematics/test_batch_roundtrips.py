"""Batch files as users chain them: ik's results into fk, and what a line may not leave out.

An ik CSV result carried a 'hint' column fk refused ("no joint 'hint'"), though README says
ik's results feed fk; fk read an ik --with-base result's joints and dropped its base, so
the tool came out where the robot stands at the origin, exit 0. A target of 'roll_rad'
alone (or roll in degrees beside pitch in radians) was solved without its orientation and
reported a success; a header with no line below it was an empty success where an empty
file is refused; a JSON line naming a joint twice took the last value without a word.
"""

from __future__ import annotations

import csv
import json

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]


def _fk_positions(run, configs, *extra) -> list[list[float]]:
    result = run("fk", "--configs", configs, "--format", "json", *extra)
    assert result.exit_code == 0, result.output
    return [json.loads(line)["poses"][0]["position_m"] for line in result.stdout.splitlines()]


def test_an_ik_csv_result_feeds_fk(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n0.5,0.2,0.4\n0.3,-0.3,0.6\n")
    out = tmp_path / "answers.csv"
    assert run("ik", "--targets", targets, "-o", out, "--seed", "1").exit_code == 0
    assert "hint" in next(csv.reader(out.open()))
    assert sum(_fk_positions(run, out), []) == pytest.approx([0.5, 0.2, 0.4, 0.3, -0.3, 0.6],
                                                             abs=1e-5)


@pytest.mark.parametrize("suffix", [".csv", ".jsonl"])
@pytest.mark.parametrize("deg", [(), ("--deg",)])
def test_an_ik_with_base_result_puts_the_tool_where_ik_aimed(run, tmp_path, suffix, deg):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n3,1,0.5\n-2,2,0.4\n")
    out = tmp_path / f"answers{suffix}"
    assert run("ik", "--targets", targets, "--with-base", "--seed", "0", "-o", out,
               *deg).exit_code == 0
    assert sum(_fk_positions(run, out, *deg), []) == pytest.approx([3, 1, 0.5, -2, 2, 0.4],
                                                                   abs=1e-5)


@pytest.mark.parametrize("orientation", ["roll_rad\n0.3,0.1,0.5,1.5",
                                         "roll_deg,pitch_rad,yaw_rad\n0.3,0.1,0.5,10,0,0",
                                         "roll_deg,pitch_deg\n0.3,0.1,0.5,10,0"])
def test_a_part_of_an_orientation_is_refused(run, tmp_path, orientation):
    header, values = orientation.split("\n")
    targets = tmp_path / "targets.csv"
    targets.write_text(f"x_m,y_m,z_m,{header}\n{values}\n")
    result = run("ik", "--targets", targets)
    assert_one_line_error(result, 2, "is given without the rest of its orientation; give roll "
                          "pitch yaw (all three in one unit) or qx qy qz qw")


@pytest.mark.parametrize(("command", "header"), [("fk", ",".join(ARM)), ("ik", "x_m,y_m,z_m")])
def test_a_header_with_no_line_below_is_refused_as_an_empty_file(run, tmp_path, command,
                                                                  header):
    given = tmp_path / "given.csv"
    given.write_text(header + "\n# nothing yet\n")
    option = "--configs" if command == "fk" else "--targets"
    out = tmp_path / "out.csv"
    result = run(command, option, given, "-o", out)
    assert_one_line_error(result, 2, "given.csv: has no data lines below its header")
    assert not out.exists()


def test_a_json_line_naming_a_joint_twice_is_refused(run, tmp_path):
    configs = tmp_path / "configs.jsonl"
    configs.write_text(json.dumps({ARM[0]: 0.1}).replace("}", f', "{ARM[0]}": 2.5}}') + "\n")
    assert_one_line_error(run("fk", "--configs", configs), 2,
                          f"configs.jsonl:1: names '{ARM[0]}' twice; give each once")


@pytest.mark.parametrize(("command", "lines"), [
    ("fk", [",".join(ARM), "x,0,0", "0,y,0"]),
    ("ik", ["x_m,y_m,z_m", "a,0,0", "0,b,0"]),
])
@pytest.mark.parametrize("kind", ["csv", "jsonl"])
def test_a_run_that_skips_every_line_computed_nothing_and_says_so(tmp_path, command, lines,
                                                                  kind):
    """--on-error skip over lines none of which is usable: no result, not an empty success."""
    given = tmp_path / "given.csv"
    given.write_text("\n".join(lines) + "\n")
    option = "--configs" if command == "fk" else "--targets"
    out = tmp_path / f"out.{kind}"
    to_file = run_servicebot(command, option, given, "--on-error", "skip", "-o", out)
    assert to_file.returncode == 2 and not out.exists()
    errors = [ln for ln in to_file.stderr.splitlines() if ln.startswith("Error:")]
    assert errors == [f"Error: {given}: every one of its 2 lines was skipped, so nothing was "
                      "computed; fix the lines named above"]
    assert sum(ln.startswith("skipped ") for ln in to_file.stderr.splitlines()) == 2
    to_stdout = run_servicebot(command, option, given, "--on-error", "skip",
                               *(["--format", "json"] if kind == "jsonl" else []))
    assert to_stdout.returncode == 2 and to_stdout.stdout == ""  # not a header alone


def test_a_header_only_file_leaves_stdout_empty(tmp_path):
    given = tmp_path / "given.csv"
    given.write_text(",".join(ARM) + "\n")
    result = run_servicebot("fk", "--configs", given)
    assert result.returncode == 2 and result.stdout == ""
