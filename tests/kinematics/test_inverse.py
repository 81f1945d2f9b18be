"""IK properties on random reachable targets: reached, verified by FK, limits kept.

Targets are FK of random configurations within the limits, so each has a solution. Every
reported success is checked again by an independent FK; no result ever leaves the limits.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.diagnosis import hint
from servicebot_cli.kinematics.frames import link_names
from servicebot_cli.kinematics.inverse import IkSettings, IkSolver, IkTarget
from tests.conftest import FIXTURES
from tests.kinematics.robots import robot_and_chain, tool_pose

FULL = ("roll", "pitch", "yaw")
TOLERANCE = 1e-6
TARGETS = 200
X, Z = np.array([1.0, 0, 0]), np.array([0, 0, 1.0])


def orientation_kept(axes, got, want):
    """The asked-for angles of ``got`` match ``want`` (checked through invariants)."""
    if axes == FULL:
        return np.linalg.norm(pin.log3(got.T @ want))
    if axes == ("pitch",):  # sin(pitch) is the height of the x axis
        return abs((got @ X)[2] - (want @ X)[2])
    if axes == ("roll", "pitch"):  # the world's up, seen from the tool
        return np.linalg.norm(got.T @ Z - want.T @ Z)
    if axes == ("pitch", "yaw"):  # where the x axis points
        return np.linalg.norm(got @ X - want @ X)
    return 0.0


def reachable_targets(robot, chain, axes, count, seed):
    rng = np.random.default_rng(seed)
    neutral = pin.neutral(robot.model)
    targets, seeds = [], []
    for _ in range(count):
        pose = tool_pose(robot, chain.frame_name, chain.to_full(chain.random_q(rng), neutral))
        targets.append(IkTarget(pose.translation, pose.rotation if axes else None, axes))
        seeds.append(chain.to_full(chain.random_q(rng), neutral))
    return targets, seeds


@pytest.mark.parametrize(("arm", "axes"), [
    ("service", ()), ("service", ("pitch",)), ("service", ("roll", "pitch")),
    ("service", ("pitch", "yaw")), ("service", FULL),
    ("ur5", ()), ("ur5", FULL), ("panda", ()), ("panda", FULL),
])
def test_reachable_targets_are_reached_within_tolerance_and_limits(arm, axes):
    robot, chain = robot_and_chain(arm)
    solver = IkSolver(chain, IkSettings(tolerance_m=TOLERANCE, tolerance_rad=TOLERANCE))
    targets, seeds = reachable_targets(robot, chain, axes, TARGETS, seed=11)
    rng = np.random.default_rng(3)
    reached = 0
    for target, seed in zip(targets, seeds, strict=True):
        result = solver.solve(target, seed, rng)
        q = chain.to_chain(result.q)
        assert np.all(q >= chain.lower) and np.all(q <= chain.upper)  # never, not even on failure
        robot.joint_space.checked(robot.joint_space.from_q(result.q))
        if result.success:
            reached += 1
            pose = tool_pose(robot, chain.frame_name, result.q)
            assert np.linalg.norm(pose.translation - target.position_m) <= TOLERANCE
            assert result.position_error_m <= TOLERANCE
            if axes:
                assert orientation_kept(axes, pose.rotation, target.rotation) <= TOLERANCE
                assert result.orientation_error_rad <= TOLERANCE
    assert reached >= 0.995 * TARGETS, f"{arm} {axes}: {reached} of {TARGETS}"


def test_a_target_beyond_reach_fails_with_how_far():
    robot, chain = robot_and_chain("service")
    solver = IkSolver(chain, IkSettings(max_attempts=10))
    shoulder = np.array([-0.1, 0.0, 0.6])
    assert chain.reach.center_m == pytest.approx(shoulder)
    assert chain.reach.radius_m == pytest.approx(0.9)
    target = IkTarget(shoulder + np.array([1.2, 0.9, 0.0]))  # 1.5 m away: 0.6 m too far
    seed, rng = robot.joint_space.neutral(), np.random.default_rng(0)
    result = solver.solve(target, seed, rng)
    assert not result.success and result.attempts == 1  # beyond reach: no restart can help
    assert result.position_error_m == pytest.approx(0.6, abs=1e-3)  # as close as it gets
    assert hint(solver, target, seed, rng) == (
        "out of reach: the target is 0.6 m beyond the arm's reach (0.9 m from joint "
        "'arm_link1_to_link2')")


def test_an_orientation_the_arm_cannot_make_gets_its_own_hint():
    robot, chain = robot_and_chain("service")
    solver = IkSolver(chain, IkSettings(max_attempts=10))
    rolled = pin.rpy.rpyToMatrix(0.5, 0.0, 0.0)  # four pitch/yaw joints cannot roll
    target = IkTarget(np.array([0.5, 0.1, 0.5]), rolled, FULL)
    seed, rng = robot.joint_space.neutral(), np.random.default_rng(0)
    assert not solver.solve(target, seed, rng).success
    assert hint(solver, target, seed, rng).startswith(
        "the position is reachable, but not with that orientation")


def test_same_random_seed_same_answer():
    robot, chain = robot_and_chain("panda")
    solver = IkSolver(chain)
    [target], [seed] = reachable_targets(robot, chain, FULL, 1, seed=5)
    first = solver.solve(target, seed, np.random.default_rng(9))
    again = solver.solve(target, seed, np.random.default_rng(9))
    assert first.success and np.array_equal(first.q, again.q)
    assert first.iterations == again.iterations


def test_the_solution_nearest_the_seed_is_returned():
    robot, chain = robot_and_chain("ur5")
    neutral = pin.neutral(robot.model)
    rng = np.random.default_rng(4)
    for _ in range(5):
        q_star = chain.to_full(chain.random_q(rng), neutral)
        pose = tool_pose(robot, "tool0", q_star)
        target = IkTarget(pose.translation, pose.rotation, FULL)
        near_seed = q_star + rng.normal(scale=0.05, size=q_star.shape)
        one = IkSolver(chain, IkSettings(solutions=1)).solve(target, near_seed, rng)
        many = IkSolver(chain, IkSettings(solutions=6)).solve(target, near_seed, rng)
        assert one.success and many.success and many.solutions == 6
        distance = [np.linalg.norm(r.q - near_seed) for r in (one, many)]
        assert distance[1] <= distance[0] + 1e-9
        assert many.q == pytest.approx(q_star, abs=1e-4)  # the seed's own solution


def test_a_seed_at_the_solution_is_returned_unchanged():
    robot, chain = robot_and_chain("service")
    q_star = robot.joint_space.to_q(robot.joint_space.vector(
        {"arm_base_to_link1": 0.4, "arm_link1_to_link2": -0.3, "arm_link2_to_link3": 0.9}))
    target = IkTarget(tool_pose(robot, "arm_tool_link", q_star).translation)
    result = IkSolver(chain, IkSettings(solutions=4)).solve(target, q_star,
                                                            np.random.default_rng(0))
    assert result.success and result.iterations >= 4 and np.array_equal(result.q, q_star)


def test_continuous_joints_turn_freely_and_wrap():
    """planar_2r's elbow is continuous: a target needing it near pi is still reached."""
    robot = load(RobotSource.of(FIXTURES / "planar_2r.urdf"))
    chain = Chain(robot.model, robot.joint_space, "tip", link_names(robot))
    assert not chain.vector_space  # (cos, sin) in q: steps go through pin.integrate
    solver = IkSolver(chain)
    rng = np.random.default_rng(1)
    for elbow in (3.0, -3.0, 2.5):
        goal = robot.joint_space.to_q(np.array([0.4, elbow]))
        target = IkTarget(tool_pose(robot, "tip", goal).translation)
        result = solver.solve(target, robot.joint_space.neutral(), rng)
        assert result.success
        values = robot.joint_space.from_q(result.q)
        assert -math.pi < values[1] <= math.pi
        q = result.q[robot.joint_space.idx_q[1]: robot.joint_space.idx_q[1] + 2]
        assert np.linalg.norm(q) == pytest.approx(1.0)


