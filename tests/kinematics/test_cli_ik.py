"""``servicebot ik`` from the command line: answers checked by ``fk``, failures, bad input."""

from __future__ import annotations

import json
import math

import pytest

from tests.conftest import assert_one_line_error, run_servicebot


def ik_json(run, *args):
    result = run("ik", *args, "--format", "json", "--seed", "1")
    return result, json.loads(result.stdout)


def fk_of(run, answer, frame="arm_tool_link"):
    joints = [f"-j{name}={value}" for name, value in answer["joints"].items()]
    unit = ["--deg"] if answer["angle_unit"] == "deg" else []
    return json.loads(run("fk", *joints, *unit, "-f", frame, "--format", "json").stdout)["poses"][0]


def test_position_only_answer_is_checked_by_fk(run):
    result, answer = ik_json(run, "--position", "0.5", "0.2", "0.4")
    assert result.exit_code == 0 and result.stderr == ""
    assert list(answer) == ["robot", "frame", "relative_to", "target", "angle_unit", "success",
                            "joints", "base", "position_error_m", "orientation_error_rad",
                            "iterations", "attempts", "solutions", "solve_time_s", "hint"]
    assert answer["success"] and answer["frame"] == "arm_tool_link" and answer["base"] is None
    assert answer["target"] == {"position_m": [0.5, 0.2, 0.4], "rpy_rad": None,
                                "orientation_axes": []}
    assert answer["orientation_error_rad"] is None and answer["position_error_m"] <= 1e-6
    assert fk_of(run, answer)["position_m"] == pytest.approx([0.5, 0.2, 0.4], abs=1e-6)
    assert answer["solutions"] == 3 and answer["solve_time_s"] > 0


def test_pitch_only_in_degrees(run):
    result, answer = ik_json(run, "--position", "0.4", "0.1", "0.2", "--rpy", "0", "90", "0",
                             "--deg", "--orientation-axes", "pitch")
    assert result.exit_code == 0, result.stderr
    assert answer["angle_unit"] == "deg" and answer["target"]["rpy_deg"][1] == pytest.approx(90)
    pose = fk_of(run, answer)
    assert pose["position_m"] == pytest.approx([0.4, 0.1, 0.2], abs=1e-6)
    assert pose["rpy_deg"][1] == pytest.approx(90, abs=1e-3)  # pointing straight down


def test_full_pose_with_a_quaternion_on_a_pose_the_arm_can_make(run):
    start = json.loads(run("fk", "-j", "arm_base_to_link1=0.3", "-j", "arm_link2_to_link3=0.8",
                           "--format", "json").stdout)["poses"][0]
    result, answer = ik_json(run, "--position", *map(str, start["position_m"]),
                             "--quat", *map(str, start["quaternion_xyzw"]))
    assert result.exit_code == 0
    assert answer["target"]["orientation_axes"] == ["roll", "pitch", "yaw"]
    pose = fk_of(run, answer)
    assert pose["position_m"] == pytest.approx(start["position_m"], abs=1e-6)
    assert pose["quaternion_xyzw"] == pytest.approx(start["quaternion_xyzw"], abs=1e-6)


def test_with_base_says_where_to_stand(run):
    result, answer = ik_json(run, "--position", "2", "1", "0.5", "--with-base")
    assert result.exit_code == 0
    base = answer["base"]
    assert list(base) == ["x_m", "y_m", "yaw_rad"] and math.hypot(base["x_m"], base["y_m"]) > 0.5
    text = run("ik", "--position", "2", "1", "0.5", "--with-base", "--seed", "1").stdout
    assert "\nbase: x " in text


def test_out_of_reach_exits_1_with_the_best_try_and_the_distance(run):
    result = run("ik", "--position", "2", "1", "0.5", "--seed", "1", "--max-attempts", "5")
    assert result.exit_code == 1
    assert result.stdout.startswith("arm_tool_link NOT reached (best found below): position "
                                    "only;")
    line = assert_one_line_error(result, 1)
    beyond = math.dist([2, 1, 0.5], [-0.1, 0, 0.6]) - 0.9
    assert line == (f"Error: no IK solution for arm_tool_link: best position error "
                    f"{beyond:.3g} m; out of reach: the target is {beyond:.3g} m beyond the "
                    "arm's reach (0.9 m from joint 'arm_link1_to_link2')")
    answer = json.loads(run("ik", "--position", "2", "1", "0.5", "--max-attempts", "5",
                            "--format", "json").stdout)
    assert answer["success"] is False and answer["hint"].startswith("out of reach")


