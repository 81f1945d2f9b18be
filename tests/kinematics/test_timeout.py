"""``ik --timeout-s``: a search that cannot succeed ends when its time is up, with the reason.

The domain takes its clock from the caller: a stepped clock makes the deadline exact here,
with no timed assertion. Through the CLI the real clock runs; the tests only ask that the
command ends with the reason, not how fast.
"""

from __future__ import annotations

import itertools
import json

import numpy as np

from servicebot_cli.description.loader import RobotSource
from servicebot_cli.kinematics.ik_problem import IkProblem
from servicebot_cli.kinematics.ik_session import IkSession
from servicebot_cli.kinematics.inverse import IkSettings, IkTarget
from servicebot_cli.kinematics.rotations import matrix_from_rpy
from tests.conftest import SIM_URDF, assert_one_line_error

# a place the arm reaches, with a tool turned in a way its joints cannot make
IMPOSSIBLE = IkTarget(np.array([0.3, 0.1, 0.5]), matrix_from_rpy(np.array([0.0, 0.0, 3.0])),
                      ("roll", "pitch", "yaw"))
HUGE = 100_000_000


def stepped_clock(step_s: float):
    ticks = itertools.count()
    return lambda: next(ticks) * step_s


def test_the_deadline_ends_the_search_with_its_best_try_and_the_reason():
    problem = IkProblem(RobotSource.of(SIM_URDF), seed=1, timeout_s=5.0,
                        settings=IkSettings(max_attempts=HUGE))
    session = IkSession(problem, stepped_clock(1.0))  # one second per look at the clock
    outcome = session.solve(IMPOSSIBLE, session.start)
    assert not outcome.success and outcome.result.stopped
    assert outcome.result.attempts < HUGE
    assert outcome.elapsed_s > 5.0
    assert outcome.hint is not None and outcome.hint.startswith("stopped by --timeout-s 5")


def test_a_reachable_target_is_not_cut_short():
    problem = IkProblem(RobotSource.of(SIM_URDF), seed=1, timeout_s=1e-9)
    session = IkSession(problem, stepped_clock(1.0))
    outcome = session.solve(IkTarget(np.array([0.4, 0.1, 0.3])), session.start)
    assert outcome.success and not outcome.result.stopped  # the first attempt always runs


def test_through_the_cli_the_search_ends_with_the_reason_on_one_line(run):
    result = run("ik", "--position", "0.3", "0.1", "0.5", "--rpy", "0", "0", "3",
                 "--max-attempts", HUGE, "--timeout-s", "0.2", "--seed", "1", "--format",
                 "json")
    line = assert_one_line_error(result, 1, "--timeout-s 0.2")
    answer = json.loads(result.stdout)
    assert answer["success"] is False and answer["attempts"] < HUGE
    assert "stopped by --timeout-s 0.2" in answer["hint"] and "stopped" in line


def test_beyond_reach_ends_at_once_whatever_the_attempts(run):
    result = run("ik", "--position", "2", "1", "0.5", "--max-attempts", HUGE, "--format",
                 "json")
    assert_one_line_error(result, 1, "out of reach")
    assert json.loads(result.stdout)["attempts"] == 1


def test_each_batch_target_has_its_own_time(run, tmp_path):
    targets = tmp_path / "t.csv"
    targets.write_text("x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad\n0.3,0.1,0.5,0,0,3\n"
                       "0.3,0.1,0.5,0,0,3\n")
    result = run("ik", "--targets", targets, "--max-attempts", HUGE, "--timeout-s", "0.1",
                 "--format", "json")
    assert_one_line_error(result, 1, "2 of 2 targets not reached")
    rows = [json.loads(r) for r in result.stdout.splitlines()]
    assert [r["line"] for r in rows] == [2, 3]
    assert all("stopped by --timeout-s 0.1" in r["hint"] for r in rows)


def test_a_timeout_that_is_not_a_positive_number_is_refused(run):
    for value in ("0", "-1", "nan", "soon"):
        assert_one_line_error(run("ik", "--position", "0.4", "0", "0.3", "--timeout-s", value),
                              2, "--timeout-s")
