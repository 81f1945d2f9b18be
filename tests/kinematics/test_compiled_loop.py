"""The compiled IK loop against Pinocchio: its FK, Jacobian and rotation error, and its answers.

The loop computes kinematics its own way (flat arrays, world-aligned Jacobian); here every
number it produces is held against Pinocchio's at random configurations of real arms, and
every answer the solver gives through it is checked again by Pinocchio's FK on the full model.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics import lm_pose
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.chain_arrays import chain_arrays
from servicebot_cli.kinematics.frames import link_names
from servicebot_cli.kinematics.ik_session import compile_note
from servicebot_cli.kinematics.inverse import IkSettings, IkSolver, IkTarget
from tests.conftest import REPO, SIM_URDF, run_servicebot
from tests.kinematics.robots import ARMS, robot_and_chain, tool_pose

FULL = ("roll", "pitch", "yaw")


def kernel_pose(arrays, theta):
    pose, jacobian = np.empty((3, 4)), np.empty((6, arrays.size))
    lm_pose.tool_pose(arrays.frames, arrays.axes, arrays.kinds, theta, pose, jacobian,
                      np.empty((3, 3)))
    return pose, jacobian


@pytest.mark.parametrize("arm", sorted(ARMS))
def test_pose_and_jacobian_are_pinocchios(arm):
    robot, chain = robot_and_chain(arm)
    arrays = chain_arrays(chain)
    assert arrays is not None
    rng = np.random.default_rng(4)
    for _ in range(50):
        q = chain.random_q(rng)
        theta = arrays.to_angles(q.copy())
        np.testing.assert_allclose(arrays.to_q(theta, chain.model.nq), q, atol=1e-12)
        pose, jacobian = kernel_pose(arrays, theta)
        pin.computeJointJacobians(chain.model, chain.data, q)
        placement = pin.updateFramePlacement(chain.model, chain.data, chain.frame)
        expected = pin.getFrameJacobian(chain.model, chain.data, chain.frame,
                                        pin.LOCAL_WORLD_ALIGNED).reshape(6, chain.model.nv)
        np.testing.assert_allclose(pose, placement.homogeneous[:3], atol=1e-12)
        np.testing.assert_allclose(jacobian, expected, atol=1e-12)


def test_jacobian_matches_finite_differences():
    _, chain = robot_and_chain("panda")
    arrays = chain_arrays(chain)
    theta = np.random.default_rng(5).uniform(-1, 1, arrays.size)
    pose, jacobian = kernel_pose(arrays, theta)
    step = 1e-7
    for i in range(arrays.size):
        moved = theta.copy()
        moved[i] += step
        after, _ = kernel_pose(arrays, moved)
        velocity = (after[:, 3] - pose[:, 3]) / step
        spin = pin.log3(after[:, :3] @ pose[:, :3].T) / step  # world-frame angular velocity
        np.testing.assert_allclose(jacobian[:3, i], velocity, atol=1e-5)
        np.testing.assert_allclose(jacobian[3:, i], spin, atol=1e-5)


@pytest.mark.parametrize("angle", [0.0, 1e-9, 1e-5, 0.5, 2.9, 3.0, 3.1, np.pi - 1e-7, np.pi])
def test_rotation_error_is_log3_at_every_angle(angle):
    rng = np.random.default_rng(int(angle * 1e3))
    for _ in range(20):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        start = pin.exp3(rng.normal(size=3))
        target = np.hstack([pin.exp3(axis * angle) @ start, np.zeros((3, 1))])
        out = np.zeros(6)
        got = lm_pose.rotation_error(target, np.hstack([start, np.zeros((3, 1))]), out,
                                     np.empty((3, 3)))
        assert got == pytest.approx(angle, abs=1e-12)
        # at pi the axis' sign is a free choice: both turns are the same rotation
        expected = axis * angle
        if angle > 3.14 and out[3:] @ expected < 0:
            expected = -expected
        np.testing.assert_allclose(out[3:], expected, atol=1e-7)


@pytest.mark.parametrize(("arm", "axes"), [
    ("ur5", FULL), ("panda", FULL), ("jaco2", FULL), ("service", FULL), ("service", ()),
    ("panda finger", ()),
])
def test_every_answer_of_the_compiled_loop_holds_under_pinocchios_fk(arm, axes):
    """Each solve seeded with the previous answer, as a program following targets does."""
    robot, chain = robot_and_chain(arm)
    solver = IkSolver(chain, IkSettings())
    assert solver.compiled
    rng = np.random.default_rng(6)
    neutral = pin.neutral(robot.model)
    seed = neutral
    for _ in range(150):
        pose = tool_pose(robot, chain.frame_name, chain.to_full(chain.random_q(rng), neutral))
        target = IkTarget(pose.translation, pose.rotation if axes else None, axes)
        result = solver.solve(target, seed, rng)
        assert result.success
        reached = tool_pose(robot, chain.frame_name, result.q)
        assert np.linalg.norm(reached.translation - pose.translation) <= 1e-6
        if axes:
            assert np.linalg.norm(pin.log3(reached.rotation.T @ pose.rotation)) <= 1e-6
        q = chain.to_chain(result.q)
        assert np.all(q >= chain.lower) and np.all(q <= chain.upper)
        assert result.position_error_m == pytest.approx(
            np.linalg.norm(reached.translation - pose.translation), abs=1e-12)
        seed = result.q


def test_compiled_and_pinocchio_loops_fail_alike_beyond_reach():
    _, chain = robot_and_chain("ur5")
    target = IkTarget(np.array([3.0, 0.0, 0.5]))
    seed = pin.neutral(chain.model)
    answers = [IkSolver(chain, IkSettings(), compiled=compiled).solve(
        target, seed, np.random.default_rng(1)) for compiled in (True, False)]
    assert [a.success for a in answers] == [False, False]
    assert [a.attempts for a in answers] == [1, 1]  # the reach says no restart can help
    assert answers[0].position_error_m == pytest.approx(answers[1].position_error_m, rel=1e-6)


def test_same_seed_same_answer_through_the_compiled_loop():
    robot, chain = robot_and_chain("panda")
    pose = tool_pose(robot, chain.frame_name, chain.to_full(
        chain.random_q(np.random.default_rng(8)), pin.neutral(robot.model)))
    target = IkTarget(pose.translation, pose.rotation, FULL)
    answers = [IkSolver(chain).solve(target, pin.neutral(robot.model),
                                     np.random.default_rng(3)).q for _ in range(2)]
    np.testing.assert_array_equal(answers[0], answers[1])


def test_chains_the_loop_cannot_do_keep_to_pinocchio():
    """A planar base (three velocities in one joint) is not a chain of single axes."""
    robot = load(RobotSource.of(SIM_URDF))
    model = robot.model_with_base("planar")
    chain = Chain(model, JointSpace.of(model, robot.movable_joints), "arm_tool_link",
                  link_names(robot))
    assert chain_arrays(chain) is None
    assert not IkSolver(chain).compiled


def imported_after(command: str) -> set[str]:
    """Top-level modules a fresh interpreter holds after running ``servicebot`` with ``command``."""
    script = ("import sys\nfrom click.testing import CliRunner\n"
              "from servicebot_cli.cli import main\n"
              f"done = CliRunner().invoke(main, {command!r}.split())\n"
              "assert done.exit_code == 0, done.output\n"
              "print(' '.join(sorted({m.split('.')[0] for m in sys.modules})))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          check=True, cwd=REPO)
    return set(done.stdout.split())


def test_a_single_solve_keeps_to_pinocchio_and_never_waits_for_a_compiler():
    """The first compile takes seconds; one target is solved in milliseconds without it."""
    assert "numba" not in imported_after("ik --position 0.4 0.1 0.2 --seed 1")


def test_a_batch_runs_in_the_compiled_loop(tmp_path):
    targets = tmp_path / "t.csv"
    targets.write_text("x,y,z\n0.4,0.1,0.2\n")
    assert "numba" in imported_after(f"ik --targets {targets} --seed 1 -o {tmp_path / 'a.csv'}")


def test_a_compile_is_said_once_it_took_seconds():
    assert compile_note(0.02) == ()
    (line,) = compile_note(7.24)
    assert line.startswith("compiled the IK loop in 7.2 s")


def test_a_batch_refused_for_its_input_never_waits_for_the_compiler(tmp_path):
    """The loop is readied by the first solve: a bad header is refused before it."""
    targets = tmp_path / "t.csv"
    targets.write_text("x_m,y_m,z_m,colour\n0.4,0.1,0.2,red\n")
    script = ("import sys\nfrom click.testing import CliRunner\n"
              "from servicebot_cli.cli import main\n"
              "from servicebot_cli.kinematics import compiled_search\n"
              "made = []\n"
              "ready = compiled_search.CompiledSearch.ready\n"
              "compiled_search.CompiledSearch.ready = lambda self: made.append(1) or ready(self)\n"
              f"done = CliRunner().invoke(main, ['ik', '--targets', {str(targets)!r}])\n"
              "print(done.exit_code, len(made))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          check=True, cwd=REPO)
    assert done.stdout.split() == ["2", "0"]


def test_only_a_compile_is_said_not_a_slow_load_from_the_cache(tmp_path):
    """The note once came from the time readying took: a load from numba's cache on a busy
    machine (1.3 s) was reported as a compile. Now numba's own count of cache misses says."""
    targets = tmp_path / "t.csv"
    targets.write_text("x,y,z\n0.4,0.1,0.2\n")
    env = {"NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    first = run_servicebot("ik", "--targets", targets, "-o", tmp_path / "a.csv", env=env)
    assert first.returncode == 0 and first.stderr.startswith("compiled the IK loop in ")
    again = run_servicebot("ik", "--targets", targets, "-o", tmp_path / "b.csv", env=env)
    assert again.returncode == 0 and again.stderr == ""