def test_with_base_the_robot_drives_to_a_far_target_and_stays_for_a_near_one():
    robot = load(RobotSource.bundled("sim"))
    model = robot.model_with_base("planar")
    space = JointSpace.of(model, robot.movable_joints)
    chain = Chain(model, space, "arm_tool_link", link_names(robot))
    solver = IkSolver(chain, IkSettings(solutions=1))
    rng = np.random.default_rng(2)
    data = model.createData()
    for position, moves in (([3.0, -2.0, 0.5], True), ([0.5, 0.2, 0.4], False)):
        result = solver.solve(IkTarget(np.array(position)), space.neutral(), rng)
        assert result.success
        pin.framesForwardKinematics(model, data, result.q)
        tool = data.oMf[model.getFrameId("arm_tool_link")].translation
        assert tool == pytest.approx(position, abs=1e-6)
        base_moved = np.linalg.norm(result.q[:2]) > 0 or result.q[3] != 0
        assert base_moved == moves
        assert robot.joint_space.checked(space.from_q(result.q)) is not None


def test_a_target_too_high_for_the_arm_anywhere_says_so():
    robot = load(RobotSource.bundled("sim"))
    model = robot.model_with_base("planar")
    space = JointSpace.of(model, robot.movable_joints)
    solver = IkSolver(Chain(model, space, "arm_tool_link", link_names(robot)),
                      IkSettings(max_attempts=5))
    target = IkTarget(np.array([2.0, 0.0, 2.0]))  # shoulder at 0.6 m, reach 0.9 m
    rng = np.random.default_rng(0)
    assert not solver.solve(target, space.neutral(), rng).success
    assert hint(solver, target, space.neutral(), rng).startswith(
        "out of reach: the target is 0.5 m higher or lower than the arm reaches")