def test_an_orientation_the_arm_cannot_make(run):
    result = run("ik", "--position", "0.5", "0.2", "0.4", "--rpy", "0.3", "0.2", "0.1",
                 "--max-attempts", "10")
    assert_one_line_error(result, 1, "the position is reachable, but not with that orientation",
                          "fewer --orientation-axes (e.g. pitch) or none")


def test_the_random_seed_makes_answers_repeat(run):
    args = ["ik", "--position", "0.3", "-0.4", "0.5", "--format", "json", "--seed", "5"]
    first, again = (json.loads(run(*args).stdout) for _ in range(2))
    assert first["joints"] == again["joints"] and first["iterations"] == again["iterations"]


def test_the_start_is_where_the_answer_starts(run):
    start = json.loads(run("fk", "-j", "arm_link1_to_link2=0.4", "-j", "arm_link2_to_link3=-0.6",
                           "--format", "json").stdout)["poses"][0]
    result, answer = ik_json(run, "--position", *map(str, start["position_m"]),
                             "--start", "arm_link1_to_link2=0.4", "--start",
                             "arm_link2_to_link3=-0.6")
    assert answer["joints"]["arm_link1_to_link2"] == pytest.approx(0.4, abs=1e-9)
    assert answer["joints"]["arm_link2_to_link3"] == pytest.approx(-0.6, abs=1e-9)


@pytest.mark.parametrize(("args", "needles"), [
    ([], ["give a target: --position X Y Z, or a --targets file"]),
    (["--position", "1", "2"], ["requires 3 arguments"]),
    (["--position", "1", "x", "3"], ["'x' is not a number"]),
    (["--position", "1", "nan", "3"], ["not a finite number"]),
    (["--position", "0.5", "0", "0.5", "--rpy", "0", "0", "0", "--quat", "0", "0", "0", "1"],
     ["--rpy or --quat, not both"]),
    (["--position", "0.5", "0", "0.5", "--quat", "0", "0", "0", "0"], ["length 0"]),
    (["--position", "0.5", "0", "0.5", "--rpy", "0", "90", "0"],  # degrees without --deg
     ["roll pitch yaw 0 90 0 rad", "over a turn", "give --deg for degrees"]),
    (["--position", "0.5", "0", "0.5", "--orientation-axes", "pitch"],
     ["--orientation-axes needs an orientation"]),
    (["--position", "0.5", "0", "0.5", "--rpy", "0", "1", "0", "--orientation-axes", "tilt"],
     ["'tilt' is not an axis"]),
    (["--position", "0.5", "0", "0.5", "-f", "tool"], ["no frame 'tool'", "arm_tool_link"]),
    (["--position", "0.5", "0", "0.5", "--start", "arm_link1_to_link2=3"],
     ["outside its limits [-1.57, 1.57] rad"]),
    (["--position", "0.5", "0", "0.5", "--start", "arm_lnk=3"], ["no joint 'arm_lnk'"]),
    (["--position", "0.5", "0", "0.5", "--tol-m", "0"], ["--tol-m"]),
    (["--position", "0.5", "0", "0.5", "--seed", "-1"], ["--seed"]),
    (["--position", "0.5", "0", "0.5", "-o", "x.csv"],
     ["--output has no effect without --targets FILE"]),
    (["--position", "0.5", "0", "0.5", "--targets", "-"], ["--position or --targets"]),
    (["--position", "0.2", "0", "0.1", "-f", "lidar_link"], ["frame 'lidar_link' is fixed to "
                                                             "the root: no joint moves it"]),
])
def test_bad_input_is_one_line_and_exit_2(run, args, needles):
    assert_one_line_error(run("ik", *args), 2, *needles)


def test_as_a_real_process_with_exit_code_1():
    result = run_servicebot("ik", "--position", "5", "0", "0", "--max-attempts", "3")
    assert result.returncode == 1 and "Traceback" not in result.stderr
    assert result.stderr.startswith("Error: no IK solution for arm_tool_link")


@pytest.mark.parametrize("command", ["fk", "ik"])
def test_help_is_light(command):
    from tests.foundation.test_cli_shape import HEAVY, _imported

    modules, stdout = _imported([command, "--help"])
    assert "Usage: servicebot" in stdout and not HEAVY & modules


def test_a_chain_of_one_continuous_joint(run):
    """A wheel: one joint, (cos, sin) in q; any random seed gives the same angle."""
    for seed in range(4):
        result = run("ik", "-f", "front_left_wheel", "--position", "0.17", "0.27", "-0.08",
                     "--rpy", "0", "1", "0", "--seed", str(seed), "--format", "json")
        answer = json.loads(result.stdout)
        assert answer["success"] and answer["joints"]["front_left_wheel_joint"] == \
            pytest.approx(1.0, abs=1e-6)
