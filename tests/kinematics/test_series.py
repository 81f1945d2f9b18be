"""A series of targets in one compiled call gives the answers of one solve per target.

Same seed, same targets: the series (``IkSession.solve_series``) and the per-target solves
must agree bit for bit on every answer, its errors and effort, and leave the generator at
the same place, including where a target fails (beyond the reach), where a target keeps to
the Pinocchio loop (some orientation axes), and where the buffer of random numbers runs out.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics import series
from servicebot_cli.kinematics.ik_problem import CollisionOptions, IkProblem
from servicebot_cli.kinematics.ik_session import IkSession
from servicebot_cli.kinematics.inverse import IkSettings, IkTarget
from tests.kinematics.robots import ARMS, random_values, tool_pose


def session(arm: str, solutions: int = 1) -> IkSession:
    path, tool = ARMS[arm]
    problem = IkProblem(RobotSource.of(path), tool, seed=3,
                        settings=IkSettings(solutions=solutions),
                        collisions=CollisionOptions(check=False))
    return IkSession(problem, time.perf_counter, compiled=True)


def reachable(arm: str, count: int, seed: int) -> list[IkTarget]:
    path, tool = ARMS[arm]
    robot = load(RobotSource.of(path))
    rng = np.random.default_rng(seed)
    targets = []
    for k in range(count):
        pose = tool_pose(robot, tool, robot.joint_space.to_q(random_values(robot, rng)))
        full = k % 3 != 0  # every third a position only
        targets.append(IkTarget(pose.translation.copy(), pose.rotation.copy() if full else None,
                                ("roll", "pitch", "yaw") if full else ()))
    return targets


def one_by_one(arm: str, targets: list[IkTarget]) -> tuple[list, float]:
    solver = session(arm)
    outcomes, start = [], solver.start
    for target in targets:
        outcome = solver.solve(target, start)
        outcomes.append(outcome)
        if outcome.success:
            start = outcome.result.q
    return outcomes, float(solver._rng.random())


def assert_same(expected: list, got: list) -> None:
    assert len(expected) == len(got)
    for k, (a, b) in enumerate(zip(expected, got, strict=True)):
        ra, rb = a.result, b.result
        assert np.array_equal(ra.q, rb.q), k
        assert (ra.success, ra.position_error_m, ra.orientation_error_rad, ra.iterations,
                ra.attempts, ra.solutions) == (rb.success, rb.position_error_m,
                                               rb.orientation_error_rad, rb.iterations,
                                               rb.attempts, rb.solutions), k
        assert a.hint == b.hint, k


@pytest.mark.parametrize("arm", ["ur5", "panda"])
def test_a_series_answers_as_one_solve_per_target(arm):
    targets = reachable(arm, 60, seed=11)
    # beyond the reach: a failure, solved the slow way, between series runs
    targets.insert(20, IkTarget(np.array([3.0, 0.0, 0.5])))
    # two axes: the Pinocchio loop's target, in the middle of a series
    targets.insert(40, IkTarget(targets[39].position_m, targets[39].rotation, ("roll", "yaw")))
    expected, next_draw = one_by_one(arm, targets)
    solver = session(arm)
    got = solver.solve_series(targets, solver.start)
    assert_same(expected, got)
    assert float(solver._rng.random()) == next_draw  # the generator left where solves leave it
    assert sum(not o.success for o in got) >= 1
    assert series.series_search(solver.solver, solver._rng) is not None


def test_a_series_refills_its_random_numbers_and_answers_alike(monkeypatch):
    targets = reachable("ur5", 40, seed=12)
    expected, next_draw = one_by_one("ur5", targets)
    monkeypatch.setattr(series, "_BUFFER", 0)  # a buffer of one target's worst case
    solver = session("ur5")
    got = solver.solve_series(targets, solver.start)
    assert_same(expected, got)
    assert float(solver._rng.random()) == next_draw


def test_settings_the_series_cannot_take_keep_to_one_solve_per_target():
    solver = session("ur5", solutions=2)
    assert series.series_search(solver.solver, solver._rng) is None
    continuous = session("jaco2")  # continuous joints: angles through cos and sin
    assert series.series_search(continuous.solver, continuous._rng) is None
    targets = reachable("jaco2", 8, seed=13)
    expected, _ = one_by_one("jaco2", targets)
    assert_same(expected, continuous.solve_series(targets, continuous.start))
